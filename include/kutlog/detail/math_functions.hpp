// kutlog/detail/math_functions.hpp: the one list of math kernels, which the array API, the
// dispatch table, the accuracy table, the tools, tests and benchmarks expand (docs/design.md,
// "Adding a math kernel"). X(function, kernel, promised_ulp, measured_x86_64, measured_aarch64,
// domain, sweep_lo, sweep_hi, peer: the std:: and xsimd:: function compared, bench_lo, bench_hi)
#pragma once

#define KUTLOG_UNARY_MATH_FUNCTIONS(X)                                                          \
  X(acos, acos_u10, 1.0, 0.65, 0.61, "[-1, 1]", -1.0f, 1.0f, acos, -1.0f, 1.0f)                 \
  X(cos, cos_u10, 1.0, 0.81, 0.81, "[-pi, pi]", -3.14159274f, 3.14159274f, cos, -3.14159f,      \
    3.14159f)                                                                                   \
  X(cos_halfpi, cos_halfpi_u10, 1.0, 0.81, 0.81, "[0, pi/2]", 0.0f, 1.57079637f, cos, 0.0f,     \
    1.57079f)                                                                                   \
  X(exp, exp_u10, 1.0, 0.51, 0.51, "[-104, 89] (0 or inf beyond)", -104.0f, 89.0f, exp, -80.0f, \
    80.0f)                                                                                      \
  X(log, log_u10, 1.0, 0.67, 0.64, "(0, FLT_MAX] (inf for inf)", 0x1p-149f, 3.40282347e38f,    \
    log, 1e-3f, 1e3f)

// kernel(x, y); the benchmarks' y is 1000.
#define KUTLOG_BINARY_MATH_FUNCTIONS(X)                                                        \
  X(pow, pow_u10, 1.0, 0.54, 0.52,                                                             \
    "x in (0, 2^8], y in {1, 2, 5, 10, 50, 100, 500, 1000, 5000}; 10^7 random (x, y)",         \
    0x1p-149f, 256.0f, pow, 0.0f, 1.0f)

#define KUTLOG_MATH_FUNCTIONS(X) KUTLOG_UNARY_MATH_FUNCTIONS(X) KUTLOG_BINARY_MATH_FUNCTIONS(X)
