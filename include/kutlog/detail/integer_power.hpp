// kutlog/detail/integer_power.hpp: base^exponent by squaring, for doubles and xsimd batches.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

namespace kutlog::detail {

// base^exponent, exponent >= 0. Inlined, and tagged by the arch whose flags compile it, so
// no copy built for one arch is kept for another. Exponents up to 5 (the lobes' usual k) are
// written out, the loop's own products, each behind a branch the predictor learns: a switch's
// indirect jump cost 6 to 10% of the per-lane kernel.
template <class Tag = void, class T>
[[gnu::always_inline]] inline T integer_power(T base, int exponent) {
  const T square = base * base;
  if (exponent == 1) return base;
  if (exponent == 2) return square;
  if (exponent == 3) return base * square;
  if (exponent == 4) return square * square;
  if (exponent == 5) return base * (square * square);
  T power(1.0);
  for (; exponent > 0; exponent >>= 1, base *= base)
    if (exponent & 1) power *= base;
  return power;
}

}  // namespace kutlog::detail

#endif  // KUTLOG_HAS_CXX20
