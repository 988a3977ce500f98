// kutlog/detail/float_ulp.hpp: the ulp of a float, from a double's exponent bits (fast).
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <algorithm>
#include <bit>
#include <cstdint>

namespace kutlog::detail {

// 2^exponent, for an exponent of the normal doubles.
constexpr double power_of_two(int exponent) {
  return std::bit_cast<double>(std::uint64_t(exponent + 1023) << 52);
}

// log2 of the ulp of a float of magnitude |value| (subnormals included).
constexpr int float_ulp_exponent(double value) {
  const int biased = int((std::bit_cast<std::uint64_t>(value) >> 52) & 0x7ff);  // 0 for 0
  return std::max(biased - 1023, -126) - 23;
}

constexpr double ulp_of_float(double value) { return power_of_two(float_ulp_exponent(value)); }

}  // namespace kutlog::detail

#endif  // KUTLOG_HAS_CXX20
