// CPU feature detection for the arch registry: one row per feature an arch can require. A new
// arch whose features are all here is only an entry in cmake/KutlogArchs.cmake.
#include "cpu_features.hpp"

#include <array>
#include <cstdint>

#include "kutlog/archs.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace kutlog::detail {
namespace {

#if defined(__x86_64__) || defined(__i386__)

// The register state the OS must save on a context switch for a feature's instructions: an
// AVX instruction on an OS that does not save YMM registers faults.
enum class RegisterState { sse, ymm, zmm };

struct Feature {
  std::string_view name;
  unsigned leaf;     // CPUID leaf (subleaf 0)
  int reg;           // 0 ebx, 1 ecx, 2 edx
  unsigned bit;
  RegisterState state;
};

constexpr int kEbx = 0, kEcx = 1, kEdx = 2;
constexpr std::array kFeatures = {
    Feature{"sse2", 1, kEdx, bit_SSE2, RegisterState::sse},
    Feature{"sse3", 1, kEcx, bit_SSE3, RegisterState::sse},
    Feature{"ssse3", 1, kEcx, bit_SSSE3, RegisterState::sse},
    Feature{"sse4_1", 1, kEcx, bit_SSE4_1, RegisterState::sse},
    Feature{"sse4_2", 1, kEcx, bit_SSE4_2, RegisterState::sse},
    Feature{"avx", 1, kEcx, bit_AVX, RegisterState::ymm},
    Feature{"fma", 1, kEcx, bit_FMA, RegisterState::ymm},
    Feature{"avx2", 7, kEbx, bit_AVX2, RegisterState::ymm},
    Feature{"avx512f", 7, kEbx, bit_AVX512F, RegisterState::zmm},
    Feature{"avx512cd", 7, kEbx, bit_AVX512CD, RegisterState::zmm},
    Feature{"avx512dq", 7, kEbx, bit_AVX512DQ, RegisterState::zmm},
    Feature{"avx512bw", 7, kEbx, bit_AVX512BW, RegisterState::zmm},
    Feature{"avx512vl", 7, kEbx, bit_AVX512VL, RegisterState::zmm},
    Feature{"avx512vnni", 7, kEcx, bit_AVX512VNNI, RegisterState::zmm},
};

std::uint64_t read_xcr0() {
  std::uint32_t low, high;
  __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
  return (std::uint64_t(high) << 32) | low;
}

// CPUID says what the processor has; XGETBV says which register states the OS saves (xsimd
// 8.1 checks only CPUID).
bool detect(const Feature& feature) {
  unsigned regs[3], eax;
  if (!__get_cpuid_count(feature.leaf, 0, &eax, &regs[kEbx], &regs[kEcx], &regs[kEdx]))
    return false;
  if (!(regs[feature.reg] & feature.bit)) return false;
  if (feature.state == RegisterState::sse) return true;
  unsigned ebx, ecx, edx;
  if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx) || !(ecx & bit_OSXSAVE)) return false;
  const std::uint64_t xcr0 = read_xcr0();
  if (feature.state == RegisterState::ymm) return (xcr0 & 0x6) == 0x6;  // SSE and AVX state
  return (xcr0 & 0xe6) == 0xe6;  // plus opmask, ZMM_Hi256, Hi16_ZMM
}

#elif defined(__aarch64__)

struct Feature {
  std::string_view name;
};
// Advanced SIMD (NEON) with double lanes and fused multiply-add is part of every AArch64 CPU.
constexpr std::array kFeatures = {Feature{"neon"}};
bool detect(const Feature&) { return true; }

#else

struct Feature {
  std::string_view name;
};
constexpr std::array<Feature, 0> kFeatures = {};
bool detect(const Feature&) { return false; }

#endif

using Detected = std::array<bool, kFeatures.size()>;

const Detected& detected() {
  static const Detected features = [] {
    Detected result{};
    for (std::size_t i = 0; i < kFeatures.size(); ++i) result[i] = detect(kFeatures[i]);
    return result;
  }();
  return features;
}

template <class Function>
constexpr bool all_words(std::string_view words, Function&& function) {
  while (!words.empty()) {
    const std::size_t space = words.find(' ');
    const std::string_view word = words.substr(0, space);
    if (!word.empty() && !function(word)) return false;
    words = space == std::string_view::npos ? std::string_view() : words.substr(space + 1);
  }
  return true;
}

constexpr bool known(std::string_view name) {
  for (const Feature& feature : kFeatures)
    if (feature.name == name) return true;
  return false;
}

// An arch that required a feature missing here would never be chosen: fail the build instead.
#define KUTLOG_CHECK_CPU_FEATURES(id, name, xsimd_arch, cpu_features)                    \
  static_assert(all_words(cpu_features, known),                                       \
                "cmake/KutlogArchs.cmake: arch " name " requires a CPU feature that " \
                "src/cpu_features.cpp does not detect");
KUTLOG_ARCHS(KUTLOG_CHECK_CPU_FEATURES)
#undef KUTLOG_CHECK_CPU_FEATURES

}  // namespace

bool cpu_has_features(std::string_view features) {
  return all_words(features, [](std::string_view name) {
    for (std::size_t i = 0; i < kFeatures.size(); ++i)
      if (kFeatures[i].name == name) return detected()[i];
    return false;
  });
}

}  // namespace kutlog::detail
