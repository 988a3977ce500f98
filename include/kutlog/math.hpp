// kutlog/math.hpp: the kernels of kutlog/simd/math.hpp (listed in
// kutlog/detail/math_functions.hpp) over arrays, dispatched at run time to the active arch
// (kutlog/dispatch.hpp). Contracts (domain, bound, special values) are those of the kernel of
// the same name in kutlog/simd/math.hpp, bounds in kutlog/accuracy.hpp. Any count and alignment:
// the tail is one batch whose lanes past count hold 0.5, moved without touching memory outside
// [0, count) (src/arch/partial_batches.hpp). out may equal an input (in place), else no
// overlap. Thread-safe, no allocation; std::runtime_error only on a CPU that runs no compiled
// arch.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstddef>

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

#endif  // KUTLOG_HAS_CXX20
