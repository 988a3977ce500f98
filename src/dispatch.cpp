// The kernel tables of the compiled archs and the active one, which the public array functions
// (src/forwarders.cpp) and Lobe's inline array eval call through; src/arch_choice.cpp chooses
// the arch. Compiled with the baseline flags only.
#include "kutlog/dispatch.hpp"

#include <array>
#include <atomic>

#include "active_table.hpp"
#include "arch/kernel_table.hpp"
#include "arch_choice.hpp"
#include "epicenter_check.hpp"

namespace kutlog {
namespace {

// The registry's tables (cmake/KutlogArchs.cmake), indexed by Arch.
constexpr const detail::KernelTable& (*kKernelTables[])() = {
#define KUTLOG_ARCH_TABLE(id, ...) &detail::kernel_table<Arch::id>,
    KUTLOG_ARCHS(KUTLOG_ARCH_TABLE)
#undef KUTLOG_ARCH_TABLE
};
static_assert(std::size(kKernelTables) == kCompiledArchs.size());

const detail::KernelTable& table_of(Arch arch) {
  return kKernelTables[static_cast<std::size_t>(arch)]();
}

}  // namespace

std::atomic<const detail::LobeArrayKernels*> Lobe::active_loops_{nullptr};

// The active table is a pointer, set by force_arch, cleared by reset_arch, filled here on first
// use after either. Release and acquire: the thread reading it may not be the one that built
// the table it points to (a function-local static).
const detail::KernelTable& detail::fill_active_table() {
  const detail::KernelTable* table = &table_of(active_arch());
  const detail::LobeArrayKernels* expected = nullptr;  // a force_arch since then wins
  return detail::Inspector::active_loops().compare_exchange_strong(
             expected, table, std::memory_order_acq_rel, std::memory_order_acquire)
             ? *table
             : static_cast<const detail::KernelTable&>(*expected);
}

void force_arch(Arch arch) {
  detail::choose_forced_arch(arch);
  detail::Inspector::active_loops().store(&table_of(arch), std::memory_order_release);
}

void force_arch(std::string_view name) { force_arch(parse_arch(name)); }

void reset_arch() {
  detail::clear_forced_arch();
  detail::Inspector::active_loops().store(nullptr, std::memory_order_relaxed);
}

const detail::KernelTable& detail::best_kernel_table() {
  for (Arch arch : kCompiledArchs)
    if (arch_supported(arch)) return table_of(arch);
  return table_of(active_arch());  // throws: this CPU runs no compiled arch
}

// Its presence makes src/lobe.cpp fit a Lobe's fused kernels (a weak reference there).
std::optional<detail::EpicenterLoops> detail::fused_epicenter_loops(const LobeKernel& kernel) {
  for (Arch arch : kCompiledArchs)
    if (arch_supported(arch) && table_of(arch).fused_fma)
      return EpicenterLoops{table_of(arch).of(kernel, false),
                            best_kernel_table().epicenter_worst_ulp};
  return std::nullopt;
}

}  // namespace kutlog
