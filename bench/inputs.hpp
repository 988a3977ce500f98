// Benchmark inputs: L1-resident arrays (4096 floats) of values from the range that matters.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace kutlog::bench {

inline constexpr std::size_t kArrayLength = 4096;
// The fragment benchmarks' other input count (bench/main.cpp): 2^18, more than a branch
// predictor learns; their names carry it as /inputs:<count>.
inline constexpr std::size_t kFragmentInputsUnlearned = std::size_t(1) << 18;
inline std::string fragment_inputs_token(std::size_t count) {
  return count == kArrayLength ? "" : "/inputs:" + std::to_string(count);
}
// The fragment benchmarks' data sets: how many cosines, and in which order ("": the lobe and
// past it; "/inside": inside the lobe only; "/raster": along scanlines; bench/main.cpp).
struct FragmentDataSet {
  std::size_t count;
  const char* order;
};
// The fragment benchmarks' exponents: a broad lobe and a narrow one.
inline constexpr int kFragmentExponents[] = {50, 1000};
inline constexpr FragmentDataSet kFragmentDataSets[] = {
    {kArrayLength, ""}, {kFragmentInputsUnlearned, ""}, {kArrayLength, "/inside"},
    {kArrayLength, "/raster"}};

// kArrayLength (or count) values uniform in [lo, hi], the same for every benchmark that asks
// for them.
inline std::vector<float> uniform_inputs(float lo, float hi, unsigned seed = 1,
                                         std::size_t count = kArrayLength) {
  std::mt19937 engine(seed);
  std::uniform_real_distribution<float> distribution(lo, hi);
  std::vector<float> values(count);
  for (float& value : values) value = distribution(engine);
  return values;
}

// Two inputs and one output (or more) of x.size() floats (a multiple of 1024) in one 64-byte
// aligned block, each array half a page (modulo 4 KiB) away from the next. With arrays at
// distances that are multiples of 4 KiB, or just above, a load can falsely wait on an earlier
// store to the same low 12 address bits (4K aliasing): where the heap happened to put an
// output vector, pow_xsimd ran at a quarter of its speed and a division-bound kernel at a
// fifteenth.
class BenchArrays {
 public:
  BenchArrays(const std::vector<float>& x, const std::vector<float>& y, int outputs = 1)
      : stride_(x.size() + 512), block_((2 + outputs) * stride_ + 16) {
    const std::size_t misalignment = reinterpret_cast<std::uintptr_t>(block_.data()) % 64 / 4;
    base_ = block_.data() + (16 - misalignment) % 16;
    std::copy(x.begin(), x.end(), this->x());
    std::copy(y.begin(), y.end(), this->y());
  }
  float* x() { return base_; }
  float* y() { return base_ + stride_; }
  float* out(int output = 0) { return base_ + (2 + output) * stride_; }

 private:
  std::size_t stride_;  // + 2 KiB
  std::vector<float> block_;
  float* base_;
};

}  // namespace kutlog::bench
