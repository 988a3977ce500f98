// kutlog/detail/integer_power.hpp: base^exponent by squaring, for doubles and xsimd batches.
#pragma once

namespace kutlog::detail {

// base^exponent (exponent >= 0), about 2 log2(exponent) products. Always inlined, and code
// compiled with one arch's flags passes that arch as Tag: no copy built with one arch's flags
// can be the one the linker keeps for another.
template <class Tag = void, class T>
[[gnu::always_inline]] inline T integer_power(T base, int exponent) {
  T power(1.0);
  for (; exponent > 0; exponent >>= 1, base *= base)
    if (exponent & 1) power *= base;
  return power;
}

}  // namespace kutlog::detail
