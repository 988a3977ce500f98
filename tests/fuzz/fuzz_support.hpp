// Shared by kutlog's libFuzzer targets (tests/fuzz/fuzz_*.cpp): inputs decoded from the
// fuzzer's bytes with a bias to the values kernels get wrong, output arrays between guard
// zones, the loop over archs, lobes cached by their parameters, the contract of a lobe kernel
// as a range of allowed values, and the report of a violation.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/guarded_output.hpp"
#include "common/names.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"

namespace kutlog::fuzz {

// Outputs between guard zones: tools/common/guarded_output.hpp, shared with the tests.
using tools::GuardedOutput;

// Each target defines it: one input, decoded from the fuzzer's bytes, on every arch.
// fuzz_support.cpp has libFuzzer's entry point, which calls it.
void fuzz_one(FuzzedDataProvider& data);

// ---- Inputs --------------------------------------------------------------------------------

inline constexpr std::size_t kMaxCount = 300;  // several batches of every arch, and a tail
inline constexpr std::size_t kMaxOffset = 15;  // in floats: every misalignment within 64 bytes

// A float where kernels break: NaN (any payload and sign, quiet or signalling), +-inf, +-0,
// subnormals, exactly +-1, a few ulps either side of +-1, of the smallest and largest normals
// and of the caller's critical points, values in [-1, 1], any finite value, any bit pattern.
float biased_float(FuzzedDataProvider& data, std::span<const float> critical_points = {});
std::vector<float> biased_floats(FuzzedDataProvider& data, std::size_t count,
                                 std::span<const float> critical_points = {});
// x moved by `steps` floats (negative: down), through +-0 and up to +-inf.
float step_floats(float x, int steps);

// `values` at a misalignment of `offset` elements, ending where its heap block ends, so that
// ASan reports any read past the last value.
template <class T>
class InputArray {
 public:
  InputArray(std::span<const T> values, std::size_t offset)
      : block_(offset + values.size()), offset_(offset) {
    std::copy(values.begin(), values.end(), block_.begin() + std::ptrdiff_t(offset));
  }
  const T* data() const { return block_.data() + offset_; }

 private:
  std::vector<T> block_;
  std::size_t offset_;
};

// ---- Reports -------------------------------------------------------------------------------

// A call under test, for the report of a violation: the API and its parameters, and the
// arrays of the call (inputs and output), printed lane by lane.
struct Call {
  Call(std::string api_name, std::string parameter_text = {})
      : api(std::move(api_name)), parameters(std::move(parameter_text)) {}
  std::string api;
  std::string parameters;
  std::size_t count = 0;
  std::vector<std::pair<std::string, const float*>> arrays;
  const std::uint8_t* mask = nullptr;
};

// Prints the violation, the arch in use and the call, then aborts: libFuzzer saves the input.
[[noreturn]] void fail(const Call& call, const std::string& violation);
// "lane 3: " and the printf-formatted rest, for fail().
std::string lane_message(std::size_t lane, const char* format, ...)
    __attribute__((format(printf, 2, 3)));

// fail() unless nothing outside [0, count) of `out` changed.
void check_guards(const GuardedOutput& out, const Call& call);
// fail() unless in place gave the bits of out of place.
void check_same_bits(std::span<const float> in_place, std::span<const float> out_of_place,
                     const Call& call);
// fail() unless every lane of `out` that `mask` leaves unselected kept the bits of `before`.
void check_unselected_lanes_kept(std::span<const float> out, std::span<const float> before,
                                 const std::uint8_t* mask, const Call& call);

// ---- Archs ---------------------------------------------------------------------------------

// Runs body(arch) once per arch this CPU supports, with that arch forced.
void for_each_supported_arch(const std::function<void(Arch)>& body);

// ---- Calls of the form f(in, ..., out, count) ----------------------------------------------

std::size_t lane_count(FuzzedDataProvider& data);    // in [0, kMaxCount]
std::size_t misalignment(FuzzedDataProvider& data);  // in floats, in [0, kMaxOffset]

// The input array and the output's place, and whether to call in place too (out == in, which
// every such function of kutlog allows).
struct ArrayArguments {
  std::size_t count, in_offset, out_offset;
  bool in_place;
  std::vector<float> in;
};
ArrayArguments array_arguments(FuzzedDataProvider& data, std::span<const float> critical_points);

// Runs kernel(in, out) on every supported arch, out of place and, if asked, in place (which
// must give the same bits), checking the guards and then check(call, lane, in, out) for every
// lane. Reports name the input `in_name`, after any arrays call.arrays lists already.
template <class Kernel, class Check>
void run_on_every_arch(const ArrayArguments& arguments, const char* in_name, Call& call,
                       const Kernel& kernel, const Check& check) {
  const InputArray<float> in(arguments.in, arguments.in_offset);
  const std::size_t count = arguments.count;
  call.count = count;
  call.parameters += std::string(arguments.in_place ? " in place" : "") + " offsets " + in_name +
                     "=" + std::to_string(arguments.in_offset) + " out=" +
                     std::to_string(arguments.out_offset);
  const std::size_t other_arrays = call.arrays.size();
  for_each_supported_arch([&](Arch) {
    GuardedOutput out(count, arguments.out_offset);
    call.arrays.resize(other_arrays);
    call.arrays.push_back({in_name, in.data()});
    call.arrays.push_back({"out", out.data()});
    kernel(in.data(), out.data());
    check_guards(out, call);
    for (std::size_t i = 0; i < count; ++i) check(call, i, arguments.in[i], out.data()[i]);
    if (!arguments.in_place) return;
    GuardedOutput same(count, arguments.out_offset);
    std::copy(arguments.in.begin(), arguments.in.end(), same.data());
    kernel(same.data(), same.data());
    check_guards(same, call);
    check_same_bits(same.values(), out.values(), call);
  });
}

// ---- Lobes ---------------------------------------------------------------------------------

struct LobeParameters {
  double n;
  int k;
  double Q;
  // Inside the documented domain (kutlog/reference.hpp): n finite and > 0, k in [1, 64],
  // Q finite and in (0, 1).
  bool valid() const;
  // Inside Lobe's (kutlog/lobe.hpp): valid() and the exact coef at most FLT_MAX.
  bool lobe_valid() const;
  std::string text() const;
};
// Mostly from tables of typical and extreme values (few distinct lobes, each built once);
// one time in eight, any bits (invalid parameters included).
LobeParameters lobe_parameters(FuzzedDataProvider& data);
// An exponent for the baselines: from the same tables, or any positive finite double.
double exponent(FuzzedDataProvider& data);

// Values built once per key: a lobe's setup takes milliseconds (more under ASan), the calls
// fuzzed take microseconds. It forgets everything when full.
template <class Key, class Value>
class Cache {
 public:
  template <class Make>
  const Value& get(const Key& key, const Make& make) {
    if (auto found = values_.find(key); found != values_.end()) return found->second;
    if (values_.size() >= kCapacity) values_.clear();
    return values_.emplace(key, make()).first->second;
  }

 private:
  static constexpr std::size_t kCapacity = 512;
  std::map<Key, Value> values_;
};

// Runs construct() and checks a constructor's contract: std::invalid_argument exactly when
// `valid` is false, and nothing else.
void check_constructor(bool valid, const std::function<void()>& construct, const Call& call);

// A Lobe with its reference.
struct LobeUnderTest {
  LobeUnderTest(const LobeParameters& parameters);
  Lobe lobe;
  ref::KutlogLobe reference;
  // F = 0 at and below it: max(cos(gran), 0).
  double cut;
};
// The lobe of these parameters, built once; nullptr for invalid parameters, after checking
// the constructor's contract.
const LobeUnderTest* lobe_under_test(const LobeParameters& parameters, const Call& call);

// The values the kernel of `lobe` may return for a t anywhere in [t_lo, t_hi], by the contract
// of kutlog/lobe.hpp: exactly the peak (1, or float(coef) when normalized) for t >= 1, exactly
// 0 at and below the cut, and elsewhere F within the variant's absolute bound relative to the
// peak (F does not decrease with t).
struct Range {
  double lo, hi;
};
Range lobe_range(const LobeUnderTest& lobe, Variant variant, Normalization normalization,
                 double t_lo, double t_hi);
// Whether a float product `out` of a value in `lobe` and a factor in [factor_lo, factor_hi]
// (>= 0) is possible, allowing its one rounding (and overflow to inf, and inf * 0 = NaN).
bool product_within(float out, Range lobe, double factor_lo, double factor_hi);

}  // namespace kutlog::fuzz
