// kutlog/dispatch.hpp: which arch (instruction set) the array functions run on. kutlog compiles
// its kernels once per arch, each in its own translation unit with only that arch's flags, and
// picks one at run time: the best the CPU supports and the operating system has enabled (on x86,
// CPUID and XGETBV), unless the environment variable KUTLOG_ARCH or force_arch() names one.
// Choosing is thread-safe; an array call reads the choice once. For tests,
// KUTLOG_CPU_HIDE=avx512[,avx2,...] makes kutlog treat the CPU as lacking those archs (and every
// arch ranked above them). A name in KUTLOG_ARCH or KUTLOG_CPU_HIDE that is unknown or
// unsupported is ignored, printed once on stderr and kept by arch_environment_error(): array
// calls never throw for it (docs/bad-input.md).
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "kutlog/archs.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// The archs compiled in, from the registry (cmake/KutlogArchs.cmake, through the generated
// kutlog/archs.hpp), best first, the last the baseline: on x86-64 avx512 (AVX-512 F, CD, DQ, BW,
// VL + FMA), avx2 (AVX2 + FMA3) and sse4_1 (x86-64-v2); on AArch64 neon64; on any other CPU, or
// with -DKUTLOG_PORTABLE_ONLY=ON, portable alone (the compiler's own vectors, no SIMD flags).
enum class Arch {
#define KUTLOG_ARCH_ENUMERATOR(id, ...) id,
  KUTLOG_ARCHS(KUTLOG_ARCH_ENUMERATOR)
#undef KUTLOG_ARCH_ENUMERATOR
};

// Every Arch, best first.
inline constexpr std::array kCompiledArchs = {
#define KUTLOG_ARCH_VALUE(id, ...) Arch::id,
    KUTLOG_ARCHS(KUTLOG_ARCH_VALUE)
#undef KUTLOG_ARCH_VALUE
};

// The arch's name, as KUTLOG_ARCH and force_arch take it ("sse4.1" for Arch::sse4_1).
std::string_view arch_name(Arch arch);
// The Arch of that name; std::invalid_argument listing the valid names for an unknown one.
Arch parse_arch(std::string_view name);

// Whether this CPU and OS run the arch (less those KUTLOG_CPU_HIDE hides), and the archs that
// pass, best first. Detected once, thread-safely.
bool arch_supported(Arch arch);
std::vector<Arch> supported_archs();

// The arch the array functions use now: the forced one, else KUTLOG_ARCH if it names a supported
// arch, else the best supported. std::runtime_error only on a CPU that runs no compiled arch
// (never an illegal instruction).
Arch active_arch();

// What was wrong with KUTLOG_ARCH or KUTLOG_CPU_HIDE, or empty.
std::string arch_environment_error();

// Makes every thread's array calls run on that arch (by name: std::invalid_argument for an
// unknown one); std::runtime_error if this machine cannot run it. reset_arch() returns to the
// automatic choice.
void force_arch(Arch arch);
void force_arch(std::string_view name);
void reset_arch();

}  // namespace kutlog
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
