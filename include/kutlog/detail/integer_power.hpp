// kutlog/detail/integer_power.hpp: base^exponent by squaring, for doubles and xsimd batches.
#pragma once

namespace kutlog::detail {

// base^exponent, exponent >= 0. Inlined, and tagged by the arch whose flags compile it, so
// no copy built for one arch is kept for another. Exponents up to 5 (the lobes' usual k) are
// written out, the loop's own products, in one jump rather than a loop per batch.
template <class Tag = void, class T>
[[gnu::always_inline]] inline T integer_power(T base, int exponent) {
  const T square = base * base;
  switch (exponent) {
    case 1: return base;
    case 2: return square;
    case 3: return base * square;
    case 4: return square * square;
    case 5: return base * (square * square);
    default: break;
  }
  T power(1.0);
  for (; exponent > 0; exponent >>= 1, base *= base)
    if (exponent & 1) power *= base;
  return power;
}

}  // namespace kutlog::detail
