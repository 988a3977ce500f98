// Benchmark inputs: L1-resident arrays (4096 floats) of values from the range that matters.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace kutlog::bench {

inline constexpr std::size_t kArrayLength = 4096;

// kArrayLength values uniform in [lo, hi], the same for every benchmark that asks for them.
inline std::vector<float> uniform_inputs(float lo, float hi, unsigned seed = 1) {
  std::mt19937 engine(seed);
  std::uniform_real_distribution<float> distribution(lo, hi);
  std::vector<float> values(kArrayLength);
  for (float& value : values) value = distribution(engine);
  return values;
}

}  // namespace kutlog::bench
