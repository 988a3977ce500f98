// The forced arch, which src/arch_choice.cpp keeps for active_arch(): force_arch and
// reset_arch (src/dispatch.cpp) set it beside the active table.
#pragma once

#include "kutlog/dispatch.hpp"

namespace kutlog::detail {

// Makes active_arch() return `arch`; std::runtime_error if this machine cannot run it.
void choose_forced_arch(Arch arch);
// Returns active_arch() to the automatic choice.
void clear_forced_arch();

}  // namespace kutlog::detail
