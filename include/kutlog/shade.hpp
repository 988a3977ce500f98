// kutlog/shade.hpp: the stream API, for a rasterizer's tile or span.
//
// From structure-of-arrays vectors it forms the cosine the lobe needs (Blinn: N.H with
// H = (L + V) / |L + V|; Phong: R.V with R = 2 (N.L) N - L) and writes
//
//   out[i] = F(t_i) * max(N_i . L_i, 0)      (F = coef * F_kutlog when normalized; the factor
//                                             max(N.L, 0) unless options.times_n_dot_l is false)
//
// N, L and V must be unit vectors (the cosines are not renormalized; rounding of normalized
// vectors is covered by the lobe's data rule, t > 1 giving F(1)). Where L + V = 0 the half
// vector is undefined and the specular term is 0; where |L + V| < 2^-63, L and V opposite to
// within float rounding, |L + V|^2 underflows and the term is 0 or inexact. A NaN or infinite
// component of N, L or V gives NaN. The cosine form takes t under the lobe's data rule and
// n_dot_l as given: the product F(t) * max(n_dot_l, 0) in IEEE arithmetic (NaN gives NaN, +inf
// gives inf, or NaN where F = 0).
//
// mask (optional, may be null): lane i is shaded where mask[i] != 0; elsewhere out[i] keeps
// its value (AVX2 and AVX-512 store with a lane mask; SSE4.1, and the last partial batch, may
// write the unchanged value back). Any count, any alignment; nothing outside [0, count) is
// read or written. Thread-safe, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kutlog/api.hpp"
#include "kutlog/lobe.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// Three arrays of the components of n vectors.
struct Vectors {
  const float* x;
  const float* y;
  const float* z;
};

// One vector for every lane: a directional light, or the viewer of an orthographic (or
// distant) camera. Unit length, like the arrays'.
struct Direction {
  float x, y, z;
};

enum class Reflection : std::uint8_t { blinn, phong };

// The defaults are Lobe::eval's: precise, unnormalized (F in [0, 1]; Normalization::exact_coef
// for the energy-conserving coef * F), Blinn, times max(N.L, 0).
struct ShadeOptions {
  Variant variant = Variant::precise;
  Normalization normalization = Normalization::none;
  Reflection reflection = Reflection::blinn;
  bool times_n_dot_l = true;  // false: F(t) alone, for a caller that applies its own N.L
};

void shade(const Lobe& lobe, Vectors normal, Vectors to_light, Vectors to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask = nullptr, ShadeOptions options = {});

// A span lit by one directional light and seen from a fixed viewer: only the normals vary.
// Blinn's H is formed once per call, in double, so t = N.H is closer to the exact cosine than
// the arrays overload's (no underflow of |L + V|^2 either); Phong's R.V is computed as there.
void shade(const Lobe& lobe, Vectors normal, Direction to_light, Direction to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask = nullptr, ShadeOptions options = {});

// The same from cosines computed by the caller: out[i] = F(t[i]) * max(n_dot_l[i], 0) (n_dot_l
// may be null when options.times_n_dot_l is false).
void shade(const Lobe& lobe, const float* t, const float* n_dot_l, float* out, std::size_t count,
           const std::uint8_t* mask = nullptr, ShadeOptions options = {});

}  // namespace kutlog
KUTLOG_API_END
