// kutlog/math.hpp: the kernels of kutlog/simd/math.hpp over arrays, dispatched at run time,
// with their contracts. Any count and alignment; out may equal an input, else no overlap.
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
