// Run-time choice of the arch: the registry's table, the CPU's support, KUTLOG_ARCH, force_arch
// and the active table the public functions (src/forwarders.cpp) call through. Compiled with
// the baseline flags only: nothing here may execute an instruction the CPU might lack.
#include "kutlog/dispatch.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "active_table.hpp"
#include "arch/kernel_table.hpp"
#include "cpu_features.hpp"
#include "epicenter_check.hpp"
#include "kutlog/lobe.hpp"

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

}  // namespace

std::atomic<const detail::LobeArrayKernels*> detail::active_lobe_loops{nullptr};

std::string_view arch_name(Arch arch) { return entry(arch).name; }

Arch parse_arch(std::string_view name) {
  for (Arch arch : kCompiledArchs)
    if (name == arch_name(arch)) return arch;
  throw std::invalid_argument("kutlog: unknown arch '" + std::string(name) +
                              "'; valid: " + name_list(kCompiledArchs));
}

// The active table is a pointer, set by force_arch, cleared by reset_arch, filled here on first
// use after either. Release and acquire: the thread reading it may not be the one that built
// the table it points to (a function-local static).
const detail::KernelTable& detail::fill_active_table() {
  const detail::KernelTable* table = &table_of(active_arch());
  const detail::LobeArrayKernels* expected = nullptr;  // a force_arch since then wins
  return detail::active_lobe_loops.compare_exchange_strong(
             expected, table, std::memory_order_acq_rel, std::memory_order_acquire)
             ? *table
             : static_cast<const detail::KernelTable&>(*expected);
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

}  // namespace kutlog
