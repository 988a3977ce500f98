// What this CPU can run: the features that the arch registry (cmake/KutlogArchs.cmake) names
// in each arch's CPU field. Compiled with the baseline flags only.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace kutlog::detail {

// The CPUID words features are read from (x86), each from its leaf and sub-leaf.
enum class CpuidWord {
  leaf1_ecx,
  leaf1_edx,
  leaf7_ebx,    // leaf 7, sub-leaf 0
  leaf7_ecx,
  leaf7_edx,
  leaf7_1_eax,  // leaf 7, sub-leaf 1
  leaf7_1_edx,
  leaf24_ebx,   // leaf 0x24: AVX10 version and vector lengths
  count,
};

// What the features are decided from: this CPU's, or words recorded from another one.
struct CpuWords {
  std::array<std::uint32_t, std::size_t(CpuidWord::count)> cpuid{};  // x86
  std::uint64_t xcr0 = 0;  // the register states the OS saves; 0 without OSXSAVE (x86)
  std::uint64_t hwcap = 0;  // getauxval(AT_HWCAP) (AArch64)
  std::uint32_t& operator[](CpuidWord word) { return cpuid[std::size_t(word)]; }
  std::uint32_t operator[](CpuidWord word) const { return cpuid[std::size_t(word)]; }
};

// True if `words` show every feature of the space-separated list with its registers enabled;
// false for a feature that is not known on this platform.
bool has_features(const CpuWords& words, std::string_view features);

// This CPU's words, read once.
const CpuWords& cpu_words();

// has_features of this CPU.
bool cpu_has_features(std::string_view features);

// Throws std::runtime_error if this CPU runs none of the compiled archs (src/arch_choice.cpp).
// The constructors of Lobe, PerLaneLobe, PowerPoly and LobeSampler call it, so that their
// noexcept array calls always find an arch.
void require_runnable_arch();

}  // namespace kutlog::detail
