// The primitives of kutlog::simd::portable (kutlog/simd/detail/portable.hpp), lane by lane against
// C++'s scalar operations, special values included: the kernels' accuracy tests cover what
// the kernels call, this covers the rest of what xsimd's API can reach and the semantics the
// kernels rely on (NaN in min and max, ties to even, -0).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "kutlog/simd/float_ops.hpp"

namespace {

using kutlog::simd::portable;
using Floats = xsimd::batch<float, portable>;
using Doubles = xsimd::batch<double, portable>;
using Ints = xsimd::batch<std::int32_t, portable>;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Lane i of the result equals scalar(lane i of the inputs), bit for bit (NaN for NaN).
template <class Batch, class Scalar>
void expect_lanes(Batch result, Scalar scalar) {
  for (std::size_t i = 0; i < Batch::size; ++i) {
    const auto expected = scalar(i);
    if constexpr (std::is_floating_point_v<decltype(expected)>) {
      if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(result.get(i))) << "lane " << i;
        continue;
      }
      EXPECT_EQ(std::signbit(result.get(i)), std::signbit(expected)) << "lane " << i;
    }
    EXPECT_EQ(result.get(i), expected) << "lane " << i;
  }
}

TEST(PortableArch, ShapeAndNoFusedMultiplyAdd) {
  EXPECT_EQ(Floats::size, 4u);
  EXPECT_EQ(Doubles::size, 2u);
  EXPECT_FALSE(kutlog::simd::has_fused_fma<portable>);
}

TEST(PortableArch, ArithmeticRoundsEachLaneOnce) {
  const std::array<float, 4> a = {1.0f, 0x1p-149f, -3.5f, kInf}, b = {3.0f, 0.5f, -0.0f, 1.0f};
  const Floats x = Floats::load_unaligned(a.data()), y = Floats::load_unaligned(b.data());
  expect_lanes(x + y, [&](std::size_t i) { return a[i] + b[i]; });
  expect_lanes(x - y, [&](std::size_t i) { return a[i] - b[i]; });
  expect_lanes(x * y, [&](std::size_t i) { return a[i] * b[i]; });
  expect_lanes(x / y, [&](std::size_t i) { return a[i] / b[i]; });
  expect_lanes(-x, [&](std::size_t i) { return -a[i]; });
  expect_lanes(xsimd::fma(x, y, x), [&](std::size_t i) { return a[i] * b[i] + a[i]; });
  expect_lanes(xsimd::reciprocal(y), [&](std::size_t i) { return 1.0f / b[i]; });
}

TEST(PortableArch, MinAndMaxReturnTheSecondOperandWhereEitherIsNaN) {
  const std::array<float, 4> a = {kNaN, 1.0f, -0.0f, 2.0f}, b = {1.0f, kNaN, 0.0f, -2.0f};
  const Floats x = Floats::load_unaligned(a.data()), y = Floats::load_unaligned(b.data());
  expect_lanes(xsimd::min(x, y), [&](std::size_t i) { return a[i] < b[i] ? a[i] : b[i]; });
  expect_lanes(xsimd::max(x, y), [&](std::size_t i) { return a[i] > b[i] ? a[i] : b[i]; });
}

TEST(PortableArch, LaneFunctionsAsTheCLibrary) {
  const std::array<float, 4> a = {2.5f, -0.0f, 3.5f, -1.5f}, squares = {2.0f, 0x1p-149f, kInf, 0.0f};
  const Floats x = Floats::load_unaligned(a.data());
  expect_lanes(xsimd::nearbyint(x), [&](std::size_t i) { return std::nearbyint(a[i]); });  // ties to even
  expect_lanes(xsimd::abs(x), [&](std::size_t i) { return std::fabs(a[i]); });
  expect_lanes(xsimd::sqrt(Floats::load_unaligned(squares.data())),
               [&](std::size_t i) { return std::sqrt(squares[i]); });
  // Ties to even, the sign of -0.4 kept, integers and what is not finite as they are.
  const std::array<float, 8> more = {-0.4f, 0x1p23f + 1.0f, kNaN, -kInf, 0.5f, 1.5f, -0x1p30f, 8388607.5f};
  for (std::size_t at = 0; at < more.size(); at += Floats::size)
    expect_lanes(xsimd::nearbyint(Floats::load_unaligned(more.data() + at)),
                 [&](std::size_t i) { return std::nearbyint(more[at + i]); });
  const std::array<double, 4> doubles = {-2.5, 0x1p52 + 1.0, -0.3, 4503599627370495.5};
  for (std::size_t at = 0; at < doubles.size(); at += Doubles::size)
    expect_lanes(xsimd::nearbyint(Doubles::load_unaligned(doubles.data() + at)),
                 [&](std::size_t i) { return std::nearbyint(doubles[at + i]); });
}

TEST(PortableArch, ComparisonsSelectsAndReductions) {
  const std::array<float, 4> a = {kNaN, 1.0f, -0.0f, 2.0f}, b = {1.0f, 1.0f, 0.0f, 3.0f};
  const Floats x = Floats::load_unaligned(a.data()), y = Floats::load_unaligned(b.data());
  const auto chosen = [&](auto mask, auto scalar) {
    expect_lanes(xsimd::select(mask, x, y), [&](std::size_t i) { return scalar(a[i], b[i]) ? a[i] : b[i]; });
  };
  chosen(x == y, [](float p, float q) { return p == q; });
  chosen(x != y, [](float p, float q) { return p != q; });
  chosen(x < y, [](float p, float q) { return p < q; });
  chosen(x <= y, [](float p, float q) { return p <= q; });
  chosen(x > y, [](float p, float q) { return p > q; });
  chosen(x >= y, [](float p, float q) { return p >= q; });
  chosen(xsimd::isnan(x), [](float p, float) { return std::isnan(p); });
  chosen(!(x < y) && (x == x), [](float p, float q) { return !(p < q) && p == p; });
  EXPECT_FALSE(xsimd::all(x <= y));
  EXPECT_TRUE(xsimd::any(x <= y));
  EXPECT_TRUE(xsimd::all(y == y));
  EXPECT_FALSE(xsimd::any(x != x && y != y));
}

TEST(PortableArch, BitsShiftsAndConversions) {
  const std::array<float, 4> a = {-1.5f, 0x1p-149f, kInf, 7.75f};
  const Floats x = Floats::load_unaligned(a.data());
  const Ints bits = xsimd::bitwise_cast<Ints>(x);
  expect_lanes(bits, [&](std::size_t i) { return std::bit_cast<std::int32_t>(a[i]); });
  expect_lanes(bits >> 23, [&](std::size_t i) { return std::bit_cast<std::int32_t>(a[i]) >> 23; });
  expect_lanes(bits << 1, [&](std::size_t i) {
    return std::int32_t(std::uint32_t(std::bit_cast<std::int32_t>(a[i])) << 1);
  });
  expect_lanes(x ^ Floats(-0.0f), [&](std::size_t i) { return -a[i]; });
  expect_lanes(xsimd::to_float(Ints{1, -2, 16777217, -2147483647 - 1}), [](std::size_t i) {
    return float(std::array<std::int32_t, 4>{1, -2, 16777217, -2147483647 - 1}[i]);
  });
  expect_lanes(xsimd::to_int(Floats{1.75f, -2.75f, 0.0f, 1e9f}), [](std::size_t i) {
    return std::int32_t(std::array<float, 4>{1.75f, -2.75f, 0.0f, 1e9f}[i]);  // truncated
  });
}

TEST(PortableArch, WhatXsimdsApiNamesBeyondTheKernels) {
  const std::array<std::int32_t, 4> a = {2147483600, -5, -2147483600, 3}, b = {100, 7, 100, -1};
  const Ints x = Ints::load_unaligned(a.data()), y = Ints::load_unaligned(b.data());
  const auto clamp = [](std::int64_t v) {
    return std::int32_t(std::clamp<std::int64_t>(v, std::numeric_limits<std::int32_t>::min(),
                                                 std::numeric_limits<std::int32_t>::max()));
  };
  expect_lanes(xsimd::sadd(x, y), [&](std::size_t i) { return clamp(std::int64_t(a[i]) + b[i]); });
  expect_lanes(xsimd::ssub(x, y), [&](std::size_t i) { return clamp(std::int64_t(a[i]) - b[i]); });
  expect_lanes(xsimd::zip_lo(x, y), [&](std::size_t i) { return i % 2 ? b[i / 2] : a[i / 2]; });
  expect_lanes(xsimd::zip_hi(x, y), [&](std::size_t i) { return i % 2 ? b[2 + i / 2] : a[2 + i / 2]; });
  const Floats rows[4] = {Floats{1, 2, 3, 4}, Floats(0.5f), Floats{-1, 1, -1, 1}, Floats(8.0f)};
  expect_lanes(xsimd::haddp(rows), [](std::size_t i) { return std::array<float, 4>{10, 2, 0, 32}[i]; });
}

}  // namespace
