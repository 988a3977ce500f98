// kutlog/shade.hpp: for a rasterizer's tile or span, out[i] = F(t_i) max(N_i.L_i, 0) from unit
// vectors (t = N.H for Blinn, R.V for Phong); lanes where mask[i] == 0 keep out[i]. Data rule
// (opposite L and V, NaN, the mask's stores): docs/api-notes.md.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kutlog/api.hpp"
#include "kutlog/lobe.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

struct Vectors {
  const float* x;
  const float* y;
  const float* z;
};

// One vector for every lane: a directional light, or a distant viewer.
struct Direction {
  float x, y, z;
};

enum class Reflection : std::uint8_t { blinn, phong };

struct ShadeOptions {
  Variant variant = Variant::precise;
  Normalization normalization = Normalization::none;
  Reflection reflection = Reflection::blinn;
  bool times_n_dot_l = true;  // false: F(t) alone, for a caller that applies its own N.L
};

void shade(const Lobe& lobe, Vectors normal, Vectors to_light, Vectors to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask = nullptr, ShadeOptions options = {});

// H formed once per call, in double.
void shade(const Lobe& lobe, Vectors normal, Direction to_light, Direction to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask = nullptr, ShadeOptions options = {});

// n_dot_l may be null when options.times_n_dot_l is false.
void shade(const Lobe& lobe, const float* t, const float* n_dot_l, float* out, std::size_t count,
           const std::uint8_t* mask = nullptr, ShadeOptions options = {});

}  // namespace kutlog
KUTLOG_API_END
