/* tests/consumer/footprint.cmake's C program: footprint.cpp's scalar program through the C API
 * (kutlog/kutlog.h), each lobe's fragment handles evaluated inline. It must link what the C++
 * one does, no kernel table, and print the same digest. */
#include <kutlog/kutlog.h>

#include <stdint.h>
#include <stdio.h>
#include <string.h>

enum { kSteps = 4096 };

static float t_at(int i) { return (float)i / (float)(kSteps - 64); }

/* FNV-1a over the outputs' bits, as footprint.cpp's. */
static uint64_t mix(uint64_t digest, float value) {
  uint32_t bits;
  memcpy(&bits, &value, sizeof bits);
  return (digest ^ bits) * 0x100000001b3u;
}

int main(void) {
  static const double n[] = {50, 2, 1000};
  static const int k[] = {3, 5, 20};
  uint64_t digest = 0xcbf29ce484222325u;
  int material, i;
  for (material = 0; material < 3; ++material) {
    kutlog_lobe* lobe = NULL;
    kutlog_fragment precise[2];
    kutlog_fast_fragment fast[2];
    kutlog_error error;
    if (kutlog_lobe_create(n[material], k[material], 0.5, &lobe, &error) != KUTLOG_OK ||
        kutlog_lobe_fragment(lobe, KUTLOG_UNNORMALIZED, &precise[0], &error) != KUTLOG_OK ||
        kutlog_lobe_fragment(lobe, KUTLOG_EXACT_COEF, &precise[1], &error) != KUTLOG_OK ||
        kutlog_lobe_fast_fragment(lobe, KUTLOG_UNNORMALIZED, &fast[0], &error) != KUTLOG_OK ||
        kutlog_lobe_fast_fragment(lobe, KUTLOG_EXACT_COEF, &fast[1], &error) != KUTLOG_OK) {
      printf("%s\n", error.message);
      return 1;
    }
    for (i = 0; i < kSteps; ++i) {
      digest = mix(digest, kutlog_eval(&precise[0], t_at(i)));
      digest = mix(digest, kutlog_eval(&precise[1], t_at(i)));
      digest = mix(digest, kutlog_eval_fast(&fast[0], t_at(i)));
      digest = mix(digest, kutlog_eval_fast(&fast[1], t_at(i)));
    }
    kutlog_lobe_destroy(lobe);
  }
  printf("scalar digest %016llx\n", (unsigned long long)digest);
  return 0;
}
