// kutlog/dispatch.hpp: which instruction set the array functions run on.
//
// kutlog compiles its kernels once per arch (each in its own translation unit, with only that
// arch's flags) and picks one at run time: the best one the CPU supports and the operating
// system has enabled (on x86, CPUID and XGETBV), unless the environment variable KUTLOG_ARCH
// or force_arch() names one. Choosing is thread-safe; the choice is read once per call.
//
// The archs come from the registry, cmake/KutlogArchs.cmake, through the generated
// kutlog/archs.hpp: on x86-64 avx512 (AVX-512 F, CD, DQ, BW, VL + FMA), avx2 (AVX2 + FMA3),
// sse4.1 (x86-64-v2) and portable (the baseline: any CPU, no SIMD flags, slower); on AArch64
// neon64; on any other CPU portable alone.
//
// For tests, KUTLOG_CPU_HIDE=avx512[,avx2,...] makes kutlog treat the CPU as lacking those
// archs (and every arch ranked above them); a name it does not know makes the first query
// throw std::runtime_error saying so.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "kutlog/api.hpp"
#include "kutlog/archs.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// One enumerator per arch of the registry, in its order (best first, from 0).
enum class Arch {
#define KUTLOG_ARCH_ENUMERATOR(id, ...) id,
  KUTLOG_ARCHS(KUTLOG_ARCH_ENUMERATOR)
#undef KUTLOG_ARCH_ENUMERATOR
};

// Every arch kutlog is compiled for, best first; the last is the baseline.
inline constexpr std::array kCompiledArchs = {
#define KUTLOG_ARCH_VALUE(id, ...) Arch::id,
    KUTLOG_ARCHS(KUTLOG_ARCH_VALUE)
#undef KUTLOG_ARCH_VALUE
};

// The names KUTLOG_ARCH and the tools take ("avx512", "avx2", "sse4.1", "portable" on x86-64).
std::string_view arch_name(Arch arch);
// The arch of that name; std::invalid_argument listing the valid names otherwise.
Arch parse_arch(std::string_view name);

// True if this CPU has the instructions and the OS saves the registers.
bool arch_supported(Arch arch);
// The compiled archs this machine runs, best first.
std::vector<Arch> supported_archs();

// The arch the array functions use now: the forced one, else KUTLOG_ARCH if set, else the
// best supported. A KUTLOG_ARCH that names an unknown or unsupported arch makes the first use
// throw std::runtime_error saying so (never an illegal instruction).
Arch active_arch();

// Makes the array functions use `arch` from now on, in every thread. Throws
// std::runtime_error if this machine cannot run it.
void force_arch(Arch arch);
void force_arch(std::string_view name);
// Back to KUTLOG_ARCH or the best supported arch.
void reset_arch();

// Forces an arch for a scope (tests, benchmarks), restoring the automatic choice after it.
class ScopedArch {
 public:
  explicit ScopedArch(Arch arch) { force_arch(arch); }
  ~ScopedArch() { reset_arch(); }
  ScopedArch(const ScopedArch&) = delete;
  ScopedArch& operator=(const ScopedArch&) = delete;
};

}  // namespace kutlog
KUTLOG_API_END
