// Run-time choice of the arch, and the array functions that go through it. Compiled with the
// baseline flags only: nothing here may execute an instruction the CPU might lack.
#include "kutlog/dispatch.hpp"

#include <cpuid.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "arch/kernel_table.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/math.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/shade.hpp"

namespace kutlog {
namespace {

struct CpuFeatures {
  bool sse4_1 = false, avx2_fma = false, avx512 = false;
};

std::uint64_t read_xcr0() {
  std::uint32_t low, high;
  __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
  return (std::uint64_t(high) << 32) | low;
}

// CPUID says what the processor has; XGETBV says which register states the OS saves on a
// context switch. An AVX instruction on an OS that does not save YMM registers faults, so
// both must agree (xsimd 8.1 checks only CPUID).
CpuFeatures detect_cpu_features() {
  CpuFeatures features;
  unsigned eax, ebx, ecx, edx;
  if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return features;
  features.sse4_1 = ecx & bit_SSE4_1;
  const bool fma = ecx & bit_FMA, avx = ecx & bit_AVX, osxsave = ecx & bit_OSXSAVE;
  if (!osxsave || !avx) return features;
  const std::uint64_t xcr0 = read_xcr0();
  const bool os_saves_ymm = (xcr0 & 0x6) == 0x6;      // SSE and AVX state
  const bool os_saves_zmm = (xcr0 & 0xe6) == 0xe6;    // plus opmask, ZMM_Hi256, Hi16_ZMM
  if (!__get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx)) return features;
  features.avx2_fma = os_saves_ymm && fma && (ebx & bit_AVX2);
  const std::uint32_t avx512_bits =
      bit_AVX512F | bit_AVX512CD | bit_AVX512DQ | bit_AVX512BW | bit_AVX512VL;
  features.avx512 = features.avx2_fma && os_saves_zmm && (ebx & avx512_bits) == avx512_bits;
  return features;
}

// KUTLOG_CPU_HIDE=avx512[,avx2...] makes kutlog treat this CPU as lacking those archs (and,
// for avx2, avx512 with it), so that the fallbacks and the unsupported-arch errors can be
// tested on a machine that has everything (glibc's hwcaps tunables do the same for glibc).
CpuFeatures hide_archs_named_in_environment(CpuFeatures features) {
  const char* hidden = std::getenv("KUTLOG_CPU_HIDE");
  if (!hidden) return features;
  std::string_view names = hidden;
  while (!names.empty()) {
    const std::size_t comma = names.find(',');
    Arch arch;
    try {
      arch = parse_arch(names.substr(0, comma));
    } catch (const std::invalid_argument& error) {
      throw std::runtime_error(std::string("kutlog: KUTLOG_CPU_HIDE: ") + error.what());
    }
    switch (arch) {  // hiding an arch hides those that build on it
      case Arch::sse4_1: features.sse4_1 = false; [[fallthrough]];
      case Arch::avx2: features.avx2_fma = false; [[fallthrough]];
      case Arch::avx512: features.avx512 = false;
    }
    names = comma == std::string_view::npos ? std::string_view() : names.substr(comma + 1);
  }
  return features;
}

const CpuFeatures& cpu_features() {
  static const CpuFeatures features = hide_archs_named_in_environment(detect_cpu_features());
  return features;
}

std::string supported_list() {
  std::string names;
  for (Arch arch : supported_archs()) names += (names.empty() ? "" : ", ") + std::string(arch_name(arch));
  return names.empty() ? "none" : names;
}

void require_supported(Arch arch, const char* who) {
  if (!arch_supported(arch))
    throw std::runtime_error(std::string("kutlog: ") + who + " arch " +
                             std::string(arch_name(arch)) +
                             " is not supported by this machine (supported: " + supported_list() +
                             ")");
}

// The automatic choice: KUTLOG_ARCH if set, else the best supported arch. Computed once
// (a function-local static is initialized thread-safely); if it throws, the next use retries.
Arch automatic_arch() {
  static const Arch arch = [] {
    if (const char* forced = std::getenv("KUTLOG_ARCH"); forced && *forced) {
      Arch named;
      try {
        named = parse_arch(forced);
      } catch (const std::invalid_argument& error) {
        throw std::runtime_error(std::string("kutlog: KUTLOG_ARCH: ") + error.what());
      }
      require_supported(named, "KUTLOG_ARCH names");
      return named;
    }
    const std::vector<Arch> archs = supported_archs();
    if (archs.empty())
      throw std::runtime_error("kutlog: this CPU lacks SSE4.1, kutlog's baseline arch");
    return archs.front();
  }();
  return arch;
}

constexpr int kNotForced = -1;
std::atomic<int> forced_arch{kNotForced};
const detail::KernelTable& table_of(Arch arch) {
  switch (arch) {
    case Arch::avx512: return detail::kernel_table_avx512();
    case Arch::avx2: return detail::kernel_table_avx2();
    case Arch::sse4_1: break;
  }
  return detail::kernel_table_sse4_1();
}

// The active arch's table, so that a call reads one pointer (a one-element eval spent two
// fifths of its time going through active_arch() to its table): set by force_arch, cleared by
// reset_arch, filled on first use after either.
std::atomic<const detail::KernelTable*> active_table_cache{nullptr};

[[gnu::noinline, gnu::cold]] const detail::KernelTable& fill_active_table() {
  const detail::KernelTable* table = &table_of(active_arch());
  const detail::KernelTable* expected = nullptr;  // a force_arch since then wins
  return active_table_cache.compare_exchange_strong(expected, table, std::memory_order_relaxed)
             ? *table
             : *expected;
}

// Inlined into every entry point below: one load and one test.
inline const detail::KernelTable& active_table() {
  const detail::KernelTable* table = active_table_cache.load(std::memory_order_relaxed);
  return table ? *table : fill_active_table();
}

}  // namespace

const detail::KernelTable& detail::active_kernel_table() { return active_table(); }

std::string_view arch_name(Arch arch) {
  switch (arch) {
    case Arch::avx512: return "avx512";
    case Arch::avx2: return "avx2";
    case Arch::sse4_1: break;
  }
  return "sse4.1";
}

Arch parse_arch(std::string_view name) {
  for (Arch arch : kCompiledArchs)
    if (name == arch_name(arch)) return arch;
  throw std::invalid_argument("kutlog: unknown arch '" + std::string(name) +
                              "'; valid: avx512, avx2, sse4.1");
}

bool arch_supported(Arch arch) {
  const CpuFeatures& features = cpu_features();
  switch (arch) {
    case Arch::avx512: return features.avx512;
    case Arch::avx2: return features.avx2_fma;
    case Arch::sse4_1: break;
  }
  return features.sse4_1;
}

std::vector<Arch> supported_archs() {
  std::vector<Arch> archs;
  for (Arch arch : kCompiledArchs)
    if (arch_supported(arch)) archs.push_back(arch);
  return archs;
}

Arch active_arch() {
  const int forced = forced_arch.load(std::memory_order_relaxed);
  return forced == kNotForced ? automatic_arch() : static_cast<Arch>(forced);
}

void force_arch(Arch arch) {
  require_supported(arch, "forced");
  forced_arch.store(static_cast<int>(arch), std::memory_order_relaxed);
  active_table_cache.store(&table_of(arch), std::memory_order_relaxed);
}

void force_arch(std::string_view name) { force_arch(parse_arch(name)); }

void reset_arch() {
  forced_arch.store(kNotForced, std::memory_order_relaxed);
  active_table_cache.store(nullptr, std::memory_order_relaxed);
}

namespace math {
void acos_u10(const float* x, float* out, std::size_t count) {
  active_table().acos_u10(x, out, count);
}
void cos_u10(const float* x, float* out, std::size_t count) {
  active_table().cos_u10(x, out, count);
}
void cos_halfpi_u10(const float* x, float* out, std::size_t count) {
  active_table().cos_halfpi_u10(x, out, count);
}
void exp_u10(const float* x, float* out, std::size_t count) {
  active_table().exp_u10(x, out, count);
}
void log_u10(const float* x, float* out, std::size_t count) {
  active_table().log_u10(x, out, count);
}
void pow_u10(const float* x, const float* y, float* out, std::size_t count) {
  active_table().pow_u10(x, y, out, count);
}
void pow_u10(const float* x, float y, float* out, std::size_t count) {
  active_table().pow_scalar_u10(x, y, out, count);
}
}  // namespace math

void Lobe::eval(const float* t, float* out, std::size_t count, Variant variant,
                Normalization normalization) const {
  // Written so that the common call saves no register and ends in a jump to the kernel: the
  // first call, an overflowing coef (throws) and a forced arch's first call go out of line.
  const detail::KernelTable* table = active_table_cache.load(std::memory_order_relaxed);
  if (!table || (normalization == Normalization::exact_coef && !coef_fits_float_)) [[unlikely]]
    return eval_out_of_line(t, out, count, variant, normalization);
  static_assert(int(Arithmetic::unfused) == 0 && int(Arithmetic::fused) == 1);
  const int index = (int(variant) * 2 + int(normalization)) * 3 + table->fused_fma;
  const LobeKernel& chosen = kernels_[0][0][index];  // one multiply, not three
  table->kutlog_lobe.of(chosen)(chosen, t, out, count);
}
void Lobe::eval_out_of_line(const float* t, float* out, std::size_t count, Variant variant,
                            Normalization normalization) const {
  const detail::KernelTable& table = active_table();
  const LobeKernel& chosen = kernel(variant, normalization, table.fused_fma);
  table.kutlog_lobe.of(chosen)(chosen, t, out, count);
}
void PerLaneLobe::eval(const float* t, const float* n, float* out, std::size_t count,
                       Normalization normalization) const {
  active_table().kutlog_per_lane(kernel_, normalization == Normalization::exact_coef, t, n, out,
                                 count);
}
void blinn_phong_xsimd(const float* t, float* out, std::size_t count, float n, float scale) {
  ref::validate_exponent(n);
  active_table().blinn_phong_xsimd(t, n, scale, out, count);
}
void blinn_phong_u10(const float* t, float* out, std::size_t count, float n, float scale) {
  ref::validate_exponent(n);
  active_table().blinn_phong_u10(t, n, scale, out, count);
}
void schlick(const float* t, float* out, std::size_t count, float n) {
  ref::validate_exponent(n);
  active_table().schlick(t, n, out, count);
}

void shade(const Lobe& lobe, Vectors normal, Vectors to_light, Vectors to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask, ShadeOptions options) {
  const detail::KernelTable& table = active_table();
  table.shade_vectors(lobe.kernel(options.variant, options.normalization, table.fused_fma),
                      options, normal, to_light, to_viewer, out, count, mask);
}
void shade(const Lobe& lobe, Vectors normal, Direction to_light, Direction to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask, ShadeOptions options) {
  const detail::KernelTable& table = active_table();
  table.shade_directions(lobe.kernel(options.variant, options.normalization, table.fused_fma),
                         options, normal, to_light, to_viewer, out, count, mask);
}
void shade(const Lobe& lobe, const float* t, const float* n_dot_l, float* out, std::size_t count,
           const std::uint8_t* mask, ShadeOptions options) {
  const detail::KernelTable& table = active_table();
  table.shade_cosines(lobe.kernel(options.variant, options.normalization, table.fused_fma),
                      options, t, n_dot_l, out, count, mask);
}

}  // namespace kutlog
