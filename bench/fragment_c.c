/* The per-fragment loop compiled as C (C99), so that the fragment/scalar_kutlog_c rows time
 * kutlog_eval as a C renderer's compiler inlines it from kutlog/kutlog.h. */
#include <kutlog/kutlog.h>

#include "fragment_c.h"

void kutlog_bench_c_eval(const kutlog_fragment* fragment, const float* t, float* out,
                         size_t count) {
  const kutlog_fragment local = *fragment; /* as a shader keeps it: in registers, not re-read */
  size_t i;
  for (i = 0; i < count; ++i) out[i] = kutlog_eval(&local, t[i]);
}

void kutlog_bench_c_eval_fast(const kutlog_fast_fragment* fragment, const float* t, float* out,
                              size_t count) {
  const kutlog_fast_fragment local = *fragment;
  size_t i;
  for (i = 0; i < count; ++i) out[i] = kutlog_eval_fast(&local, t[i]);
}
