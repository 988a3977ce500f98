// kutlog/simd/constants.hpp: the math kernels' constants and polynomial cores (lowest degree
// first, from tools/fit/fit_polynomials.py), shared with scalar code, so without xsimd.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <cstdint>

namespace kutlog::simd {

namespace constants {
// asin(s) = s + s*z*P(z), z = s^2 in [0, 1/4].
inline constexpr std::array<float, 6> kAsin = {1.666666567e-01f, 7.500094175e-02f,
                                               4.459940270e-02f, 3.110066243e-02f,
                                               1.714923792e-02f, 3.369084746e-02f};
// sin(r) = r + r*u*S(u), cos(r) = 1 - u/2 + u^2*C(u), u = r^2 in [0, (pi/4)^2].
inline constexpr std::array<float, 4> kSin = {-1.666666716e-01f, 8.333331905e-03f,
                                              -1.984008704e-04f, 2.724992555e-06f};
inline constexpr std::array<float, 4> kCos = {4.166666791e-02f, -1.388888806e-03f,
                                              2.480059993e-05f, -2.730095900e-07f};
// log(1+f) = f - f^2/2 + f^3*L(f), f in [sqrt(1/2) - 1, sqrt(2) - 1].
inline constexpr std::array<float, 11> kLog = {
    3.333333433e-01f,  -2.500000000e-01f, 1.999997348e-01f,  -1.666671932e-01f,
    1.428788602e-01f,  -1.249992773e-01f, 1.104825065e-01f,  -9.931553155e-02f,
    9.804564714e-02f,  -9.727659076e-02f, 5.555094406e-02f};
// Double: log(m) = 2s + s*z*A(z), s = (m-1)/(m+1); exp(r) = 1 + r + r^2*E(r), |r| <= ln2/2.
inline constexpr std::array<double, 4> kPowLog = {
    6.66666665544970893e-01, 4.00001218398061242e-01, 2.85508208159606647e-01,
    2.33304672163038351e-01};
inline constexpr std::array<double, 6> kExpDouble = {
    5.00000001345772715e-01, 1.66666666816142561e-01, 4.16664650060400502e-02,
    8.33331093444886900e-03, 1.39336410319867011e-03, 1.98909808697503266e-04};

// pi/2 and pi as float + float; pi/2 also in three parts whose products by |n| <= 2 are exact.
inline constexpr float kHalfPiHi = 1.57079637e+00f, kHalfPiLo = -4.37113883e-08f;
inline constexpr float kHalfPiLo2 = -1.71512451e-15f;
inline constexpr float kPiHi = 3.14159274e+00f, kPiLo = -8.74227766e-08f;
inline constexpr float kTwoOverPi = 6.36619747e-01f;
// ln 2 = kLn2Hi + kLn2Lo, k * kLn2Hi exact for |k| < 2^9.
inline constexpr float kLn2Hi = 6.93145752e-01f, kLn2Lo = 1.42860677e-06f;
inline constexpr std::int32_t kSqrtHalfBits = 0x3f3504f3;  // bits of sqrt(1/2)
inline constexpr float kSmallestNormal = 1.17549435e-38f;
inline constexpr float kTwoTo23 = 8388608.0f;
}  // namespace constants

}  // namespace kutlog::simd

#endif  // KUTLOG_HAS_CXX20
