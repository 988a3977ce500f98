// The C API (kutlog/kutlog.h): each call checks its handles, pointers, counts and enums, then
// calls the C++ API, every exception caught at this boundary and turned into a status and a
// message.
#include "kutlog/kutlog.h"

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "kutlog/detail/math_functions.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/math.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

struct kutlog_lobe {
  kutlog::Lobe lobe;
};
struct kutlog_per_lane_lobe {
  kutlog::PerLaneLobe lobe;
};
struct kutlog_sampler {
  kutlog::LobeSampler sampler;
};

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

kutlog_status report(kutlog_error* error, kutlog_status code, const char* message) {
  if (error) {
    error->code = code;
    std::snprintf(error->message, sizeof error->message, "%s", message);
  }
  return code;
}

// body() under the boundary's rule: its status, or the exception's.
template <class Body>
kutlog_status guarded(kutlog_error* error, Body body) noexcept {
  try {
    const kutlog_status status = body();
    if (status == KUTLOG_OK) report(error, KUTLOG_OK, "");
    return status;
  } catch (const std::invalid_argument& exception) {
    return report(error, KUTLOG_INVALID_ARGUMENT, exception.what());
  } catch (const std::bad_alloc&) {
    return report(error, KUTLOG_OUT_OF_MEMORY, "kutlog: out of memory");
  } catch (const std::runtime_error& exception) {
    // A CPU without the baseline arch, or a forced arch it lacks; else a setup that met no bound.
    const bool unsupported = std::string(exception.what()).find("no kernel") == std::string::npos;
    return report(error, unsupported ? KUTLOG_UNSUPPORTED : KUTLOG_INTERNAL_ERROR,
                  exception.what());
  } catch (const std::exception& exception) {
    return report(error, KUTLOG_INTERNAL_ERROR, exception.what());
  } catch (...) {
    return report(error, KUTLOG_INTERNAL_ERROR, "kutlog: unknown exception");
  }
}

// The checks of one call, in order, the first failure reported: Check(error).handle(...)...
class Check {
 public:
  explicit Check(kutlog_error* error) : error_(error) {}
  operator kutlog_status() const { return status_; }

  Check& pointer(const void* pointer, const char* name, const char* valid) {
    if (!pointer) fail(std::string(name) + " is NULL; valid: " + valid);
    return *this;
  }
  Check& handle(const void* handle, const char* name) {
    return pointer(handle, name, "a handle from its create call");
  }
  Check& in_range(int value, int count, const char* name, const char* valid) {
    if (value < 0 || value >= count)
      fail(std::string(name) + " = " + std::to_string(value) + " is out of range; valid: " + valid);
    return *this;
  }
  Check& variant(kutlog_variant variant, const char* name = "variant") {
    return in_range(int(variant), 2, name, "KUTLOG_PRECISE or KUTLOG_FAST");
  }
  Check& normalization(kutlog_normalization normalization,
                       const char* name = "normalization") {
    return in_range(int(normalization), 2, name, "KUTLOG_UNNORMALIZED or KUTLOG_EXACT_COEF");
  }
  Check& options(const kutlog_shade_options& options) {
    return variant(options.variant, "options->variant")
        .normalization(options.normalization, "options->normalization")
        .in_range(int(options.reflection), 2, "options->reflection",
                  "KUTLOG_REFLECT_BLINN or KUTLOG_REFLECT_PHONG");
  }
  // The rule of every array: count 0 takes NULL; else each array non-NULL, and count at most
  // KUTLOG_MAX_COUNT.
  struct Array {
    const char* name;
    const void* pointer;
  };
  Check& arrays(std::size_t count, std::initializer_list<Array> arrays) {
    if (count == 0) return *this;
    if (count > std::size_t(KUTLOG_MAX_COUNT))
      fail("count = " + std::to_string(count) + " is out of range; valid: [0, " +
           std::to_string(KUTLOG_MAX_COUNT) + "] (KUTLOG_MAX_COUNT)");
    for (const Array& array : arrays)
      if (!array.pointer)
        fail(std::string(array.name) + " is NULL with count = " + std::to_string(count) +
             "; valid: NULL only with count 0");
    return *this;
  }

 private:
  void fail(const std::string& message) {
    if (status_ == KUTLOG_OK) status_ = report(error_, KUTLOG_INVALID_ARGUMENT, ("kutlog: " + message).c_str());
  }
  kutlog_error* error_;
  kutlog_status status_ = KUTLOG_OK;
};

template <class Enum>
bool valid_enum(Enum value) {
  return int(value) == 0 || int(value) == 1;
}

kutlog::ShadeOptions options_of(const kutlog_shade_options& options) {
  return {kutlog::Variant(options.variant), kutlog::Normalization(options.normalization),
          kutlog::Reflection(options.reflection), options.times_n_dot_l != 0};
}
// Creates a handle around a new C++ object, or reports why not; *handle is NULL then.
template <class Handle, class... Arguments>
kutlog_status create(Handle** handle, kutlog_error* error, Arguments... arguments) {
  if (handle) *handle = nullptr;
  return guarded(error, [&] {
    if (const kutlog_status status = Check(error).pointer(handle, "the handle's address", "where to write the new handle"))
      return status;
    *handle = new Handle{{arguments...}};
    return KUTLOG_OK;
  });
}

// A lobe's fragment handle (precise or fast, by Fragment): its pieces and fallback kernel.
template <class Fragment>
kutlog_status fill_fragment(const kutlog_lobe* lobe, kutlog_normalization normalization,
                            Fragment* fragment, kutlog_error* error) {
  return guarded(error, [&] {
    if (const kutlog_status status =
            Check(error).handle(lobe, "lobe").handle(fragment, "fragment").normalization(
                normalization))
      return status;
    constexpr bool kFast = std::is_same_v<Fragment, kutlog_fast_fragment>;
    const kutlog::Normalization chosen = kutlog::Normalization(normalization);
    const auto& pieces = [&]() -> const auto& {
      if constexpr (kFast) return kutlog::inspect::fast_pieces(lobe->lobe, chosen);
      else return kutlog::inspect::precise_pieces(lobe->lobe, chosen);
    }();
    const kutlog::detail::LobeKernel& kernel =
        kutlog::inspect::kernel(lobe->lobe, kFast ? kutlog::Variant::fast : kutlog::Variant::precise,
                                chosen, kutlog::inspect::Arithmetic::scalar);
    *fragment = {pieces.table.empty() ? nullptr : pieces.table.data(), &kernel,
                 pieces.pieces_per_w, std::uint32_t(pieces.table.size() - 1), lobe->lobe.t_cut()};
    return KUTLOG_OK;
  });
}
template <class Fragment>
float kernel_eval(const Fragment* fragment, float t) {
  if (!fragment || !fragment->kernel) return kNaN;
  return static_cast<const kutlog::detail::LobeKernel*>(fragment->kernel)->evaluate(t);
}

}  // namespace

extern "C" {

kutlog_status kutlog_lobe_create(double n, int k, double Q, kutlog_lobe** lobe,
                                 kutlog_error* error) {
  return create(lobe, error, n, k, Q);
}
void kutlog_lobe_destroy(kutlog_lobe* lobe) { delete lobe; }
double kutlog_lobe_coef_exact(const kutlog_lobe* lobe) {
  return lobe ? lobe->lobe.coef_exact() : std::numeric_limits<double>::quiet_NaN();
}
float kutlog_lobe_t_cut(const kutlog_lobe* lobe) { return lobe ? lobe->lobe.t_cut() : kNaN; }

kutlog_status kutlog_lobe_fragment(const kutlog_lobe* lobe, kutlog_normalization normalization,
                                   kutlog_fragment* fragment, kutlog_error* error) {
  return fill_fragment(lobe, normalization, fragment, error);
}
kutlog_status kutlog_lobe_fast_fragment(const kutlog_lobe* lobe,
                                        kutlog_normalization normalization,
                                        kutlog_fast_fragment* fragment, kutlog_error* error) {
  return fill_fragment(lobe, normalization, fragment, error);
}
float kutlog_fragment_kernel_eval(const kutlog_fragment* fragment, float t) {
  return kernel_eval(fragment, t);
}
float kutlog_fast_fragment_kernel_eval(const kutlog_fast_fragment* fragment, float t) {
  return kernel_eval(fragment, t);
}

float kutlog_lobe_eval(const kutlog_lobe* lobe, float t, kutlog_variant variant,
                       kutlog_normalization normalization) {
  if (!lobe || !valid_enum(variant) || !valid_enum(normalization)) return kNaN;
  return lobe->lobe.eval(t, kutlog::Variant(variant), kutlog::Normalization(normalization));
}
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
  if (!lobe || !valid_enum(variant) || !valid_enum(normalization)) return kNaN;
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
          int(use), 2, "use", "KUTLOG_USE_MICROFACET or KUTLOG_USE_PHONG")) {
    if (sampler) *sampler = nullptr;
    return status;
  }
  return create(sampler, error, n, k, Q, kutlog::LobeUse(use));
}
void kutlog_sampler_destroy(kutlog_sampler* sampler) { delete sampler; }
kutlog_sample kutlog_sampler_sample(const kutlog_sampler* sampler, float u1, float u2) {
  if (!sampler) return {kNaN, kNaN, kNaN, kNaN};
  const kutlog::SampledDirection direction = sampler->sampler.sample(u1, u2);
  return {direction.x, direction.y, direction.z, direction.pdf};
}
kutlog_status kutlog_sampler_sample_array(const kutlog_sampler* sampler, const float* u1,
                                          const float* u2, float* x, float* y, float* z,
                                          float* pdf, std::size_t count, kutlog_error* error) {
  return guarded(error, [&] {
    if (const kutlog_status status = Check(error).handle(sampler, "sampler").arrays(
            count, {{"u1", u1}, {"u2", u2}, {"x", x}, {"y", y}, {"z", z}, {"pdf", pdf}}))
      return status;
    sampler->sampler.sample(u1, u2, {x, y, z, pdf}, count);
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
