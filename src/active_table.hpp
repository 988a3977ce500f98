// The active arch's kernel table, as the public functions read it: one acquire load and one
// test per call (src/dispatch.cpp fills it).
#pragma once

#include <atomic>

#include "arch/kernel_table.hpp"
#include "kutlog/detail/inspector.hpp"

namespace kutlog::detail {

// Sets the active table on first use after force_arch or reset_arch; returns it.
[[gnu::noinline, gnu::cold]] const KernelTable& fill_active_table();

inline const KernelTable& active_table() {
  const LobeArrayKernels* loops = Inspector::active_loops().load(std::memory_order_acquire);
  return loops ? static_cast<const KernelTable&>(*loops) : fill_active_table();
}

}  // namespace kutlog::detail
