# The arch registry: the one list of the instruction sets kutlog compiles its kernels for.
#
# Everything that varies with the arch is read from here: the kernel objects and their flags
# (CMakeLists.txt compiles src/arch/kernels.cpp once per entry), the benchmarks' per-arch
# objects (bench/arch_benchmarks.cpp, likewise), the generated header kutlog/archs.hpp (the
# Arch enum, the dispatch table, the names that KUTLOG_ARCH, KUTLOG_CPU_HIDE and the tools
# accept, the error that lists them) and the per-arch tests of tests/CMakeLists.txt.
#
#   kutlog_arch(<id> PLATFORM <x86_64|aarch64|any> NAME <name> XSIMD <xsimd arch type>
#               FUSED_FMA <YES|NO> CPU <features...> FLAGS <flags...>)
#
# <id> is a C++ identifier (the enumerator kutlog::Arch::<id>), <name> what users type
# (KUTLOG_ARCH=<name>), CPU the features src/cpu_features.cpp must find in this CPU (and the
# OS must have enabled) for the arch to be chosen, none for an arch that runs on any CPU.
# FUSED_FMA says whether the arch's multiply-add rounds once: kutlog::simd::has_fused_fma is
# read from it, and with it which of a Lobe's certified kernels the arch runs.
# Entries go best first: dispatch takes the first supported one, and KUTLOG_CPU_HIDE=<name>
# hides an arch and every one listed before it. The last entry of a platform is its baseline.
# An entry of another platform is compiled nowhere; its name is kept for the accuracy table's
# per-platform columns (kutlog/accuracy.hpp).
#
# KUTLOG_PORTABLE_ONLY=ON keeps only the portable entry, as on a CPU kutlog has no SIMD arch
# for: that is how the portable path is built and tested on x86-64 (scripts/test.sh).
option(KUTLOG_PORTABLE_ONLY "Compile only the portable kernels (no SIMD arch, no SIMD flags)" OFF)

if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(KUTLOG_PLATFORM x86_64)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64|ARM64)$")
  set(KUTLOG_PLATFORM aarch64)
else()
  set(KUTLOG_PLATFORM other)
endif()

set(KUTLOG_ARCHS)
set(KUTLOG_ARCH_NAMES_x86_64)
set(KUTLOG_ARCH_NAMES_aarch64)
function(kutlog_arch id)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PLATFORM;NAME;XSIMD;FUSED_FMA" "CPU;FLAGS")
  if(NOT arg_PLATFORM OR NOT arg_NAME OR NOT arg_XSIMD OR NOT arg_FUSED_FMA MATCHES "^(YES|NO)$")
    message(FATAL_ERROR "kutlog_arch(${id}): PLATFORM, NAME, XSIMD and FUSED_FMA YES or NO are required")
  endif()
  if(NOT arg_PLATFORM STREQUAL "any")
    set(KUTLOG_ARCH_NAMES_${arg_PLATFORM} ${KUTLOG_ARCH_NAMES_${arg_PLATFORM}} ${arg_NAME}
        PARENT_SCOPE)
    if(NOT arg_PLATFORM STREQUAL KUTLOG_PLATFORM OR KUTLOG_PORTABLE_ONLY)
      return()
    endif()
  endif()
  set(KUTLOG_ARCHS ${KUTLOG_ARCHS} ${id} PARENT_SCOPE)
  set(KUTLOG_ARCH_NAME_${id} ${arg_NAME} PARENT_SCOPE)
  set(KUTLOG_ARCH_XSIMD_${id} ${arg_XSIMD} PARENT_SCOPE)
  set(KUTLOG_ARCH_FUSED_FMA_${id} ${arg_FUSED_FMA} PARENT_SCOPE)
  set(KUTLOG_ARCH_CPU_${id} ${arg_CPU} PARENT_SCOPE)
  set(KUTLOG_ARCH_FLAGS_${id} ${arg_FLAGS} PARENT_SCOPE)
endfunction()

# GCC 12 warns inside its own avx512fintrin.h, whose _mm512_undefined_ps initializes a vector
# with itself, at -O2 (maybe-uninitialized; uninitialized where a masked load feeds it);
# clang has no such warning (and warns about the unknown option).
kutlog_arch(avx512 PLATFORM x86_64 NAME avx512 XSIMD xsimd::avx512bw FUSED_FMA YES
            CPU avx avx2 fma avx512f avx512cd avx512dq avx512bw avx512vl
            FLAGS -mavx512f -mavx512cd -mavx512dq -mavx512bw -mavx512vl -mfma
                  $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized -Wno-uninitialized>)
kutlog_arch(avx2 PLATFORM x86_64 NAME avx2 XSIMD xsimd::fma3<xsimd::avx2> FUSED_FMA YES
            CPU avx avx2 fma FLAGS -mavx2 -mfma)
kutlog_arch(sse4_1 PLATFORM x86_64 NAME sse4.1 XSIMD xsimd::sse4_1 FUSED_FMA NO CPU sse4_1
            FLAGS -msse4.1)
# Advanced SIMD with double lanes and FMA is part of AArch64: no flags.
kutlog_arch(neon64 PLATFORM aarch64 NAME neon64 XSIMD xsimd::neon64 FUSED_FMA YES CPU neon)
if(NOT KUTLOG_ARCHS AND NOT KUTLOG_PORTABLE_ONLY)
  message(STATUS "kutlog has no SIMD arch for ${CMAKE_SYSTEM_PROCESSOR}: portable kernels only")
endif()
# The same kernel templates on kutlog::simd::portable, an xsimd arch of the compiler's own
# vectors (kutlog/simd/detail/portable.hpp): no flags, any CPU, correct and slower: the only entry on
# a CPU kutlog has no SIMD arch for. Not on x86-64 nor AArch64: there it would only serve
# x86-64 CPUs without SSE4.1 (none made since 2011), and as one more arch of every per-arch
# test it would add about 16 minutes to the exhaustive sweeps; KUTLOG_PORTABLE_ONLY tests it.
if(NOT KUTLOG_ARCHS)
  kutlog_arch(portable PLATFORM any NAME portable XSIMD kutlog::simd::portable
              FUSED_FMA NO)
endif()

# kutlog/archs.hpp: the list as an X-macro, KUTLOG_ARCHS(X) expanding to
# X(id, "name", xsimd type, "cpu features", fused_fma) per arch, best first.
set(KUTLOG_ARCH_ENTRIES "")
foreach(id IN LISTS KUTLOG_ARCHS)
  list(JOIN KUTLOG_ARCH_CPU_${id} " " cpu)
  if(KUTLOG_ARCH_FUSED_FMA_${id})
    set(fused true)
  else()
    set(fused false)
  endif()
  string(APPEND KUTLOG_ARCH_ENTRIES
         " \\\n  X(${id}, \"${KUTLOG_ARCH_NAME_${id}}\", ${KUTLOG_ARCH_XSIMD_${id}}, \"${cpu}\", ${fused})")
endforeach()
list(JOIN KUTLOG_ARCH_NAMES_x86_64 " " KUTLOG_ARCH_NAMES_X86_64)
list(JOIN KUTLOG_ARCH_NAMES_aarch64 " " KUTLOG_ARCH_NAMES_AARCH64)
set(KUTLOG_GENERATED_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
configure_file(${CMAKE_CURRENT_LIST_DIR}/archs.hpp.in
               ${KUTLOG_GENERATED_INCLUDE_DIR}/kutlog/archs.hpp @ONLY)
