#include "common/lobe_errors.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "common/ulp.hpp"
#include "kutlog/reference.hpp"

namespace kutlog::tools {
namespace {

void merge(LobeErrors& into, const LobeErrors& from) {
  if (from.max_abs_error > into.max_abs_error)
    into.max_abs_error = from.max_abs_error, into.worst_abs_input = from.worst_abs_input;
  if (from.max_epicenter_ulp > into.max_epicenter_ulp)
    into.max_epicenter_ulp = from.max_epicenter_ulp, into.worst_ulp_input = from.worst_ulp_input;
  into.inputs += from.inputs;
}

}  // namespace

std::array<LobeErrors, 4> measure_lobe(const Lobe& lobe, std::uint32_t stride, unsigned threads) {
  const ref::KutlogLobe reference(lobe.n(), lobe.k(), lobe.Q());
  // The reference is 0 at and below the cut: t <= max(cos(gran), 0).
  const double cut = lobe.cutoff_angle() >= ref::pi / 2 ? 0.0 : std::cos(lobe.cutoff_angle());
  const std::uint32_t cut_key = order_key(float(cut)), zero_key = order_key(0.0f);
  const std::uint32_t first_key = order_key(-1.0f), last_key = order_key(1.0f);
  constexpr std::uint32_t kBoundary = 1 << 16, kBelowCutStride = 61;
  // Segments of order keys [first, last] sampled every `step`.
  struct Segment {
    std::uint32_t first, last, step;
  };
  std::vector<Segment> segments = {
      {first_key, cut_key, kBelowCutStride * stride},
      {cut_key - std::min(kBoundary, cut_key - first_key), cut_key, 1},
      {std::max(zero_key, first_key + kBoundary) - kBoundary, std::min(zero_key + kBoundary, cut_key), 1},
      {cut_key + 1, last_key, stride}};
  // Tasks of up to 2^16 samples each.
  constexpr std::uint64_t kSamples = 1 << 16;
  struct Task {
    std::uint32_t first, last, step;
  };
  std::vector<Task> tasks;
  for (const Segment& segment : segments)
    for (std::uint64_t key = segment.first; segment.first <= segment.last && key <= segment.last;
         key += kSamples * segment.step)
      tasks.push_back({std::uint32_t(key),
                       std::uint32_t(std::min<std::uint64_t>(segment.last, key + (kSamples - 1) * segment.step)),
                       segment.step});

  std::array<LobeErrors, 4> total{};
  std::mutex total_mutex;
  parallel_for(tasks.size(), threads, [&](std::uint64_t index, unsigned) {
    const Task& task = tasks[index];
    thread_local std::vector<float> t, out;
    thread_local std::vector<double> expected;
    t.clear();
    for (std::uint64_t key = task.first; key <= task.last; key += task.step)
      t.push_back(float_of_order_key(std::uint32_t(key)));
    expected.resize(t.size());
    for (std::size_t i = 0; i < t.size(); ++i)
      expected[i] = double(t[i]) <= cut ? 0.0 : reference.eval(t[i]);
    out.resize(t.size());
    std::array<LobeErrors, 4> local{};
    int kernel_index = 0;
    for (Variant variant : kLobeVariants)
      for (Normalization normalization : kLobeNormalizations) {
        LobeErrors& errors = local[kernel_index++];
        const double scale = normalization == Normalization::exact_coef ? lobe.coef_exact() : 1.0;
        lobe.eval(t.data(), out.data(), t.size(), variant, normalization);
        for (std::size_t i = 0; i < t.size(); ++i) {
          const double error = lobe_abs_error(out[i], scale, expected[i]);
          if (!(error <= errors.max_abs_error))  // NaN counts as the worst
            errors.max_abs_error = std::isnan(error) ? INFINITY : error,
            errors.worst_abs_input = t[i];
          if (expected[i] >= 0.6) {
            const double ulps = epicenter_ulps(error, expected[i]);
            if (ulps > errors.max_epicenter_ulp)
              errors.max_epicenter_ulp = ulps, errors.worst_ulp_input = t[i];
          }
        }
        errors.inputs += t.size();
      }
    const std::lock_guard lock(total_mutex);
    for (int i = 0; i < 4; ++i) merge(total[i], local[i]);
  });
  return total;
}

}  // namespace kutlog::tools
