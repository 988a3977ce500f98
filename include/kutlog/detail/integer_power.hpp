// kutlog/detail/integer_power.hpp: base^exponent by squaring, for doubles and xsimd batches.
#pragma once

namespace kutlog::detail {

// base^exponent, exponent >= 0. Inlined, and tagged by the arch whose flags compile it, so
// no copy built for one arch is kept for another.
template <class Tag = void, class T>
[[gnu::always_inline]] inline T integer_power(T base, int exponent) {
  T power(1.0);
  for (; exponent > 0; exponent >>= 1, base *= base)
    if (exponent & 1) power *= base;
  return power;
}

}  // namespace kutlog::detail
