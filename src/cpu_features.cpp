// CPU feature detection for the arch registry: one row per feature an arch can require. A new
// arch whose features are all here needs no row (docs/design.md, "Adding an arch").
#include "cpu_features.hpp"

#include "kutlog/archs.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#elif defined(__aarch64__) && defined(__linux__)
#include <sys/auxv.h>
#endif

namespace kutlog::detail {
namespace {

#if defined(__x86_64__) || defined(__i386__)

// The register state the OS must save on a context switch for a feature's instructions: an
// AVX instruction on an OS that does not save YMM registers faults.
enum class RegisterState { sse, ymm, zmm };

struct Feature {
  std::string_view name;
  CpuidWord word;
  unsigned bit;
  RegisterState state;
};

using enum CpuidWord;
constexpr std::array kFeatures = {
    Feature{"sse2", leaf1_edx, 26, RegisterState::sse},
    Feature{"sse3", leaf1_ecx, 0, RegisterState::sse},
    Feature{"ssse3", leaf1_ecx, 9, RegisterState::sse},
    Feature{"sse4_1", leaf1_ecx, 19, RegisterState::sse},
    Feature{"sse4_2", leaf1_ecx, 20, RegisterState::sse},
    Feature{"avx", leaf1_ecx, 28, RegisterState::ymm},
    Feature{"fma", leaf1_ecx, 12, RegisterState::ymm},
    Feature{"avx2", leaf7_ebx, 5, RegisterState::ymm},
    Feature{"avx512f", leaf7_ebx, 16, RegisterState::zmm},
    Feature{"avx512dq", leaf7_ebx, 17, RegisterState::zmm},
    Feature{"avx512cd", leaf7_ebx, 28, RegisterState::zmm},
    Feature{"avx512bw", leaf7_ebx, 30, RegisterState::zmm},
    Feature{"avx512vl", leaf7_ebx, 31, RegisterState::zmm},
    Feature{"avx512vnni", leaf7_ecx, 11, RegisterState::zmm},
    Feature{"avx_vnni", leaf7_1_eax, 4, RegisterState::ymm},
    Feature{"avx10", leaf7_1_edx, 19, RegisterState::zmm},
    Feature{"avx10_512", leaf24_ebx, 18, RegisterState::zmm},
};

constexpr unsigned kOsxsaveBit = 27;  // leaf 1 ecx

bool detect(const Feature& feature, const CpuWords& words) {
  if (!(words[feature.word] >> feature.bit & 1)) return false;
  if (feature.state == RegisterState::sse) return true;
  if (feature.state == RegisterState::ymm) return (words.xcr0 & 0x6) == 0x6;  // SSE, AVX state
  return (words.xcr0 & 0xe6) == 0xe6;  // plus opmask, ZMM_Hi256, Hi16_ZMM
}

std::uint64_t read_xcr0() {
  std::uint32_t low, high;
  __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
  return (std::uint64_t(high) << 32) | low;
}

// CPUID says what the processor has, XGETBV which register states the OS saves (xsimd 8.1
// checks only CPUID). A sub-leaf or leaf beyond what the CPU reports reads as zeros.
CpuWords read_words() {
  CpuWords words;
  unsigned eax, ebx, ecx, edx;
  const unsigned max_leaf = __get_cpuid_max(0, nullptr);
  if (max_leaf >= 1 && __get_cpuid(1, &eax, &ebx, &ecx, &edx)) {
    words[leaf1_ecx] = ecx, words[leaf1_edx] = edx;
    if (ecx >> kOsxsaveBit & 1) words.xcr0 = read_xcr0();
  }
  if (max_leaf >= 7) {
    __cpuid_count(7, 0, eax, ebx, ecx, edx);
    const unsigned max_subleaf = eax;
    words[leaf7_ebx] = ebx, words[leaf7_ecx] = ecx, words[leaf7_edx] = edx;
    if (max_subleaf >= 1) {
      __cpuid_count(7, 1, eax, ebx, ecx, edx);
      words[leaf7_1_eax] = eax, words[leaf7_1_edx] = edx;
    }
  }
  if (max_leaf >= 0x24 && (words[leaf7_1_edx] >> 19 & 1)) {
    __cpuid_count(0x24, 0, eax, ebx, ecx, edx);
    words[leaf24_ebx] = ebx;
  }
  return words;
}

#elif defined(__aarch64__)

struct Feature {
  std::string_view name;
  std::uint64_t hwcap_bit;
};
// Advanced SIMD (FEAT_AdvSIMD: double lanes and fused multiply-add) as the kernel reports it.
constexpr std::uint64_t kHwcapAsimd = 1u << 1;  // HWCAP_ASIMD
constexpr std::array kFeatures = {Feature{"neon", kHwcapAsimd}};
bool detect(const Feature& feature, const CpuWords& words) {
  return (words.hwcap & feature.hwcap_bit) != 0;
}
CpuWords read_words() {
  CpuWords words;
#if defined(__linux__)
  words.hwcap = getauxval(AT_HWCAP);
#endif
  return words;
}

#else

struct Feature {
  std::string_view name;
};
constexpr std::array<Feature, 0> kFeatures = {};
bool detect(const Feature&, const CpuWords&) { return false; }
CpuWords read_words() { return {}; }

#endif

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
#define KUTLOG_CHECK_CPU_FEATURES(id, name, xsimd_arch, cpu_features, ...)             \
  static_assert(all_words(cpu_features, known),                                       \
                "cmake/KutlogArchs.cmake: arch " name " requires a CPU feature that " \
                "src/cpu_features.cpp does not detect");
KUTLOG_ARCHS(KUTLOG_CHECK_CPU_FEATURES)
#undef KUTLOG_CHECK_CPU_FEATURES

}  // namespace

bool has_features(const CpuWords& words, std::string_view features) {
  return all_words(features, [&](std::string_view name) {
    for (const Feature& feature : kFeatures)
      if (feature.name == name) return detect(feature, words);
    return false;
  });
}

const CpuWords& cpu_words() {
  static const CpuWords words = read_words();
  return words;
}

bool cpu_has_features(std::string_view features) { return has_features(cpu_words(), features); }

}  // namespace kutlog::detail
