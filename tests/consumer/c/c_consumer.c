/* A C renderer's use of kutlog, through kutlog/kutlog.h alone: a lobe per material, its
 * fragment handle evaluated inline per fragment, an array call, a sample, and an error. Built
 * as C99 by a C-only CMake project (find_package) and by pkg-config's flags, against the static
 * and the shared library. Prints "c consumer: ok". */
#include <kutlog/kutlog.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int check(int condition, const char* what) {
  if (!condition) printf("FAILED: %s\n", what);
  return condition;
}

int main(void) {
  enum { kCount = 1000 };
  static float t[kCount], out[kCount];
  kutlog_lobe *lobe = NULL, *lobe_of_k0 = NULL;
  kutlog_sampler* sampler = NULL;
  kutlog_fragment fragment;
  kutlog_error error;
  kutlog_sample sample;
  int ok = 1, i;
  if (!check(kutlog_lobe_create(1000, 3, 0.5, &lobe, &error) == KUTLOG_OK, error.message) ||
      !check(kutlog_lobe_fragment(lobe, KUTLOG_UNNORMALIZED, &fragment, &error) == KUTLOG_OK,
             error.message))
    return 1;
  for (i = 0; i < kCount; ++i) t[i] = 1.0f - (float)i * 1e-5f;
  ok &= check(kutlog_lobe_eval_array(lobe, t, out, kCount, KUTLOG_PRECISE, KUTLOG_UNNORMALIZED,
                                     &error) == KUTLOG_OK,
              error.message);
  for (i = 0; i < kCount; ++i) {
    const float inline_value = kutlog_eval(&fragment, t[i]);
    const float library_value = kutlog_lobe_eval(lobe, t[i], KUTLOG_PRECISE, KUTLOG_UNNORMALIZED);
    /* Inline against the library's own scalar eval: the same bits; against the array: within
     * both bounds of 2^-22. */
    ok &= check(memcmp(&inline_value, &library_value, sizeof inline_value) == 0, "inline bits");
    ok &= check(fabsf(inline_value - out[i]) <= 0x1p-21f, "inline against the array");
  }
  ok &= check(kutlog_sampler_create(1000, 3, 0.5, KUTLOG_USE_MICROFACET, &sampler, &error) ==
                  KUTLOG_OK,
              error.message);
  sample = kutlog_sampler_sample(sampler, 0.25f, 0.5f, KUTLOG_PRECISE);
  ok &= check(sample.z > 0 && sample.pdf > 0, "a sample above the surface");
  ok &= check(kutlog_lobe_create(100, 0, 0.5, &lobe_of_k0, &error) == KUTLOG_INVALID_ARGUMENT &&
                  lobe_of_k0 == NULL && strstr(error.message, "k = 0") != NULL,
              "k = 0 refused, naming k");
  ok &= check(kutlog_active_arch(&error) != NULL, error.message);
  kutlog_sampler_destroy(sampler);
  kutlog_lobe_destroy(lobe);
  if (!ok) return 1;
  printf("c consumer: ok (arch %s)\n", kutlog_active_arch(NULL));
  return 0;
}
