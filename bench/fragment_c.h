/* bench/fragment_c.c's loops: out[i] = kutlog_eval(fragment, t[i]), compiled as C. */
#ifndef KUTLOG_BENCH_FRAGMENT_C_H
#define KUTLOG_BENCH_FRAGMENT_C_H

#include <kutlog/kutlog.h>

#ifdef __cplusplus
extern "C" {
#endif
void kutlog_bench_c_eval(const kutlog_fragment* fragment, const float* t, float* out,
                         size_t count);
void kutlog_bench_c_eval_fast(const kutlog_fast_fragment* fragment, const float* t, float* out,
                              size_t count);
#ifdef __cplusplus
}
#endif

#endif
