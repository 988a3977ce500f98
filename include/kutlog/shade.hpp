// kutlog/shade.hpp: the stream API, for a rasterizer's tile or span. From structure-of-arrays
// vectors it forms the cosine the lobe needs (Blinn: N.H with H = (L + V) / |L + V|; Phong: R.V
// with R = 2 (N.L) N - L) and writes out[i] = F(t_i) max(N_i.L_i, 0) (F = coef_exact() F_kutlog
// when normalized; the factor max(N.L, 0) unless options.times_n_dot_l is false), on the active
// arch with the lobe's contract for t. N, L and V must be unit vectors (not renormalized; their
// rounding is covered by the lobe's data rule, t > 1 giving F(1)). Where L + V = 0 the half
// vector is undefined and the term is 0; where |L + V| < 2^-63 (L and V opposite within float
// rounding) |L + V|^2 underflows and the term is 0 or inexact. A NaN or infinite component of N,
// L or V gives NaN.
// mask (optional, may be null): lane i is shaded where mask[i] != 0, elsewhere out[i] keeps its
// value (AVX2 and AVX-512 store with a lane mask; SSE4.1, and the last partial batch, may write
// the unchanged value back). Any count and alignment; nothing outside [0, count) is read or
// written. Thread-safe, no allocation; nothing thrown once a Lobe exists.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstddef>
#include <cstdint>

#include "kutlog/lobe.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// count vectors as three arrays of components (structure of arrays).
struct Vectors {
  const float* x;
  const float* y;
  const float* z;
};

// One vector for every lane: a directional light, or a distant viewer.
struct Direction {
  float x, y, z;
};

// Which cosine the lobe takes: N.H (Blinn) or R.V (Phong).
enum class Reflection : std::uint8_t { blinn, phong };

// The lobe's variant and normalization, the reflection, and whether to multiply by max(N.L, 0).
struct ShadeOptions {
  Variant variant = Variant::precise;
  Normalization normalization = Normalization::none;
  Reflection reflection = Reflection::blinn;
  bool times_n_dot_l = true;  // false: F(t) alone, for a caller that applies its own N.L
};

// Every lane its own normal, light and viewer directions.
void shade(const Lobe& lobe, Vectors normal, Vectors to_light, Vectors to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask = nullptr, ShadeOptions options = {});

// A span lit by one directional light and seen from a fixed viewer: only the normals vary.
// Blinn's H is formed once per call, in double, so t = N.H is closer to the exact cosine than the
// arrays overload's (no underflow of |L + V|^2 either); Phong's R.V is computed as there.
void shade(const Lobe& lobe, Vectors normal, Direction to_light, Direction to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask = nullptr, ShadeOptions options = {});

// The cosines given: t under the lobe's data rule, and n_dot_l as given, the product
// F(t) max(n_dot_l, 0) in IEEE arithmetic (NaN gives NaN, +inf gives inf, or NaN where F = 0).
// n_dot_l may be null when options.times_n_dot_l is false (options.reflection is unused).
void shade(const Lobe& lobe, const float* t, const float* n_dot_l, float* out, std::size_t count,
           const std::uint8_t* mask = nullptr, ShadeOptions options = {});

}  // namespace kutlog
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
