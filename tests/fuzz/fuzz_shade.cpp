// libFuzzer target: the stream API of kutlog/shade.hpp on every arch this CPU supports -- every
// overload (SoA vectors, one light and viewer, and cosines), Blinn and Phong, both variants
// and normalizations, with and without a lane mask -- against the scalar reference:
// out = F(t) max(N.L, 0) within the lobe's bound (kutlog/accuracy.hpp) and the float rounding
// of the cosines, NaN in the data gives NaN, L + V = 0 gives 0 (Blinn), unselected lanes keep
// their bits, and nothing outside [0, count) is written.
#include <cmath>
#include <limits>
#include <string>

#include "cosine_error.hpp"
#include "fuzz_support.hpp"
#include "kutlog/shade.hpp"

namespace kutlog::fuzz {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// How far the kernels' float cosines may be from the double ones of the same unit vectors:
// derived in tests/cosine_error.hpp (Blinn 9u, Phong 18.5u, N.L 3.5u, u = 2^-24), which
// tests/test_shade.cpp uses too.
using test::kBlinnCosineError;
using test::kNDotLError;
using test::kPhongCosineError;
// Unit vectors in float are unit within a few roundings; others have no contract but NaN's.
constexpr double kUnitTolerance = 0x1p-20;

struct Vector {
  float x, y, z;
  bool has_nan() const { return std::isnan(x) || std::isnan(y) || std::isnan(z); }
  bool unit() const {
    return std::fabs(double(x) * x + double(y) * y + double(z) * z - 1) <= kUnitTolerance;
  }
  ref::Vec3 exact() const { return {x, y, z}; }
  Vector operator-() const { return {-x, -y, -z}; }
};

using ref::dot;

float component(FuzzedDataProvider& data) {
  static constexpr float kCritical[] = {0.0f, 1.0f, -1.0f, 0x1p-100f, 0.5f};
  return data.ConsumeBool() ? 2 * data.ConsumeProbability<float>() - 1
                            : biased_float(data, kCritical);
}

// A unit vector in float from three fuzzed components (normalized in double), or (0, 0, 1)
// when they give no direction.
Vector unit_vector(FuzzedDataProvider& data) {
  const double x = component(data), y = component(data), z = component(data);
  const double length = std::sqrt(x * x + y * y + z * z);
  if (!(length > 0) || !std::isfinite(length)) return {0, 0, 1};
  return {float(x / length), float(y / length), float(z / length)};
}

// One lane: unit vectors (the contract's case), to_viewer opposite to_light exactly or within
// a few ulps, or any nine floats (only NaN has a contract then).
struct Lane {
  Vector normal, to_light, to_viewer;
};
Lane lane(FuzzedDataProvider& data) {
  switch (data.ConsumeIntegralInRange<int>(0, 3)) {
    case 0: {
      const Vector light = unit_vector(data);
      Vector viewer = -light;
      float* components[] = {&viewer.x, &viewer.y, &viewer.z};
      float& nudged = *components[data.ConsumeIntegralInRange<int>(0, 2)];
      nudged = step_floats(nudged, data.ConsumeIntegralInRange<int>(-3, 3));
      return {unit_vector(data), light, viewer};
    }
    case 1:
      return {{component(data), component(data), component(data)},
              {component(data), component(data), component(data)},
              {component(data), component(data), component(data)}};
    default: return {unit_vector(data), unit_vector(data), unit_vector(data)};
  }
}

std::uint8_t mask_byte(FuzzedDataProvider& data) {
  const std::uint8_t byte = data.ConsumeIntegral<std::uint8_t>();
  return byte < 96 ? 0 : byte < 192 ? 1 : byte < 224 ? 0xff : byte;
}

// Checks one selected lane of the cosines overload: out = F(t) max(n_dot_l, 0).
void check_cosines(const Call& call, std::size_t i, const LobeUnderTest& lobe,
                   const ShadeOptions& options, float t, float n_dot_l, float out) {
  if (std::isnan(t) || std::isnan(n_dot_l)) {
    if (!std::isnan(out)) fail(call, lane_message(i, "%.9g where NaN is due", double(out)));
    return;
  }
  const Range range = lobe_range(lobe, options.variant, options.normalization, t, t);
  const double factor = std::max(0.0, double(n_dot_l));
  if (!product_within(out, range, factor, factor))
    fail(call, lane_message(i, "%.9g, but F(t) is in [%.9g, %.9g] and max(N.L, 0) = %.9g",
                            double(out), range.lo, range.hi, factor));
}

// Checks one selected lane of the vectors overload against the cosines of its vectors.
void check_vectors(const Call& call, std::size_t i, const LobeUnderTest& lobe,
                   const ShadeOptions& options, const Lane& lane, float out) {
  if (lane.normal.has_nan() || lane.to_light.has_nan() || lane.to_viewer.has_nan()) {
    if (!std::isnan(out)) fail(call, lane_message(i, "%.9g where NaN is due", double(out)));
    return;
  }
  if (!lane.normal.unit() || !lane.to_light.unit() || !lane.to_viewer.unit()) return;
  const ref::Vec3 n = lane.normal.exact(), l = lane.to_light.exact(), v = lane.to_viewer.exact();
  const bool blinn = options.reflection == Reflection::blinn;
  // L + V = 0 has no half vector: the contract's 0 (the sum of floats is exact there); where
  // |L + V|^2 underflows (below 2^-126), 0 or any cosine.
  const ref::Vec3 sum{l.x + v.x, l.y + v.y, l.z + v.z};
  const bool opposite = blinn && dot(sum, sum) == 0;
  const bool nearly_opposite = blinn && dot(sum, sum) < 0x1p-126;
  const double t = blinn ? ref::blinn_cosine(n, l, v) : ref::phong_cosine(n, l, v);
  const double n_dot_l = dot(n, l);
  const auto range_over = [&](double t_lo, double t_hi) {
    return lobe_range(lobe, options.variant, options.normalization, t_lo, t_hi);
  };
  const double dt = blinn ? kBlinnCosineError : kPhongCosineError;
  const Range range = opposite          ? range_over(0, 0)
                      : nearly_opposite ? range_over(-1, 2)
                                        : range_over(t - dt, t + dt);
  const double factor_lo = std::max(0.0, n_dot_l - kNDotLError);
  const double factor_hi = std::max(0.0, n_dot_l + kNDotLError);
  if (!product_within(out, range, factor_lo, factor_hi))
    fail(call, lane_message(i, "%.9g, but t = %.17g gives F in [%.9g, %.9g] and N.L = %.17g",
                            double(out), t, range.lo, range.hi, n_dot_l));
}

}  // namespace

// One call of shade, on every arch.
void fuzz_one(FuzzedDataProvider& data) {
  const LobeParameters parameters = lobe_parameters(data);
  ShadeOptions options;
  options.variant = data.ConsumeBool() ? Variant::precise : Variant::fast;
  options.normalization = data.ConsumeBool() ? Normalization::exact_coef : Normalization::none;
  options.reflection = data.ConsumeBool() ? Reflection::blinn : Reflection::phong;
  const bool from_vectors = data.ConsumeBool(), masked = data.ConsumeBool();
  const std::size_t count = lane_count(data);
  const std::size_t in_offset = misalignment(data);
  const std::size_t mask_offset = misalignment(data);
  const std::size_t out_offset = misalignment(data);

  Call call{from_vectors ? "kutlog::shade (vectors)" : "kutlog::shade (cosines)",
            parameters.text() + " variant=" + std::string(variant_name(options.variant)) +
                " normalization=" + std::string(normalization_name(options.normalization)) +
                (options.reflection == Reflection::blinn ? " blinn" : " phong") +
                " offsets in=" + std::to_string(in_offset) + " mask=" +
                std::to_string(mask_offset) + " out=" + std::to_string(out_offset)};
  call.count = count;
  const LobeUnderTest* lobe = lobe_under_test(parameters, call);
  if (!lobe) return;

  std::vector<std::uint8_t> mask_values(masked ? count : 0);
  for (std::uint8_t& byte : mask_values) byte = mask_byte(data);
  const float before_critical[] = {kNaN};
  const std::vector<float> before = biased_floats(data, count, before_critical);
  // The cosines overload's t and n_dot_l, or the nine components of the vectors.
  std::vector<Lane> lanes;
  std::vector<std::vector<float>> columns(from_vectors ? 9 : 2, std::vector<float>(count));
  const float critical_t[] = {1.0f, 0.0f, float(lobe->cut)}, critical_n_dot_l[] = {0.0f, 1.0f};
  for (std::size_t i = 0; i < count; ++i) {
    if (!from_vectors) {
      columns[0][i] = biased_float(data, critical_t);
      columns[1][i] = biased_float(data, critical_n_dot_l);
      continue;
    }
    lanes.push_back(lane(data));
    const Lane& l = lanes.back();
    const float components[] = {l.normal.x,   l.normal.y,   l.normal.z,
                                l.to_light.x, l.to_light.y, l.to_light.z,
                                l.to_viewer.x, l.to_viewer.y, l.to_viewer.z};
    for (int c = 0; c < 9; ++c) columns[c][i] = components[c];
  }
  std::vector<InputArray<float>> inputs;
  for (const std::vector<float>& column : columns) inputs.emplace_back(column, in_offset);
  const InputArray<std::uint8_t> mask(mask_values, mask_offset);
  call.mask = masked ? mask.data() : nullptr;
  static const char* const kVectorNames[] = {"nx", "ny", "nz", "lx", "ly", "lz", "vx", "vy", "vz"};
  static const char* const kCosineNames[] = {"t", "n_dot_l"};

  for_each_supported_arch([&](Arch) {
    GuardedOutput out(count, out_offset);
    std::copy(before.begin(), before.end(), out.data());
    call.arrays.clear();
    for (std::size_t c = 0; c < inputs.size(); ++c)
      call.arrays.push_back({from_vectors ? kVectorNames[c] : kCosineNames[c], inputs[c].data()});
    call.arrays.push_back({"before", before.data()});
    call.arrays.push_back({"out", out.data()});
    if (from_vectors)
      shade(lobe->lobe, {inputs[0].data(), inputs[1].data(), inputs[2].data()},
            {inputs[3].data(), inputs[4].data(), inputs[5].data()},
            {inputs[6].data(), inputs[7].data(), inputs[8].data()}, out.data(), count,
            call.mask, options);
    else
      shade(lobe->lobe, inputs[0].data(), inputs[1].data(), out.data(), count, call.mask, options);
    check_guards(out, call);
    check_unselected_lanes_kept(out.values(), before, call.mask, call);
    for (std::size_t i = 0; i < count; ++i) {
      if (call.mask && !call.mask[i]) continue;
      if (from_vectors) check_vectors(call, i, *lobe, options, lanes[i], out.data()[i]);
      else check_cosines(call, i, *lobe, options, columns[0][i], columns[1][i], out.data()[i]);
    }
    if (!from_vectors || count == 0) return;
    // The single-vector overload on the same normals, lane 0's light and viewer for every lane
    // (its Blinn half vector, formed once, is within the same window).
    const Lane& first = lanes[0];
    GuardedOutput single(count, out_offset);
    std::copy(before.begin(), before.end(), single.data());
    call.arrays.back() = {"out (lane 0's light and viewer as Direction)", single.data()};
    shade(lobe->lobe, {inputs[0].data(), inputs[1].data(), inputs[2].data()},
          Direction{first.to_light.x, first.to_light.y, first.to_light.z},
          Direction{first.to_viewer.x, first.to_viewer.y, first.to_viewer.z}, single.data(),
          count, call.mask, options);
    check_guards(single, call);
    check_unselected_lanes_kept(single.values(), before, call.mask, call);
    for (std::size_t i = 0; i < count; ++i) {
      if (call.mask && !call.mask[i]) continue;
      check_vectors(call, i, *lobe, options, {lanes[i].normal, first.to_light, first.to_viewer},
                    single.data()[i]);
    }
  });
}

}  // namespace kutlog::fuzz
