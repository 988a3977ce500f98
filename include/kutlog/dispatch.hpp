// kutlog/dispatch.hpp: which arch (instruction set) the array functions run on: the best the
// CPU and OS support, unless KUTLOG_ARCH or force_arch() names one. A bad name in KUTLOG_ARCH
// or KUTLOG_CPU_HIDE (tests: hide archs) is ignored and reported (docs/bad-input.md).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "kutlog/api.hpp"
#include "kutlog/archs.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// The registry's archs (cmake/KutlogArchs.cmake), best first; the last is the baseline.
enum class Arch {
#define KUTLOG_ARCH_ENUMERATOR(id, ...) id,
  KUTLOG_ARCHS(KUTLOG_ARCH_ENUMERATOR)
#undef KUTLOG_ARCH_ENUMERATOR
};

inline constexpr std::array kCompiledArchs = {
#define KUTLOG_ARCH_VALUE(id, ...) Arch::id,
    KUTLOG_ARCHS(KUTLOG_ARCH_VALUE)
#undef KUTLOG_ARCH_VALUE
};

std::string_view arch_name(Arch arch);
// std::invalid_argument listing the valid names for an unknown one.
Arch parse_arch(std::string_view name);

bool arch_supported(Arch arch);
std::vector<Arch> supported_archs();

// Throws std::runtime_error only on a CPU that runs no compiled arch.
Arch active_arch();

// What was wrong with KUTLOG_ARCH or KUTLOG_CPU_HIDE, or empty.
std::string arch_environment_error();

// In every thread; std::runtime_error if this machine cannot run it.
void force_arch(Arch arch);
void force_arch(std::string_view name);
void reset_arch();

}  // namespace kutlog
KUTLOG_API_END
