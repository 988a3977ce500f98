// Run-time choice of the arch, and the array functions that go through it. Compiled with the
// baseline flags only: nothing here may execute an instruction the CPU might lack.
#include "kutlog/dispatch.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "arch/kernel_table.hpp"
#include "cpu_features.hpp"
#include "epicenter_check.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/math.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

namespace kutlog {
namespace {

// The registry (cmake/KutlogArchs.cmake) as a table, indexed by Arch.
struct ArchEntry {
  std::string_view name;
  std::string_view cpu_features;
  const detail::KernelTable& (*kernel_table)();
};
constexpr ArchEntry kArchEntries[] = {
#define KUTLOG_ARCH_ENTRY(id, name, xsimd_arch, cpu_features, ...) \
  {name, cpu_features, &detail::kernel_table<Arch::id>},
    KUTLOG_ARCHS(KUTLOG_ARCH_ENTRY)
#undef KUTLOG_ARCH_ENTRY
};
static_assert(std::size(kArchEntries) == kCompiledArchs.size());

const ArchEntry& entry(Arch arch) { return kArchEntries[static_cast<std::size_t>(arch)]; }

constexpr Arch kBaselineArch = kCompiledArchs.back();

using ArchSupport = std::array<bool, kCompiledArchs.size()>;

// KUTLOG_CPU_HIDE=avx512[,avx2...] makes kutlog treat this CPU as lacking those archs and
// every arch ranked above them (for avx2, avx512 too), so that the fallbacks and the
// unsupported-arch errors can be tested on a machine that has everything (glibc's hwcaps
// tunables do the same for glibc).
ArchSupport hide_archs_named_in_environment(ArchSupport support) {
  const char* hidden = std::getenv("KUTLOG_CPU_HIDE");
  if (!hidden) return support;
  std::string_view names = hidden;
  while (!names.empty()) {
    const std::size_t comma = names.find(',');
    Arch arch;
    try {
      arch = parse_arch(names.substr(0, comma));
    } catch (const std::invalid_argument& error) {
      throw std::runtime_error(std::string("kutlog: KUTLOG_CPU_HIDE: ") + error.what());
    }
    for (std::size_t above = 0; above <= static_cast<std::size_t>(arch); ++above)
      support[above] = false;
    names = comma == std::string_view::npos ? std::string_view() : names.substr(comma + 1);
  }
  return support;
}

const ArchSupport& arch_support() {
  static const ArchSupport support = [] {
    ArchSupport detected{};
    for (Arch arch : kCompiledArchs)
      detected[static_cast<std::size_t>(arch)] = detail::cpu_has_features(entry(arch).cpu_features);
    return hide_archs_named_in_environment(detected);
  }();
  return support;
}

std::string name_list(const auto& archs) {
  std::string names;
  for (Arch arch : archs) names += (names.empty() ? "" : ", ") + std::string(arch_name(arch));
  return names.empty() ? "none" : names;
}

void require_supported(Arch arch, const char* who) {
  if (!arch_supported(arch))
    throw std::runtime_error(std::string("kutlog: ") + who + " arch " +
                             std::string(arch_name(arch)) +
                             " is not supported by this machine (supported: " +
                             name_list(supported_archs()) + ")");
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
      throw std::runtime_error("kutlog: this CPU lacks " + std::string(arch_name(kBaselineArch)) +
                               ", kutlog's baseline arch (compiled: " +
                               name_list(kCompiledArchs) + ")");
    return archs.front();
  }();
  return arch;
}

constexpr int kNotForced = -1;
std::atomic<int> forced_arch{kNotForced};
const detail::KernelTable& table_of(Arch arch) { return entry(arch).kernel_table(); }

// The active arch's table, so that a call reads one pointer (a one-element eval spent two
// fifths of its time going through active_arch() to its table), as its LobeArrayKernels: what
// Lobe's inline array eval reads (kutlog/lobe.hpp). Set by force_arch, cleared by reset_arch,
// filled on first use after either. Stored with release and loaded with acquire: the thread
// that fills it may be the one that built the table (a function-local static), and a relaxed
// load would let another thread read the table through the pointer before it sees the
// table's contents (a data race ThreadSanitizer reported, tests/test_threads.cpp; on x86-64
// an acquire load is the same instruction, on AArch64 an ldar instead of an ldr).
[[gnu::noinline, gnu::cold]] const detail::KernelTable& fill_active_table() {
  const detail::KernelTable* table = &table_of(active_arch());
  const detail::LobeArrayKernels* expected = nullptr;  // a force_arch since then wins
  return detail::active_lobe_loops.compare_exchange_strong(
             expected, table, std::memory_order_acq_rel, std::memory_order_acquire)
             ? *table
             : static_cast<const detail::KernelTable&>(*expected);
}

// Inlined into every entry point below: one load and one test.
inline const detail::KernelTable& active_table() {
  const detail::LobeArrayKernels* loops =
      detail::active_lobe_loops.load(std::memory_order_acquire);
  return loops ? static_cast<const detail::KernelTable&>(*loops) : fill_active_table();
}

}  // namespace

std::atomic<const detail::LobeArrayKernels*> detail::active_lobe_loops{nullptr};

std::string_view arch_name(Arch arch) { return entry(arch).name; }

Arch parse_arch(std::string_view name) {
  for (Arch arch : kCompiledArchs)
    if (name == arch_name(arch)) return arch;
  throw std::invalid_argument("kutlog: unknown arch '" + std::string(name) +
                              "'; valid: " + name_list(kCompiledArchs));
}

bool arch_supported(Arch arch) { return arch_support()[static_cast<std::size_t>(arch)]; }

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
  detail::active_lobe_loops.store(&table_of(arch), std::memory_order_release);
}

void force_arch(std::string_view name) { force_arch(parse_arch(name)); }

void reset_arch() {
  forced_arch.store(kNotForced, std::memory_order_relaxed);
  detail::active_lobe_loops.store(nullptr, std::memory_order_relaxed);
}

const detail::LobeArrayKernels* detail::fused_lobe_array_kernels() {
  for (Arch arch : kCompiledArchs)
    if (arch_supported(arch) && table_of(arch).fused_fma) return &table_of(arch);
  return nullptr;
}

namespace math {
#define KUTLOG_FORWARD_UNARY(function, kernel, ...)           \
  void kernel(const float* x, float* out, std::size_t count) { \
    active_table().kernel(x, out, count);                      \
  }
#define KUTLOG_FORWARD_BINARY(function, kernel, ...)                             \
  void kernel(const float* x, const float* y, float* out, std::size_t count) { \
    active_table().kernel(x, y, out, count);                                   \
  }                                                                            \
  void kernel(const float* x, float y, float* out, std::size_t count) {        \
    active_table().kernel##_scalar(x, y, out, count);                          \
  }
KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_FORWARD_UNARY)
KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_FORWARD_BINARY)
#undef KUTLOG_FORWARD_UNARY
#undef KUTLOG_FORWARD_BINARY
}  // namespace math

void Lobe::eval_out_of_line(const float* t, float* out, std::size_t count, Variant variant,
                            Normalization normalization) const {
  const detail::KernelTable& table = active_table();
  const LobeKernel& chosen = kernel(variant, normalization, table.fused_fma);
  table.of(chosen)(chosen, t, out, count);
}
void PerLaneLobe::eval(const float* t, const float* n, float* out, std::size_t count,
                       Normalization normalization) const {
  active_table().kutlog_per_lane(kernel_, normalization == Normalization::exact_coef, t, n, out,
                                 count);
}
void PowerPoly::eval(const float* t, float* out, std::size_t count) const {
  active_table().power_poly(kernel_, t, out, count);
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

void LobeSampler::sample(const float* u1, const float* u2, DirectionSamples out,
                         std::size_t count) const {
  active_table().sample_lobe(kernel_, u1, u2, out, count);
}

SampledDirection LobeSampler::sample(float u1, float u2) const {
  return active_table().sample_one(kernel_, u1, u2);
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
