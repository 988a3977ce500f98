// kutlog/math.hpp: the SIMD math kernels (kutlog/simd/math.hpp) over arrays, dispatched at
// run time to the best arch (kutlog/dispatch.hpp).
//
// Every function takes any count and any alignment; the tail is computed in a full batch
// through a local buffer, so nothing is read or written outside [0, count). out may equal an
// input (in place); otherwise the arrays must not overlap. Thread-safe, no allocation.
// Contracts (domain, bound, special values) are those of the kernel of the same name.
#pragma once

#include <cstddef>

#include "kutlog/api.hpp"

KUTLOG_API_BEGIN
namespace kutlog::math {

void acos_u10(const float* x, float* out, std::size_t count);
void cos_u10(const float* x, float* out, std::size_t count);
void cos_halfpi_u10(const float* x, float* out, std::size_t count);
void exp_u10(const float* x, float* out, std::size_t count);
void log_u10(const float* x, float* out, std::size_t count);
// out[i] = x[i]^y[i]
void pow_u10(const float* x, const float* y, float* out, std::size_t count);
// out[i] = x[i]^y
void pow_u10(const float* x, float y, float* out, std::size_t count);

}  // namespace kutlog::math
KUTLOG_API_END
