// kutlog/math.hpp: the SIMD math kernels (kutlog/simd/math.hpp) over arrays, dispatched at
// run time to the best arch (kutlog/dispatch.hpp).
//
// Every function takes any count and any alignment; the tail is computed in a full batch
// through a local buffer, so nothing is read or written outside [0, count). out may equal an
// input (in place); otherwise the arrays must not overlap. Thread-safe, no allocation.
// Contracts (domain, bound, special values) are those of the kernel of the same name; the
// kernels are those of kutlog/detail/math_functions.hpp.
#pragma once

#include <cstddef>

#include "kutlog/api.hpp"
#include "kutlog/detail/math_functions.hpp"

KUTLOG_API_BEGIN
namespace kutlog::math {

// kernel(x, out, count) per unary kernel; kernel(x, y, out, count), out[i] = kernel(x[i], y[i]),
// and kernel(x, y, out, count), out[i] = kernel(x[i], y), per binary one.
#define KUTLOG_DECLARE_UNARY(function, kernel, ...) \
  void kernel(const float* x, float* out, std::size_t count);
#define KUTLOG_DECLARE_BINARY(function, kernel, ...)                            \
  void kernel(const float* x, const float* y, float* out, std::size_t count); \
  void kernel(const float* x, float y, float* out, std::size_t count);
KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_DECLARE_UNARY)
KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_DECLARE_BINARY)
#undef KUTLOG_DECLARE_UNARY
#undef KUTLOG_DECLARE_BINARY

}  // namespace kutlog::math
KUTLOG_API_END
