// libFuzzer target: the lobe kernels of kutlog/lobe.hpp on every arch this CPU supports --
// Lobe::eval (both variants, both normalizations), PerLaneLobe::eval (arrays and scalar),
// PerLanePowerPoly::eval and the baselines blinn_phong_xsimd, blinn_phong_u10 and schlick --
// against the scalar reference (kutlog/reference.hpp) within the bounds of
// kutlog/accuracy.hpp, with the data rule of every lobe (t >= 1 gives the peak, t <= 0 and t
// at or below the cut give 0, NaN gives NaN), the constructors' validation, any count and
// misalignment, in place, and nothing written outside the output.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include "common/lobe_errors.hpp"
#include "common/ulp.hpp"
#include "fuzz_support.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/baselines.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"

namespace kutlog::fuzz {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void fuzz_lobe(FuzzedDataProvider& data) {
  const LobeParameters parameters = lobe_parameters(data);
  const Variant variant = data.ConsumeBool() ? Variant::precise : Variant::fast;
  const Normalization normalization =
      data.ConsumeBool() ? Normalization::none : Normalization::exact_coef;
  Call call{"kutlog::Lobe::eval", parameters.text() + " variant=" +
                                      std::string(variant_name(variant)) + " normalization=" +
                                      std::string(normalization_name(normalization))};
  const LobeUnderTest* lobe = lobe_under_test(parameters, call);
  if (!lobe) return;
  const float critical_points[] = {1.0f, 0.0f, float(lobe->cut),
                                   float(std::cos(lobe->reference.anchor_angle()))};
  const double scale =
      normalization == Normalization::exact_coef ? lobe->lobe.coef_exact() : 1.0;
  const LobeBound& bound = kLobeBounds[variant == Variant::precise ? 0 : 1];
  run_on_every_arch(
      array_arguments(data, critical_points), "t", call,
      [&](const float* t, float* out) {
        lobe->lobe.eval(t, out, call.count, variant, normalization);
      },
      [&](const Call& call, std::size_t i, float t, float out) {
        if (std::isnan(t)) {
          if (!std::isnan(out)) fail(call, lane_message(i, "%.9g where NaN is due", double(out)));
          return;
        }
        const Range range = lobe_range(*lobe, variant, normalization, t, t);
        if (!(range.lo <= out && out <= range.hi))
          fail(call, lane_message(i, "%.9g outside [%.9g, %.9g]", double(out), range.lo, range.hi));
        const double expected = lobe->reference.eval(t);
        if (bound.max_epicenter_ulp() > 0 && expected >= 0.6 && t < 1) {
          const double ulps = tools::ulp_error(out, scale * expected);
          if (!(ulps <= bound.max_epicenter_ulp()))
            fail(call, lane_message(i, "%g ulp from F = %.17g in the epicenter, bound %g", ulps,
                                    expected, bound.max_epicenter_ulp()));
        }
      });
}

// The documented domain of PerLaneLobe(n_min, n_max, k, Q) (kutlog/lobe.hpp).
struct PerLaneParameters {
  int k;
  double Q, n_min, n_max;
  bool valid() const {
    return LobeParameters{n_min, k, Q}.valid() && LobeParameters{n_max, k, Q}.valid() &&
           n_min >= k && n_max >= n_min && n_max <= std::numeric_limits<float>::max();
  }
};

// PerLanePowerPoly(n_min, n_max, variant, normalization) on a PerLaneLobe's lanes: within
// PerLaneLobe's bounds of scale(n) t^n (scale 1 or the Blinn-Phong coef), 0 <= out <= the
// peak within that bound, the data rule; the documented domain n_min >= 44 (fast 36).
void fuzz_per_lane_power_poly(double n_min, double n_max, Variant variant,
                              Normalization normalization, const ArrayArguments& arguments,
                              const std::vector<float>& n_values, const float* n) {
  char text[200];
  std::snprintf(text, sizeof text, "n_min=%.17g n_max=%.17g variant=%s normalization=%s", n_min,
                n_max, variant_name(variant).data(), normalization_name(normalization).data());
  Call call{"kutlog::PerLanePowerPoly::eval", text};
  const bool valid = n_min >= (variant == Variant::fast ? 36 : 44);  // n_max checked above
  static Cache<std::tuple<double, double, Variant, Normalization>, PerLanePowerPoly> powers;
  const PerLanePowerPoly* power = nullptr;
  check_constructor(
      valid,
      [&] {
        const auto make = [&] { return PerLanePowerPoly(n_min, n_max, variant, normalization); };
        if (!valid) {
          make();  // not cached: it must throw at once
          return;
        }
        power = &powers.get({n_min, n_max, variant, normalization}, make);
      },
      call);
  if (!power) return;
  call.arrays = {{"n", n}};
  const double bound = kLobeBounds[variant == Variant::fast ? 3 : 2].max_abs_error();
  run_on_every_arch(
      arguments, "t", call, [&](const float* t, float* out) { power->eval(t, n, out, call.count); },
      [&](const Call& call, std::size_t i, float t, float out) {
        if (std::isnan(t) || std::isnan(n_values[i])) {
          if (!std::isnan(out)) fail(call, lane_message(i, "%.9g where NaN is due", double(out)));
          return;
        }
        if (t <= 0 && out != 0) fail(call, lane_message(i, "%.9g where 0 is due", double(out)));
        const double lane_n = std::clamp(double(n_values[i]), n_min, n_max);
        const double scale = normalization == Normalization::none
                                 ? 1.0
                                 : ref::blinn_phong_exact_coef(lane_n);
        const double exact = t <= 0 ? 0.0 : scale * std::pow(std::min(1.0, double(t)), lane_n);
        const double error = std::fabs(out - exact) / scale;
        if (!(error <= bound))
          fail(call, lane_message(i, "%.9g against %.17g: error %.3g of the peak (n = %.9g), "
                                     "bound %.3g", double(out), exact, error, lane_n, bound));
        if (!(out >= 0 && out <= scale * (1 + bound)))
          fail(call, lane_message(i, "%.9g outside [0, %.9g] (n = %.9g)", double(out),
                                  scale * (1 + bound), lane_n));
      });
}

void fuzz_per_lane_lobe(FuzzedDataProvider& data) {
  const LobeParameters base = lobe_parameters(data);
  const double ratio = data.PickValueInArray({1.0, 1.5, 2.0, 10.0, 100.0, 1e4, 0.5});
  const PerLaneParameters parameters{base.k, base.Q, base.n, base.n * ratio};
  const Normalization normalization =
      data.ConsumeBool() ? Normalization::none : Normalization::exact_coef;
  char text[200];
  std::snprintf(text, sizeof text, "k=%d Q=%.17g n_min=%.17g n_max=%.17g normalization=%s",
                parameters.k, parameters.Q, parameters.n_min, parameters.n_max,
                normalization_name(normalization).data());
  Call call{"kutlog::PerLaneLobe::eval", text};
  static Cache<std::tuple<int, double, double, double>, PerLaneLobe> lobes;
  const PerLaneLobe* lobe = nullptr;
  check_constructor(
      parameters.valid(),
      [&] {
        const auto make = [&] {
          return PerLaneLobe(parameters.n_min, parameters.n_max, parameters.k, parameters.Q);
        };
        if (!parameters.valid()) {
          make();  // not cached: it must throw at once
          return;
        }
        try {
          lobe = &lobes.get({parameters.k, parameters.Q, parameters.n_min, parameters.n_max}, make);
        } catch (const std::invalid_argument& error) {
          // Documented: a range of n too wide for one fit is refused (kutlog/lobe.hpp).
          if (std::string_view(error.what()).find("too wide") == std::string_view::npos) throw;
        }
      },
      call);
  if (!lobe) return;

  const float critical_t[] = {1.0f, 0.0f, 1.0f - inspect::kernel(*lobe).w_limit};
  const float critical_n[] = {float(parameters.n_min), float(parameters.n_max),
                              float(parameters.k)};
  const ArrayArguments arguments = array_arguments(data, critical_t);
  std::vector<float> n_values(arguments.count);
  for (float& n : n_values)
    n = data.ConsumeBool()
            ? float(parameters.n_min * std::pow(parameters.n_max / parameters.n_min,
                                                data.ConsumeProbability<double>()))
            : biased_float(data, critical_n);
  const InputArray<float> n(n_values, misalignment(data));
  call.arrays = {{"n", n.data()}};
  // Consumed last: the regression inputs written before the fast variant replay as they were.
  const Variant variant = data.ConsumeBool() ? Variant::fast : Variant::precise;
  call.parameters += variant == Variant::fast ? " variant=fast" : " variant=precise";
  const double bound = kLobeBounds[variant == Variant::fast ? 3 : 2].max_abs_error();
  run_on_every_arch(
      arguments, "t", call,
      [&](const float* t, float* out) {
        lobe->eval(t, n.data(), out, call.count, variant, normalization);
      },
      [&](const Call& call, std::size_t i, float t, float array_out) {
        // The array's lane, then the scalar path's eval(t, n) on the same lane.
        const float outs[] = {array_out, lobe->eval(t, n_values[i], variant, normalization)};
        for (int scalar = 0; scalar < 2; ++scalar) {
          const float out = outs[scalar];
          const char* path = scalar ? "scalar eval: " : "";
          if (std::isnan(t) || std::isnan(n_values[i])) {
            if (!std::isnan(out))
              fail(call, lane_message(i, "%s%.9g where NaN is due", path, double(out)));
            continue;
          }
          if (t <= 0 && out != 0)
            fail(call, lane_message(i, "%s%.9g where 0 is due", path, double(out)));
          if (t >= 1 && normalization == Normalization::none && out != 1)
            fail(call, lane_message(i, "%s%.9g where 1 is due", path, double(out)));
          const double lane_n = std::clamp(double(n_values[i]), parameters.n_min, parameters.n_max);
          const ref::KutlogLobe reference(lane_n, parameters.k, parameters.Q);
          const double scale = normalization == Normalization::none ? 1.0 : reference.coef_exact();
          const double error = tools::lobe_abs_error(out, scale, reference.eval(t));
          if (!(error <= bound))
            fail(call, lane_message(i, "%serror %.3g relative to the peak (n = %.9g), bound %.3g",
                                    path, error, lane_n, bound));
          // The hard contract against the reference's peak: 1, or coef within the variant's
          // peak bound.
          const double peak = normalization == Normalization::none
                                  ? 1.0
                                  : scale * (1 + tools::per_lane_peak_bound(variant));
          if (!(out >= 0 && out <= peak))
            fail(call, lane_message(i, "%s%.9g outside [0, %.9g] (n = %.9g)", path, double(out),
                                    peak, lane_n));
        }
      });
  // The per-lane peer on the same lanes, chosen last: the inputs above replay as they were.
  if (data.ConsumeBool())
    fuzz_per_lane_power_poly(parameters.n_min, parameters.n_max, variant, normalization,
                             arguments, n_values, n.data());
}

// blinn_phong_xsimd, blinn_phong_u10 and schlick: out = scale * F(t) with the reference's F.
void fuzz_baseline(FuzzedDataProvider& data, int which) {
  float n = float(exponent(data));
  if (!(n > 0 && std::isfinite(n))) n = 1;  // the exponent's domain (kutlog/reference.hpp)
  const bool coef = which != 2 && data.ConsumeBool();
  const float scale = coef ? float(ref::blinn_phong_exact_coef(n)) : 1.0f;
  const char* names[] = {"kutlog::blinn_phong_xsimd", "kutlog::blinn_phong_u10", "kutlog::schlick"};
  char text[120];
  std::snprintf(text, sizeof text, "n=%.9g scale=%.9g", double(n), double(scale));
  Call call{names[which], text};
  const float critical_points[] = {1.0f, 0.0f, std::pow(0.5f, 1 / n)};
  const double pow_ulp = find_accuracy_bound("pow")->max_ulp();
  run_on_every_arch(
      array_arguments(data, critical_points), "t", call,
      [&](const float* t, float* out) {
        if (which == 0) blinn_phong_xsimd(t, out, call.count, n, scale);
        if (which == 1) blinn_phong_u10(t, out, call.count, n, scale);
        if (which == 2) schlick(t, out, call.count, n);
      },
      [&](const Call& call, std::size_t i, float t, float out) {
        const double expected = std::isnan(t) ? kNaN
                                : which == 2  ? ref::schlick(t, n)
                                              : scale * ref::blinn_phong(t, n);
        if (std::isnan(expected) || t <= 0 || t >= 1) {  // the data rule, exactly
          const bool same = std::isnan(expected) ? std::isnan(out) : double(out) == expected;
          if (!same) fail(call, lane_message(i, "%.9g where %.9g is due", double(out), expected));
          return;
        }
        if (which == 0) {
          if (!(std::fabs(out - expected) <= kBlinnPhongXsimdMaxAbsError * scale))
            fail(call, lane_message(i, "%.9g, %.3g from %.9g", double(out),
                                    std::fabs(out - expected), expected));
          return;
        }
        // pow_u10's bound, plus the rounding of the product by scale (whose relative size is
        // at most twice pow's in ulps) and pow's absolute 2^-150 at subnormal results.
        double ulps = which == 2 ? kSchlickMaxUlp : scale == 1 ? pow_ulp : 2 * pow_ulp + 0.5;
        if (which == 1 && scale != 1)
          ulps += scale * 0x1p-150 / detail::ulp_of_float(expected);
        const double error = tools::ulp_error(out, expected);
        if (!(error <= ulps))
          fail(call, lane_message(i, "%g ulp from %.17g, bound %g", error, expected, ulps));
      });
}

}  // namespace

// One call of a lobe kernel or baseline, on every arch.
void fuzz_one(FuzzedDataProvider& data) {
  const int api = data.ConsumeIntegralInRange<int>(0, 4);
  if (api == 0) fuzz_lobe(data);
  else if (api == 1) fuzz_per_lane_lobe(data);
  else fuzz_baseline(data, api - 2);
}

}  // namespace kutlog::fuzz
