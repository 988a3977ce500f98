// The C API (kutlog/kutlog.h) past a lobe's scalar calls (src/c_api_lobe.cpp): each call checks
// its handles, pointers, counts and enums, then calls the C++ API, every exception caught at
// this boundary (src/c_api_boundary.hpp) and turned into a status and a message.
#include <cstdint>
#include <string_view>

#include "c_api_boundary.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/math.hpp"
#include "kutlog/shade.hpp"

using namespace kutlog::c_api;

extern "C" {

kutlog_status kutlog_lobe_eval_array(const kutlog_lobe* lobe, const float* t, float* out,
                                     std::size_t count, kutlog_variant variant,
                                     kutlog_normalization normalization, kutlog_error* error) {
  return guarded(error, [&] {
    if (const kutlog_status status = Check(error)
                                         .handle(lobe, "lobe")
                                         .variant(variant)
                                         .normalization(normalization)
                                         .arrays(count, {{"t", t}, {"out", out}}))
      return status;
    lobe->lobe.eval(t, out, count, kutlog::Variant(variant),
                    kutlog::Normalization(normalization));
    return KUTLOG_OK;
  });
}

kutlog_status kutlog_per_lane_lobe_create(double n_min, double n_max, int k, double Q,
                                          kutlog_per_lane_lobe** lobe, kutlog_error* error) {
  return create(lobe, error, n_min, n_max, k, Q);
}
void kutlog_per_lane_lobe_destroy(kutlog_per_lane_lobe* lobe) { delete lobe; }
float kutlog_per_lane_lobe_eval(const kutlog_per_lane_lobe* lobe, float t, float n,
                                kutlog_variant variant, kutlog_normalization normalization) {
  if (!lobe || !valid_variant(variant) || !valid_normalization(normalization)) return kNaN;
  return lobe->lobe.eval(t, n, kutlog::Variant(variant), kutlog::Normalization(normalization));
}
kutlog_status kutlog_per_lane_lobe_eval_array(const kutlog_per_lane_lobe* lobe, const float* t,
                                              const float* n, float* out, std::size_t count,
                                              kutlog_variant variant,
                                              kutlog_normalization normalization,
                                              kutlog_error* error) {
  return guarded(error, [&] {
    if (const kutlog_status status = Check(error)
                                         .handle(lobe, "lobe")
                                         .variant(variant)
                                         .normalization(normalization)
                                         .arrays(count, {{"t", t}, {"n", n}, {"out", out}}))
      return status;
    lobe->lobe.eval(t, n, out, count, kutlog::Variant(variant),
                    kutlog::Normalization(normalization));
    return KUTLOG_OK;
  });
}

kutlog_shade_options kutlog_default_shade_options(void) {
  return {KUTLOG_PRECISE, KUTLOG_UNNORMALIZED, KUTLOG_REFLECT_BLINN, 1};
}

kutlog_status kutlog_shade(const kutlog_lobe* lobe, kutlog_vectors normal,
                           kutlog_vectors to_light, kutlog_vectors to_viewer, float* out,
                           std::size_t count, const std::uint8_t* mask,
                           const kutlog_shade_options* options, kutlog_error* error) {
  return guarded(error, [&] {
    const kutlog_shade_options chosen = options ? *options : kutlog_default_shade_options();
    if (const kutlog_status status =
            Check(error).handle(lobe, "lobe").options(chosen).arrays(
                count, {{"normal.x", normal.x}, {"normal.y", normal.y}, {"normal.z", normal.z},
                        {"to_light.x", to_light.x}, {"to_light.y", to_light.y},
                        {"to_light.z", to_light.z}, {"to_viewer.x", to_viewer.x},
                        {"to_viewer.y", to_viewer.y}, {"to_viewer.z", to_viewer.z},
                        {"out", out}}))
      return status;
    kutlog::shade(lobe->lobe, {normal.x, normal.y, normal.z},
                  {to_light.x, to_light.y, to_light.z}, {to_viewer.x, to_viewer.y, to_viewer.z},
                  out, count, mask, options_of(chosen));
    return KUTLOG_OK;
  });
}

kutlog_status kutlog_shade_directional(const kutlog_lobe* lobe, kutlog_vectors normal,
                                       kutlog_direction to_light, kutlog_direction to_viewer,
                                       float* out, std::size_t count, const std::uint8_t* mask,
                                       const kutlog_shade_options* options,
                                       kutlog_error* error) {
  return guarded(error, [&] {
    const kutlog_shade_options chosen = options ? *options : kutlog_default_shade_options();
    if (const kutlog_status status =
            Check(error).handle(lobe, "lobe").options(chosen).arrays(
                count, {{"normal.x", normal.x}, {"normal.y", normal.y}, {"normal.z", normal.z},
                        {"out", out}}))
      return status;
    kutlog::shade(lobe->lobe, {normal.x, normal.y, normal.z},
                  kutlog::Direction{to_light.x, to_light.y, to_light.z},
                  kutlog::Direction{to_viewer.x, to_viewer.y, to_viewer.z}, out, count, mask,
                  options_of(chosen));
    return KUTLOG_OK;
  });
}

kutlog_status kutlog_shade_cosines(const kutlog_lobe* lobe, const float* t, const float* n_dot_l,
                                   float* out, std::size_t count, const std::uint8_t* mask,
                                   const kutlog_shade_options* options, kutlog_error* error) {
  return guarded(error, [&] {
    const kutlog_shade_options chosen = options ? *options : kutlog_default_shade_options();
    // n_dot_l may be NULL where it is not read.
    const void* read_n_dot_l = chosen.times_n_dot_l ? n_dot_l : static_cast<const void*>(t);
    if (const kutlog_status status =
            Check(error).handle(lobe, "lobe").options(chosen).arrays(
                count, {{"t", t}, {"n_dot_l", read_n_dot_l}, {"out", out}}))
      return status;
    kutlog::shade(lobe->lobe, t, n_dot_l, out, count, mask, options_of(chosen));
    return KUTLOG_OK;
  });
}

kutlog_status kutlog_sampler_create(double n, int k, double Q, kutlog_lobe_use use,
                                    kutlog_sampler** sampler, kutlog_error* error) {
  if (const kutlog_status status = Check(error).in_range(
          use, 2, "use", "KUTLOG_USE_MICROFACET or KUTLOG_USE_PHONG")) {
    if (sampler) *sampler = nullptr;
    return status;
  }
  return create(sampler, error, n, k, Q, kutlog::LobeUse(use));
}
void kutlog_sampler_destroy(kutlog_sampler* sampler) { delete sampler; }
kutlog_sample kutlog_sampler_sample(const kutlog_sampler* sampler, float u1, float u2,
                                    kutlog_variant variant) {
  if (!sampler || !valid_variant(variant)) return {kNaN, kNaN, kNaN, kNaN};
  const kutlog::SampledDirection direction =
      sampler->sampler.sample(u1, u2, kutlog::Variant(variant));
  return {direction.x, direction.y, direction.z, direction.pdf};
}
kutlog_status kutlog_sampler_sample_array(const kutlog_sampler* sampler, const float* u1,
                                          const float* u2, float* x, float* y, float* z,
                                          float* pdf, std::size_t count, kutlog_variant variant,
                                          kutlog_error* error) {
  return guarded(error, [&] {
    if (const kutlog_status status =
            Check(error).handle(sampler, "sampler").variant(variant).arrays(
                count, {{"u1", u1}, {"u2", u2}, {"x", x}, {"y", y}, {"z", z}, {"pdf", pdf}}))
      return status;
    sampler->sampler.sample(u1, u2, {x, y, z, pdf}, count, kutlog::Variant(variant));
    return KUTLOG_OK;
  });
}

// kernel(inputs..., out, count) after the array checks.
#define KUTLOG_C_MATH_BODY(kernel, inputs, ...)                                           \
  return guarded(error, [&] {                                                             \
    if (const kutlog_status status = Check(error).arrays(count, {__VA_ARGS__, {"out", out}})) \
      return status;                                                                      \
    kutlog::math::kernel(KUTLOG_UNPARENTHESIZE inputs, out, count);                       \
    return KUTLOG_OK;                                                                     \
  });
#define KUTLOG_UNPARENTHESIZE(...) __VA_ARGS__
#define KUTLOG_C_DEFINE_UNARY(function, kernel, ...)                                       \
  kutlog_status kutlog_##kernel(const float* x, float* out, std::size_t count,             \
                                kutlog_error* error) {                                     \
    KUTLOG_C_MATH_BODY(kernel, (x), {"x", x})                                              \
  }
#define KUTLOG_C_DEFINE_BINARY(function, kernel, ...)                                          \
  kutlog_status kutlog_##kernel(const float* x, const float* y, float* out, std::size_t count, \
                                kutlog_error* error) {                                         \
    KUTLOG_C_MATH_BODY(kernel, (x, y), {"x", x}, {"y", y})                                     \
  }                                                                                            \
  kutlog_status kutlog_##kernel##_scalar_y(const float* x, float y, float* out,                \
                                           std::size_t count, kutlog_error* error) {           \
    KUTLOG_C_MATH_BODY(kernel, (x, y), {"x", x})                                               \
  }
KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_C_DEFINE_UNARY)
KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_C_DEFINE_BINARY)
#undef KUTLOG_C_DEFINE_UNARY
#undef KUTLOG_C_DEFINE_BINARY
#undef KUTLOG_UNPARENTHESIZE
#undef KUTLOG_C_MATH_BODY

const char* kutlog_active_arch(kutlog_error* error) {
  const char* name = nullptr;
  guarded(error, [&] {
    name = kutlog::arch_name(kutlog::active_arch()).data();  // the registry's string literal
    return KUTLOG_OK;
  });
  return name;
}
kutlog_status kutlog_force_arch(const char* name, kutlog_error* error) {
  return guarded(error, [&] {
    if (const kutlog_status status = Check(error).pointer(name, "name", "an arch's name")) return status;
    kutlog::force_arch(std::string_view(name));
    return KUTLOG_OK;
  });
}
void kutlog_reset_arch(void) { kutlog::reset_arch(); }

}  // extern "C"
