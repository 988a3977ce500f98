#include "common/lobe_errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include "common/ulp.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/reference.hpp"

namespace kutlog::tools {

void LobeErrors::add(float t, float out, double scale, double expected) {
  ++inputs;
  const double error = lobe_abs_error(out, scale, expected);
  if (!(error <= max_abs_error))
    max_abs_error = std::isnan(error) ? INFINITY : error, worst_abs_input = t;
  if (expected >= 0.6) {
    const double ulps = ulp_error(out, scale * expected);
    if (!(ulps <= max_epicenter_ulp))
      max_epicenter_ulp = std::isnan(ulps) ? INFINITY : ulps, worst_ulp_input = t;
  }
  if (out < min_output) min_output = out, min_output_input = t;
  if (out > max_output) max_output = out, max_output_input = t;
  if (expected == 0) {
    const float magnitude = std::isnan(out) ? INFINITY : std::fabs(out);
    if (magnitude > max_where_zero) max_where_zero = magnitude, max_where_zero_input = t;
  }
}

void LobeErrors::merge(const LobeErrors& from) {
  if (from.max_abs_error > max_abs_error)
    max_abs_error = from.max_abs_error, worst_abs_input = from.worst_abs_input;
  if (from.max_epicenter_ulp > max_epicenter_ulp)
    max_epicenter_ulp = from.max_epicenter_ulp, worst_ulp_input = from.worst_ulp_input;
  if (from.min_output < min_output)
    min_output = from.min_output, min_output_input = from.min_output_input;
  if (from.max_output > max_output)
    max_output = from.max_output, max_output_input = from.max_output_input;
  if (from.max_where_zero > max_where_zero)
    max_where_zero = from.max_where_zero, max_where_zero_input = from.max_where_zero_input;
  inputs += from.inputs;
}

double epicenter_edge(const Lobe& lobe) {
  const double x = std::acos(std::pow(0.6, 1.0 / lobe.k())) / inspect::c(lobe);  // F(x) = 0.6
  return x >= ref::pi / 2 ? 0.0 : std::cos(x);
}

void evaluate_array(const Lobe& lobe, Variant variant, Normalization normalization,
                    const float* t, float* out, std::size_t count) {
  lobe.eval(t, out, count, variant, normalization);
}

LobeKernelErrors measure_lobe(const Lobe& lobe, LobeSweep sweep, LobeEvaluator evaluate,
                                       unsigned threads) {
  const ref::KutlogLobe reference(lobe.n(), lobe.k(), lobe.Q());
  // The reference is 0 at and below the cut: t <= max(cos(gran), 0).
  const double cut = lobe.cutoff_angle() >= ref::pi / 2 ? 0.0 : std::cos(lobe.cutoff_angle());
  const std::uint32_t cut_key = order_key(float(cut)), zero_key = order_key(0.0f);
  const std::uint32_t first_key = order_key(-1.0f), last_key = order_key(1.0f);
  // The first float of the epicenter (rounded down: a float more costs nothing).
  const std::uint32_t epicenter_key =
      std::max(cut_key + 1, order_key(std::nextafter(float(epicenter_edge(lobe)), -1.0f)));
  constexpr std::uint32_t kBoundary = 1 << 16;
  const std::uint32_t end_reach =
      std::max<std::uint32_t>(kBoundary / sweep.support_stride, 1 << 10);
  // Segments of order keys [first, last] sampled every `step`.
  struct Segment {
    std::uint32_t first, last, step;
  };
  std::vector<Segment> segments = {
      {first_key, cut_key, sweep.below_cut_stride},
      {cut_key - std::min(kBoundary, cut_key - first_key), cut_key, 1},
      {std::max(zero_key, first_key + kBoundary) - kBoundary, std::min(zero_key + kBoundary, cut_key), 1},
      {cut_key + 1, epicenter_key - 1, sweep.support_stride},
      {epicenter_key, last_key, sweep.epicenter_stride},
      // Every float of the support's two ends, where the output meets 0 and the peak: 2^16
      // of each in a sweep of every float, fewer in sparser ones (2^10 at least).
      {cut_key + 1, std::min(cut_key + end_reach, last_key), 1},
      {std::max(cut_key + 1, last_key - end_reach), last_key, 1}};
  // And about each SIMD kernel's own cut, raised where the setup dropped its clamp at 0 (the
  // negative outputs the clamp would remove sit within a few floats of where the cut goes).
  const std::uint32_t kernel_cut_reach = std::min<std::uint32_t>(end_reach, 1 << 12);
  std::vector<std::uint32_t> kernel_cuts;
  for (Variant variant : kLobeVariants)
    for (Normalization normalization : kLobeNormalizations)
      for (inspect::Arithmetic arithmetic :
           {inspect::Arithmetic::unfused, inspect::Arithmetic::fused}) {
        const std::uint32_t key =
            order_key(inspect::kernel(lobe, variant, normalization, arithmetic).t_cut);
        const auto near = [&](std::uint32_t cut) {
          return std::max(key, cut) - std::min(key, cut) <= kernel_cut_reach / 2;
        };
        const bool covered = key <= cut_key + end_reach / 2 ||
                             std::any_of(kernel_cuts.begin(), kernel_cuts.end(), near);
        if (covered) continue;
        kernel_cuts.push_back(key);
        segments.push_back({key - kernel_cut_reach, std::min(key + kernel_cut_reach, last_key), 1});
      }
  // Tasks of up to 2^16 samples each.
  constexpr std::uint64_t kSamples = 1 << 16;
  std::vector<Segment> tasks;
  for (const Segment& segment : segments)
    for (std::uint64_t key = segment.first; segment.first <= segment.last && key <= segment.last;
         key += kSamples * segment.step)
      tasks.push_back({std::uint32_t(key),
                       std::uint32_t(std::min<std::uint64_t>(segment.last, key + (kSamples - 1) * segment.step)),
                       segment.step});

  LobeKernelErrors total{};
  std::mutex total_mutex;
  parallel_for(tasks.size(), threads, [&](std::uint64_t index, unsigned) {
    const Segment& task = tasks[index];
    thread_local std::vector<float> t, out;
    thread_local std::vector<double> expected;
    t.clear();
    for (std::uint64_t key = task.first; key <= task.last; key += task.step)
      t.push_back(float_of_order_key(std::uint32_t(key)));
    expected.resize(t.size());
    for (std::size_t i = 0; i < t.size(); ++i)
      expected[i] = double(t[i]) <= cut ? 0.0 : reference.eval(t[i]);
    out.resize(t.size());
    LobeKernelErrors local{};
    int kernel_index = 0;
    for (Variant variant : kLobeVariants)
      for (Normalization normalization : kLobeNormalizations) {
        LobeErrors& errors = local[kernel_index++];
        const bool normalized = normalization == Normalization::exact_coef;
        const double scale = normalized ? lobe.coef_exact() : 1.0;
        evaluate(lobe, variant, normalization, t.data(), out.data(), t.size());
        for (std::size_t i = 0; i < t.size(); ++i) errors.add(t[i], out[i], scale, expected[i]);
      }
    const std::lock_guard lock(total_mutex);
    for (int i = 0; i < 4; ++i) total[i].merge(local[i]);
  });
  return total;
}

}  // namespace kutlog::tools
