// The CPU feature parser on recorded and edited CPUID words (x86) and HWCAP words (AArch64),
// and has_fused_fma against the arch registry.
#include <gtest/gtest.h>

#include "arch/kernel_table.hpp"
#include "cpu_features.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/archs.hpp"
#include "kutlog/simd/float_ops.hpp"

namespace kutlog::detail {
namespace {

// Every registry arch's has_fused_fma is its FUSED_FMA field.
#define KUTLOG_CHECK_FUSED_FMA(id, name, xsimd_arch, cpu_features, fused_fma)  \
  static_assert(simd::has_fused_fma<xsimd_arch> == fused_fma,                   \
                "has_fused_fma of arch " name " differs from the registry's FUSED_FMA");
KUTLOG_ARCHS(KUTLOG_CHECK_FUSED_FMA)
#undef KUTLOG_CHECK_FUSED_FMA

// The arithmetic agrees with the registry: each supported arch's mul_add rounds once exactly
// where its entry says FUSED_FMA YES.
TEST(FusedFma, MulAddRoundsOnceExactlyWhereTheRegistrySaysSo) {
#define KUTLOG_CHECK_MUL_ADD(id, name, xsimd_arch, cpu_features, fused_fma)            \
  if (arch_supported(Arch::id))                                                         \
    EXPECT_EQ(kernel_table<Arch::id>().mul_add_rounds_once(), fused_fma) << name;
  KUTLOG_ARCHS(KUTLOG_CHECK_MUL_ADD)
#undef KUTLOG_CHECK_MUL_ADD
}

// Every entry of the dispatch's lists (the math kernels, KUTLOG_ARRAY_ENTRIES, the lobes'
// slots) is filled in the table of every compiled arch this CPU runs.
void expect_every_entry_filled(const KernelTable& table, const char* arch) {
#define KUTLOG_CHECK_UNARY(function, kernel, ...) EXPECT_NE(table.kernel, nullptr) << arch;
#define KUTLOG_CHECK_BINARY(function, kernel, ...) \
  EXPECT_NE(table.kernel, nullptr) << arch;        \
  EXPECT_NE(table.kernel##_scalar, nullptr) << arch;
#define KUTLOG_CHECK_ENTRY(entry, ...) EXPECT_NE(table.entry, nullptr) << arch << " " #entry;
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_CHECK_UNARY)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_CHECK_BINARY)
  KUTLOG_ARRAY_ENTRIES(KUTLOG_CHECK_ENTRY)
#undef KUTLOG_CHECK_UNARY
#undef KUTLOG_CHECK_BINARY
#undef KUTLOG_CHECK_ENTRY
  for (LobeArrayKernel loop : table.by_slot) EXPECT_NE(loop, nullptr) << arch;
}

TEST(KernelTables, EveryListedEntryIsFilledOnEveryCompiledArch) {
  int checked = 0;
#define KUTLOG_CHECK_TABLE(id, name, ...)                      \
  if (arch_supported(Arch::id)) {                              \
    expect_every_entry_filled(kernel_table<Arch::id>(), name); \
    ++checked;                                                 \
  }
  KUTLOG_ARCHS(KUTLOG_CHECK_TABLE)
#undef KUTLOG_CHECK_TABLE
  EXPECT_EQ(checked, int(supported_archs().size()));
}

TEST(CpuFeatures, UnknownFeaturesAreAbsentAndTheEmptyListIsPresent) {
  EXPECT_FALSE(has_features(CpuWords{}, "no_such_feature"));
  EXPECT_TRUE(has_features(CpuWords{}, ""));
}

#if defined(__x86_64__) || defined(__i386__)

using enum CpuidWord;

// An Intel Xeon with AVX-512 and AVX10.1/512, as its CPUID and XGETBV read.
CpuWords xeon_avx10() {
  CpuWords words;
  words[leaf1_ecx] = 0xfffa3203, words[leaf1_edx] = 0x1f8bfbff;
  words[leaf7_ebx] = 0xf1bf2ffb, words[leaf7_ecx] = 0x1a415f46, words[leaf7_edx] = 0x23c14010;
  words[leaf7_1_eax] = 0x1c30, words[leaf7_1_edx] = 0x84000;
  words[leaf24_ebx] = 0x70001;
  words.xcr0 = 0x600e7;
  return words;
}

TEST(CpuFeatures, RecordedXeonHasEveryX86Arch) {
  const CpuWords words = xeon_avx10();
  EXPECT_TRUE(has_features(words, "sse2 sse4_1 sse4_2 avx fma avx2"));
  EXPECT_TRUE(has_features(words, "avx512f avx512cd avx512dq avx512bw avx512vl avx512vnni"));
  EXPECT_TRUE(has_features(words, "avx_vnni"));  // leaf 7 sub-leaf 1 eax
  EXPECT_TRUE(has_features(words, "avx10 avx10_512"));  // leaf 7 sub-leaf 1 edx, leaf 0x24
}

TEST(CpuFeatures, SubLeafOneIsReadApartFromSubLeafZero) {
  CpuWords words = xeon_avx10();
  words[leaf7_1_eax] = 0, words[leaf7_1_edx] = 0;  // a CPU reporting sub-leaf 0 only
  EXPECT_FALSE(has_features(words, "avx_vnni"));
  EXPECT_FALSE(has_features(words, "avx10"));
  EXPECT_TRUE(has_features(words, "avx512f avx2"));
}

TEST(CpuFeatures, RegistersTheOsDoesNotSaveHideTheirFeatures) {
  CpuWords words = xeon_avx10();
  words.xcr0 = 0x7;  // x87, SSE, AVX: no opmask nor ZMM state
  EXPECT_TRUE(has_features(words, "avx2 fma sse4_1"));
  EXPECT_FALSE(has_features(words, "avx512f"));
  words.xcr0 = 0;  // no OSXSAVE
  EXPECT_FALSE(has_features(words, "avx"));
  EXPECT_TRUE(has_features(words, "sse4_1"));
}

TEST(CpuFeatures, AnSse41OnlyCpuHasNoAvx) {
  CpuWords words;
  words[leaf1_ecx] = 1u << 19 | 1u << 9 | 1u, words[leaf1_edx] = 1u << 26;
  EXPECT_TRUE(has_features(words, "sse2 sse3 ssse3 sse4_1"));
  EXPECT_FALSE(has_features(words, "sse4_2"));
  EXPECT_FALSE(has_features(words, "avx"));
}

#elif defined(__aarch64__)

TEST(CpuFeatures, NeonIsReadFromHwcap) {
  CpuWords words;
  words.hwcap = 1u << 1;  // HWCAP_ASIMD
  EXPECT_TRUE(has_features(words, "neon"));
  words.hwcap = 1u << 0;  // HWCAP_FP alone
  EXPECT_FALSE(has_features(words, "neon"));
}

#endif

TEST(CpuFeatures, ThisCpuHasTheBaselineArchsFeatures) {
  constexpr std::string_view kFeaturesOfArchs[] = {
#define KUTLOG_FEATURES_OF(id, name, xsimd_arch, cpu_features, ...) cpu_features,
      KUTLOG_ARCHS(KUTLOG_FEATURES_OF)
#undef KUTLOG_FEATURES_OF
  };
  EXPECT_TRUE(cpu_has_features(std::end(kFeaturesOfArchs)[-1]));
}

}  // namespace
}  // namespace kutlog::detail
