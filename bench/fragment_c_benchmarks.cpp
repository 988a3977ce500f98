// fragment/scalar_kutlog_c[_fast]: the per-fragment rows of kutlog_eval, its loop compiled as C
// (bench/fragment_c.c) on a lobe of the C API, at the inputs of the C++ rows.
#include <memory>

#include "fragment_benchmarks.hpp"
#include "fragment_c.h"
#include "kutlog/kutlog.h"

namespace kutlog::bench {

void register_c_fragment_benchmarks(double n, int k, const std::string& at,
                                    const std::vector<float>& cosines) {
  kutlog_lobe* created = nullptr;
  if (kutlog_lobe_create(n, k, kLobeAnchor, &created, nullptr) != KUTLOG_OK) return;
  const std::shared_ptr<kutlog_lobe> lobe(created, kutlog_lobe_destroy);
  kutlog_fragment precise;
  kutlog_fast_fragment fast;
  kutlog_lobe_fragment(lobe.get(), KUTLOG_UNNORMALIZED, &precise, nullptr);
  kutlog_lobe_fast_fragment(lobe.get(), KUTLOG_UNNORMALIZED, &fast, nullptr);
  benchmark::RegisterBenchmark(("fragment/scalar_kutlog_c" + at).c_str(),
                               // lobe too: the fragment points into it
                               [lobe, precise, cosines](benchmark::State& state) {
    time_loop(state, [&](const float* t, float* out, std::size_t count) {
      kutlog_bench_c_eval(&precise, t, out, count);
    }, cosines);
  });
  benchmark::RegisterBenchmark(("fragment/scalar_kutlog_c_fast" + at).c_str(),
                               [lobe, fast, cosines](benchmark::State& state) {
    time_loop(state, [&](const float* t, float* out, std::size_t count) {
      kutlog_bench_c_eval_fast(&fast, t, out, count);
    }, cosines);
  });
}

}  // namespace kutlog::bench
