#include "fuzz_support.hpp"

#include <bit>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "kutlog/accuracy.hpp"
#include "kutlog/inspect.hpp"

namespace kutlog::fuzz {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

float with_sign(float x, bool negative) { return negative ? -x : x; }
bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

}  // namespace

float step_floats(float x, int steps) {
  for (; steps > 0; --steps) x = std::nextafter(x, kInf);
  for (; steps < 0; ++steps) x = std::nextafter(x, -kInf);
  return x;
}

float biased_float(FuzzedDataProvider& data, std::span<const float> critical_points) {
  enum Kind : std::uint8_t {
    kAnyBits, kNaN, kInfinity, kZero, kSubnormal, kOne, kNearOne, kNearCritical,
    kNearCritical2, kUnitInterval, kExtremeNormal, kAnyFinite, kKinds
  };
  const auto kind = Kind(data.ConsumeIntegral<std::uint8_t>() % kKinds);
  const bool negative = data.ConsumeBool();
  const auto steps = [&] { return data.ConsumeIntegralInRange<int>(-8, 8); };
  switch (kind) {
    case kAnyBits: return std::bit_cast<float>(data.ConsumeIntegral<std::uint32_t>());
    case kNaN: {
      // Any nonzero payload: quiet (bit 22 set) or signalling.
      const std::uint32_t payload = data.ConsumeIntegralInRange<std::uint32_t>(1, 0x7fffff);
      return std::bit_cast<float>((negative ? 0xff800000u : 0x7f800000u) | payload);
    }
    case kInfinity: return with_sign(kInf, negative);
    case kZero: return with_sign(0.0f, negative);
    case kSubnormal: {
      const std::uint32_t bits = data.ConsumeIntegralInRange<std::uint32_t>(1, 0x7fffff);
      return with_sign(std::bit_cast<float>(bits), negative);
    }
    case kOne: return with_sign(1.0f, negative);
    case kNearOne: return with_sign(step_floats(1.0f, steps()), negative);
    case kNearCritical:
    case kNearCritical2:  // twice as likely: the caller knows where its kernels turn
      if (critical_points.empty()) return step_floats(0.5f, steps());
      return step_floats(
          critical_points[data.ConsumeIntegralInRange<std::size_t>(0, critical_points.size() - 1)],
          steps());
    case kUnitInterval: return with_sign(data.ConsumeProbability<float>(), negative);
    case kExtremeNormal:
      return with_sign(step_floats(data.ConsumeBool() ? std::numeric_limits<float>::min()
                                                      : std::numeric_limits<float>::max(),
                                   steps()),
                       negative);
    case kAnyFinite:
    case kKinds: break;
  }
  return data.ConsumeFloatingPoint<float>();
}

std::vector<float> biased_floats(FuzzedDataProvider& data, std::size_t count,
                                 std::span<const float> critical_points) {
  std::vector<float> values(count);
  for (float& value : values) value = biased_float(data, critical_points);
  return values;
}

// ---- Reports -------------------------------------------------------------------------------

std::string lane_message(std::size_t lane, const char* format, ...) {
  char text[512];
  std::va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(text, sizeof text, format, arguments);
  va_end(arguments);
  return "lane " + std::to_string(lane) + ": " + text;
}

void fail(const Call& call, const std::string& violation) {
  std::fprintf(stderr, "\n==== kutlog fuzz: contract violated ====\n%s\n", violation.c_str());
  std::fprintf(stderr, "call: %s on arch %s, count %zu\n", call.api.c_str(),
               std::string(arch_name(active_arch())).c_str(), call.count);
  if (!call.parameters.empty()) std::fprintf(stderr, "parameters: %s\n", call.parameters.c_str());
  for (std::size_t lane = 0; lane < call.count; ++lane) {
    std::fprintf(stderr, "  [%3zu]", lane);
    for (const auto& [name, values] : call.arrays)
      std::fprintf(stderr, " %s=%.9g (0x%08x)", name.c_str(), double(values[lane]),
                   std::bit_cast<std::uint32_t>(values[lane]));
    if (call.mask) std::fprintf(stderr, " mask=%u", unsigned(call.mask[lane]));
    std::fprintf(stderr, "\n");
  }
  std::fflush(stderr);
  std::abort();
}

void check_guards(const GuardedOutput& out, const Call& call) {
  std::ptrdiff_t index;
  if (out.changed_guard_byte(index))
    fail(call, "wrote outside [0, count): byte " + std::to_string(index) +
                   " relative to the first output byte");
}

void check_unselected_lanes_kept(std::span<const float> out, std::span<const float> before,
                                 const std::uint8_t* mask, const Call& call) {
  for (std::size_t lane = 0; mask && lane < out.size(); ++lane)
    if (!mask[lane] && !same_bits(out[lane], before[lane]))
      fail(call, lane_message(lane, "masked off, but its value changed from %a to %a",
                              double(before[lane]), double(out[lane])));
}

void check_same_bits(std::span<const float> in_place, std::span<const float> out_of_place,
                     const Call& call) {
  for (std::size_t lane = 0; lane < in_place.size(); ++lane)
    if (!same_bits(in_place[lane], out_of_place[lane]))
      fail(call, lane_message(lane, "in place %a, out of place %a", double(in_place[lane]),
                              double(out_of_place[lane])));
}

// ---- Archs ---------------------------------------------------------------------------------

void for_each_supported_arch(const std::function<void(Arch)>& body) {
  static const std::vector<Arch> archs = supported_archs();
  for (Arch arch : archs) {
    const inspect::ScopedArch forced(arch);
    body(arch);
  }
}

// ---- Calls of the form f(in, ..., out, count) ----------------------------------------------

std::size_t lane_count(FuzzedDataProvider& data) {
  return data.ConsumeIntegralInRange<std::size_t>(0, kMaxCount);
}
std::size_t misalignment(FuzzedDataProvider& data) {
  return data.ConsumeIntegralInRange<std::size_t>(0, kMaxOffset);
}

ArrayArguments array_arguments(FuzzedDataProvider& data, std::span<const float> critical_points) {
  ArrayArguments arguments;
  arguments.count = lane_count(data);
  arguments.in_offset = misalignment(data);
  arguments.out_offset = misalignment(data);
  arguments.in_place = data.ConsumeBool();
  arguments.in = biased_floats(data, arguments.count, critical_points);
  return arguments;
}

// ---- Lobes ---------------------------------------------------------------------------------

namespace {
// Typical and extreme values; the tests' grid is n in {k+1, 10, ..., 10000}, k in 1..5,
// Q in {0.1, 0.5, 0.9}.
constexpr double kExponents[] = {1e-10, 1e-3, 0.1, 0.5, 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10,
                                 20, 50, 65, 100, 300, 1000, 2000, 5000, 10000, 1e5, 1e6,
                                 1e8, 1e12, 1e16, 1e20, 1e30, 1e38, 1e100};
constexpr double kAnchors[] = {1e-300, 1e-6, 0.01, 0.1, 0.2, 0.3, 0.4, 0.45,
                               0.5,    0.6,  0.7,  0.9, 0.99, 0.999999, 0.3333333333333333,
                               0x1.fffffffffffffp-1};  // the double below 1

double raw_double(FuzzedDataProvider& data) {
  return std::bit_cast<double>(data.ConsumeIntegral<std::uint64_t>());
}
}  // namespace

bool LobeParameters::valid() const {
  return std::isfinite(n) && n > 0 && k >= 1 && k <= ref::kMaxK && std::isfinite(Q) && Q > 0 &&
         Q < 1;
}

bool LobeParameters::lobe_valid() const {
  return valid() && ref::coef_exact(n, k, Q) <= std::numeric_limits<float>::max();
}

std::string LobeParameters::text() const {
  char text[160];
  std::snprintf(text, sizeof text, "n=%.17g (%a) k=%d Q=%.17g (%a)", n, n, k, Q, Q);
  return text;
}

LobeParameters lobe_parameters(FuzzedDataProvider& data) {
  const std::uint8_t mode = data.ConsumeIntegral<std::uint8_t>();
  const std::uint8_t k_choice = data.ConsumeIntegral<std::uint8_t>();
  LobeParameters parameters{data.PickValueInArray(kExponents),
                            1 + k_choice % (k_choice < 192 ? 8 : ref::kMaxK),
                            data.PickValueInArray(kAnchors)};
  if (mode < 16) return {raw_double(data), data.ConsumeIntegral<int>(), raw_double(data)};
  if (mode < 32) parameters.n = raw_double(data);
  else if (mode < 40) parameters.Q = raw_double(data);
  return parameters;
}

double exponent(FuzzedDataProvider& data) {
  if (data.ConsumeIntegral<std::uint8_t>() >= 32) return data.PickValueInArray(kExponents);
  const double raw = std::fabs(raw_double(data));
  return std::isfinite(raw) && raw > 0 ? raw : 1.0;
}

LobeUnderTest::LobeUnderTest(const LobeParameters& parameters)
    : lobe(parameters.n, parameters.k, parameters.Q),
      reference(parameters.n, parameters.k, parameters.Q),
      cut(lobe.cutoff_angle() >= ref::pi / 2 ? 0.0 : std::cos(lobe.cutoff_angle())) {}

void check_constructor(bool valid, const std::function<void()>& construct, const Call& call) {
  try {
    construct();
  } catch (const std::invalid_argument& error) {
    if (valid) fail(call, std::string("invalid_argument for valid parameters: ") + error.what());
    return;
  } catch (const std::exception& error) {
    fail(call, std::string("threw something else than std::invalid_argument: ") + error.what());
  } catch (...) {
    fail(call, "threw something else than std::invalid_argument");
  }
  if (!valid) fail(call, "accepted parameters outside the documented domain");
}

const LobeUnderTest* lobe_under_test(const LobeParameters& parameters, const Call& call) {
  static Cache<std::tuple<double, int, double>, LobeUnderTest> lobes;
  const LobeUnderTest* found = nullptr;
  check_constructor(
      parameters.lobe_valid(),
      [&] {
        if (!parameters.lobe_valid()) {  // not cached: it must throw at once
          const Lobe rejected(parameters.n, parameters.k, parameters.Q);
          return;
        }
        found = &lobes.get({parameters.n, parameters.k, parameters.Q},
                           [&] { return LobeUnderTest(parameters); });
      },
      call);
  return found;
}

Range lobe_range(const LobeUnderTest& lobe, Variant variant, Normalization normalization,
                 double t_lo, double t_hi) {
  const double scale = normalization == Normalization::exact_coef ? lobe.lobe.coef_exact() : 1.0;
  const double bound = kLobeBounds[variant == Variant::precise ? 0 : 1].max_abs_error();
  const double peak = double(float(scale));
  // The smooth part between the cut and 1, where F is within the bound.
  const auto smooth = [&](double t) { return lobe.reference.eval(t) * scale; };
  double lo, hi;
  if (t_lo >= 1) lo = peak;
  else if (t_lo <= lobe.cut) lo = t_hi > lobe.cut ? -bound * scale : 0.0;
  else lo = smooth(t_lo) - bound * scale;
  if (t_hi >= 1) hi = t_lo < 1 ? std::max(peak, (1 + bound) * scale) : peak;
  else if (t_hi <= lobe.cut) hi = 0.0;  // the cut may round to 1 in double: t = 1 first
  else hi = smooth(t_hi) + bound * scale;
  // The hard contract: 0 <= out <= peak.
  return {std::max(lo, 0.0), std::min(hi, peak)};
}

bool product_within(float out, Range lobe, double factor_lo, double factor_hi) {
  // No information: an unbounded range.
  if (lobe.lo == -INFINITY && lobe.hi == INFINITY) return true;
  if (std::isinf(factor_hi)) {
    // value * inf: inf for a positive value, NaN for 0, -inf for a negative one.
    if (std::isnan(out)) return lobe.lo <= 0 && lobe.hi >= 0;
    return std::isinf(out) && (out > 0 ? lobe.hi > 0 : lobe.lo < 0);
  }
  // The extremes of value * factor; inf * 0 is NaN.
  double lo = INFINITY, hi = -INFINITY;
  bool nan_possible = false;
  for (double value : {lobe.lo, lobe.hi})
    for (double factor : {factor_lo, factor_hi}) {
      const double product = value * factor;
      if (std::isnan(product)) nan_possible = true;
      else lo = std::min(lo, product), hi = std::max(hi, product);
    }
  if (std::isnan(out)) return nan_possible;
  // One float rounding: half an ulp relative, or half the smallest subnormal absolute.
  constexpr double kRounding = 0x1p-24, kTiny = 0x1p-150;
  const double lo_rounded = lo - std::fabs(lo) * kRounding - kTiny;
  const double hi_rounded = hi + std::fabs(hi) * kRounding + kTiny;
  // Rounding to nearest gives inf from 2^128 (1 - 2^-25) on.
  constexpr double kOverflow = 0x1.ffffffp127;
  if (std::isinf(out)) return out > 0 ? hi_rounded >= kOverflow : lo_rounded <= -kOverflow;
  return lo_rounded <= out && out <= hi_rounded;
}

}  // namespace kutlog::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  kutlog::fuzz::fuzz_one(data);
  return 0;
}
