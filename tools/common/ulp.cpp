#include "common/ulp.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include "kutlog/accuracy.hpp"
#include "kutlog/math.hpp"

namespace kutlog::tools {
namespace {

constexpr double kInfinite = std::numeric_limits<double>::infinity();

constexpr std::size_t kChunk = 1 << 16;

unsigned thread_count(unsigned requested) {
  return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace

void parallel_for(std::uint64_t chunks, unsigned requested_threads,
                  const std::function<void(std::uint64_t, unsigned)>& work,
                  const std::string& progress_label) {
  const unsigned threads = thread_count(requested_threads);
  std::atomic<std::uint64_t> next{0}, done{0};
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t)
    workers.emplace_back([&, t] {
      for (std::uint64_t chunk; (chunk = next.fetch_add(1)) < chunks; done.fetch_add(1))
        work(chunk, t);
    });
  const bool show = !progress_label.empty() && isatty(STDERR_FILENO);
  while (show && done.load() < chunks) {
    std::fprintf(stderr, "\r%s %5.1f%%", progress_label.c_str(),
                 100.0 * double(done.load()) / double(chunks));
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  for (std::thread& worker : workers) worker.join();
  if (show) std::fprintf(stderr, "\r%s done  \n", progress_label.c_str());
}

namespace {

// Per-thread statistics and profiles, merged after the sweep.
class Accumulator {
 public:
  Accumulator(unsigned threads, const SweepOptions& options)
      : stats_(threads), profiles_(options.profile ? threads : 0), options_(options) {
    for (ErrorProfile& profile : profiles_) {
      profile.worst_input.assign(options.profile_buckets, std::nanf(""));
      profile.max_ulp.assign(options.profile_buckets, -1);
    }
  }
  bool profiling() const { return !profiles_.empty(); }
  // Adds one chunk's statistics, and (when profiling) each input's error at its position in
  // [0, 1) along the sweep.
  void add_chunk(unsigned thread, const ErrorStats& chunk) { stats_[thread].merge(chunk); }
  void add_to_profile(unsigned thread, double error, float x, double position) {
    ErrorProfile& profile = profiles_[thread];
    const auto bucket = std::min<std::size_t>(std::size_t(position * double(profile.max_ulp.size())),
                                              profile.max_ulp.size() - 1);
    if (error > profile.max_ulp[bucket]) profile.max_ulp[bucket] = error, profile.worst_input[bucket] = x;
  }
  ErrorStats finish() {
    ErrorStats total;
    for (const ErrorStats& stats : stats_) total.merge(stats);
    if (options_.profile) {
      ErrorProfile& merged = *options_.profile;
      merged = profiles_.front();
      for (const ErrorProfile& profile : profiles_)
        for (std::size_t b = 0; b < profile.max_ulp.size(); ++b)
          if (profile.max_ulp[b] > merged.max_ulp[b])
            merged.max_ulp[b] = profile.max_ulp[b], merged.worst_input[b] = profile.worst_input[b];
    }
    return total;
  }

 private:
  std::vector<ErrorStats> stats_;
  std::vector<ErrorProfile> profiles_;
  SweepOptions options_;
};

}  // namespace

std::uint32_t order_key(float x) {
  const auto bits = std::bit_cast<std::uint32_t>(x);
  return bits & 0x80000000u ? 0xffffffffu - bits : bits + 0x80000000u;
}
float float_of_order_key(std::uint32_t key) {
  return std::bit_cast<float>(key >= 0x80000000u ? key - 0x80000000u : 0xffffffffu - key);
}

double ulp_error_special(float computed, double reference) {
  if (std::isnan(reference)) return std::isnan(computed) ? 0 : kInfinite;
  if (std::isnan(computed)) return kInfinite;
  if (std::isinf(computed)) return static_cast<float>(reference) == computed ? 0 : kInfinite;
  if (std::isinf(reference)) return kInfinite;
  if (reference == 0 && computed == 0)
    return std::signbit(reference) == std::signbit(computed) ? 0 : kInfinite;
  return std::fabs(double(computed) - reference) * 0x1p149;  // reference 0: subnormal ulp
}

void ErrorStats::merge(const ErrorStats& other) {
  if (other.inputs && (other.max_ulp > max_ulp || inputs == 0))
    max_ulp = other.max_ulp, worst_x = other.worst_x, worst_y = other.worst_y;
  sum_ulp += other.sum_ulp;
  inputs += other.inputs;
}

// Each function's sweep domain is its row of kutlog/accuracy.hpp, made from the one list of
// kutlog/detail/math_functions.hpp.
UnaryFunction unary_function(std::string_view name, UnaryArray array, double (*reference)(double)) {
  const AccuracyBound bound = *find_accuracy_bound(name);
  return {bound.function, bound.kernel, array, reference, bound.sweep_lo, bound.sweep_hi,
          bound.domain};
}

const std::vector<UnaryFunction>& unary_functions() {
  static const std::vector<UnaryFunction> functions = {
#define KUTLOG_UNARY_FUNCTION(function, kernel, promised, x86_64, aarch64, domain, lo, hi, peer, \
                              ...)                                                             \
  unary_function(#function, &math::kernel, [](double x) { return std::peer(x); }),
      KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_UNARY_FUNCTION)
#undef KUTLOG_UNARY_FUNCTION
  };
  return functions;
}

std::vector<std::string> math_function_names() {
  std::vector<std::string> names;
  for (const AccuracyBound& bound : kAccuracyBounds) names.emplace_back(bound.function);
  return names;
}

const UnaryFunction* find_unary_function(std::string_view name) {
  for (const UnaryFunction& function : unary_functions())
    if (function.name == name) return &function;
  return nullptr;
}

void for_each_float(float lo, float hi, unsigned threads,
                    const std::function<void(std::uint32_t, std::size_t, unsigned)>& visit,
                    const std::string& progress_label, std::uint32_t stride) {
  const std::uint32_t first = order_key(lo), last = order_key(hi);
  const std::uint64_t total = (std::uint64_t(last) - first) / stride + 1;
  const std::uint64_t chunks = (total + kChunk - 1) / kChunk;
  parallel_for(
      chunks, thread_count(threads),
      [&](std::uint64_t chunk, unsigned thread) {
        const std::uint64_t start = first + chunk * kChunk * stride;
        visit(std::uint32_t(start), std::size_t(std::min<std::uint64_t>(kChunk, total - chunk * kChunk)),
              thread);
      },
      progress_label);
}

std::uint32_t sample_stride(float lo, float hi, std::uint64_t samples) {
  const std::uint64_t total = std::uint64_t(order_key(hi)) - order_key(lo) + 1;
  return samples == 0 || samples >= total ? 1 : std::uint32_t((total + samples - 1) / samples);
}

namespace {
// Sweeps every float in [lo, hi] through `compute` (array in, array out), comparing with
// `reference`. A template, so that the per-element reference call is direct.
template <class Compute, class Reference>
ErrorStats sweep(float lo, float hi, const SweepOptions& options, Compute compute,
                 Reference reference, float y) {
  const unsigned threads = thread_count(options.threads);
  Accumulator accumulator(threads, options);
  const double first = order_key(lo), span = double(order_key(hi)) - first + 1;
  const std::uint32_t stride = sample_stride(lo, hi, options.samples);
  for_each_float(
      lo, hi, threads,
      [&](std::uint32_t first_key, std::size_t count, unsigned thread) {
        thread_local std::vector<float> in_buffer, out_buffer;
        in_buffer.resize(count), out_buffer.resize(count);
        float* const in = in_buffer.data();
        float* const out = out_buffer.data();
        for (std::size_t i = 0; i < count; ++i)
          in[i] = float_of_order_key(first_key + std::uint32_t(i) * stride);
        compute(in, out, count);
        ErrorStats chunk;
        for (std::size_t i = 0; i < count; ++i) chunk.add(ulp_error(out[i], reference(in[i])), in[i], y);
        accumulator.add_chunk(thread, chunk);
        if (accumulator.profiling())
          for (std::size_t i = 0; i < count; ++i) {
            const double position = options.profile_linear_in_value
                                        ? (double(in[i]) - lo) / (double(hi) - lo)
                                        : (double(first_key) + double(i) * stride - first) / span;
            accumulator.add_to_profile(thread, ulp_error(out[i], reference(in[i])), in[i], position);
          }
      },
      options.progress_label, stride);
  return accumulator.finish();
}
}  // namespace

ErrorStats sweep_unary(const UnaryFunction& function, float lo, float hi,
                       const SweepOptions& options) {
  return sweep(
      lo, hi, options, [&](const float* in, float* out, std::size_t n) { function.array(in, out, n); },
      [reference = function.reference](float x) { return reference(x); }, std::nanf(""));
}

constexpr AccuracyBound kPowBound = *find_accuracy_bound("pow");

ErrorStats sweep_pow_exponent(float y, const SweepOptions& options) {
  // At and below x_zero, x^y < 2^-1100 (y > 0): glibc's pow returns +0 there (the result is
  // below half the least subnormal, 2^-1075), after a slow underflow path. Returning +0 at once
  // gives the same reference, and for y >= 50 almost every x of (0, 1] is there: the sweep
  // takes about a third of the time. (0 when no float is: y <= 0, or 2^(-1100 / y) < 2^-149.)
  const float x_zero =
      y > 0 ? std::nextafter(float(std::exp2(-1100.0 / double(y))), 0.0f) : 0.0f;
  return sweep(
      kPowBound.sweep_lo, kPowBound.sweep_hi, options,
      [y](const float* in, float* out, std::size_t n) { math::pow_u10(in, y, out, n); },
      [y, x_zero](float x) { return x <= x_zero ? 0.0 : std::pow(double(x), double(y)); }, y);
}

ErrorStats sweep_pow_random(std::uint64_t pairs, std::uint64_t seed, const SweepOptions& options) {
  const unsigned threads = thread_count(options.threads);
  Accumulator accumulator(threads, options);
  const std::uint64_t chunks = (pairs + kChunk - 1) / kChunk;
  parallel_for(
      chunks, threads,
      [&](std::uint64_t chunk, unsigned thread) {
        // One generator per chunk: the pairs do not depend on the thread count.
        std::mt19937_64 engine(seed * 0x9e3779b97f4a7c15ull + chunk);
        std::uniform_int_distribution<std::uint32_t> positive_bits(1, 0x7f7fffffu);
        std::uniform_int_distribution<std::uint32_t> any_bits;
        std::uniform_real_distribution<double> exponent_of_result(-104, 89);
        const std::size_t count = std::size_t(std::min<std::uint64_t>(kChunk, pairs - chunk * kChunk));
        thread_local std::vector<float> x, y, out;
        x.resize(count), y.resize(count), out.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
          x[i] = std::bit_cast<float>(positive_bits(engine));
          if (i % 2 == 0 && x[i] != 1.0f) {
            y[i] = float(exponent_of_result(engine) / std::log(double(x[i])));
          } else {
            do y[i] = std::bit_cast<float>(any_bits(engine));
            while (!std::isfinite(y[i]));
          }
        }
        math::pow_u10(x.data(), y.data(), out.data(), count);
        ErrorStats chunk_stats;
        for (std::size_t i = 0; i < count; ++i)
          chunk_stats.add(ulp_error(out[i], std::pow(double(x[i]), double(y[i]))), x[i], y[i]);
        accumulator.add_chunk(thread, chunk_stats);
      },
      options.progress_label);
  return accumulator.finish();
}

}  // namespace kutlog::tools
