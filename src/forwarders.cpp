// The public array functions: each forwards to the active arch's kernel table. Compiled with
// the baseline flags only.
#include "active_table.hpp"
#include "deterministic.hpp"
#include "kutlog/baselines.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/math.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

namespace kutlog {

using detail::active_table;

namespace math {
#define KUTLOG_FORWARD_UNARY(function, kernel, ...)           \
  void kernel(const float* x, float* out, std::size_t count) { \
    active_table().kernel(x, out, count);                      \
  }
#define KUTLOG_FORWARD_BINARY(function, kernel, ...)                             \
  void kernel(const float* x, const float* y, float* out, std::size_t count) { \
    active_table().kernel(x, y, out, count);                                   \
  }                                                                            \
  void kernel(const float* x, float y, float* out, std::size_t count) {        \
    active_table().kernel##_scalar(x, y, out, count);                          \
  }
KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_FORWARD_UNARY)
KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_FORWARD_BINARY)
#undef KUTLOG_FORWARD_UNARY
#undef KUTLOG_FORWARD_BINARY
}  // namespace math

void Lobe::eval_out_of_line(const float* t, float* out, std::size_t count, Variant variant,
                            Normalization normalization) const noexcept {
  const detail::KernelTable& table = active_table();
  const detail::LobeKernel& chosen =
      inspect::kernel(*this, variant, normalization, table.fused_fma);
  table.of(chosen, variant == Variant::deterministic)(chosen, t, out, count);
}
void PerLaneLobe::eval(const float* t, const float* n, float* out, std::size_t count,
                       Variant variant, Normalization normalization) const noexcept {
  active_table().per_lane_lobe(inspect::kernel(*this, variant),
                               normalization == Normalization::exact_coef,
                               variant == Variant::deterministic, t, n, out, count);
}
void PowerPoly::eval(const float* t, float* out, std::size_t count) const noexcept {
  active_table().power_poly(kernel_, t, out, count);
}
void PerLanePowerPoly::eval(const float* t, const float* n, float* out,
                            std::size_t count) const noexcept {
  active_table().per_lane_power_poly(kernel_, t, n, out, count);
}
void blinn_phong_xsimd(const float* t, float* out, std::size_t count, float n, float scale) {
  ref::validate_exponent(n);
  active_table().blinn_phong_xsimd(t, n, scale, out, count);
}
void blinn_phong_u10(const float* t, float* out, std::size_t count, float n, float scale) {
  ref::validate_exponent(n);
  active_table().blinn_phong_u10(t, n, scale, out, count);
}
void schlick(const float* t, float* out, std::size_t count, float n) {
  ref::validate_exponent(n);
  active_table().schlick(t, n, out, count);
}

void LobeSampler::sample(const float* u1, const float* u2, DirectionSamples out,
                         std::size_t count, Variant variant) const noexcept {
  active_table().sample_lobe(kernel_, variant == Variant::deterministic, u1, u2, out, count);
}

SampledDirection LobeSampler::sample(float u1, float u2, Variant variant) const noexcept {
  if (variant == Variant::deterministic) return detail::deterministic_sample(kernel_, u1, u2);
  return active_table().sample_one(kernel_, u1, u2);
}

void shade(const Lobe& lobe, Vectors normal, Vectors to_light, Vectors to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask, ShadeOptions options) {
  const detail::KernelTable& table = active_table();
  table.shade_vectors(
      inspect::kernel(lobe, options.variant, options.normalization, table.fused_fma), options,
      normal, to_light, to_viewer, out, count, mask);
}
void shade(const Lobe& lobe, Vectors normal, Direction to_light, Direction to_viewer, float* out,
           std::size_t count, const std::uint8_t* mask, ShadeOptions options) {
  const detail::KernelTable& table = active_table();
  table.shade_directions(
      inspect::kernel(lobe, options.variant, options.normalization, table.fused_fma), options,
      normal, to_light, to_viewer, out, count, mask);
}
void shade(const Lobe& lobe, const float* t, const float* n_dot_l, float* out, std::size_t count,
           const std::uint8_t* mask, ShadeOptions options) {
  const detail::KernelTable& table = active_table();
  table.shade_cosines(
      inspect::kernel(lobe, options.variant, options.normalization, table.fused_fma), options, t,
      n_dot_l, out, count, mask);
}

}  // namespace kutlog
