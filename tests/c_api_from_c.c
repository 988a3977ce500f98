/* kutlog/kutlog.h as a C99 program sees it, compiled with -std=c99 -pedantic -Werror: the
 * inline fragment eval, compiled by the C compiler, gives the bits of C++'s Lobe::eval for
 * every float of [-1, 1] that a stride of 61 reaches (2^25 of them) on a few lobes, and errors
 * come back as codes with messages. Prints "c api: ok". */
#include <kutlog/kutlog.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

static void fail(const char* what, double n, int k, float t, float expected, float actual) {
  if (++failures <= 10)
    printf("FAIL %s: n = %g, k = %d, t = %.9g: %.9g against C++'s %.9g\n", what, n, k,
           (double)t, (double)actual, (double)expected);
}

static int same_bits(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Every float of [-1, 1] at a stride of 61 units, both signs: the inline eval against the
 * library's own (kutlog_lobe_eval, C++'s Lobe::eval compiled into it), bit for bit; 0 at and
 * below the cut. */
static void check_lobe(double n, int k, double Q, kutlog_normalization normalization) {
  kutlog_lobe* lobe = NULL;
  kutlog_fragment fragment;
  kutlog_error error;
  uint32_t bits;
  int sign;
  if (kutlog_lobe_create(n, k, Q, &lobe, &error) != KUTLOG_OK ||
      kutlog_lobe_fragment(lobe, normalization, &fragment, &error) != KUTLOG_OK) {
    printf("FAIL create: %s\n", error.message);
    ++failures;
    kutlog_lobe_destroy(lobe);
    return;
  }
  for (sign = 0; sign < 2; ++sign)
    for (bits = 0; bits <= 0x3f800000u; bits += 61u) {
      const uint32_t signed_bits = sign ? bits | 0x80000000u : bits;
      float t, actual, expected;
      memcpy(&t, &signed_bits, sizeof t);
      actual = kutlog_eval(&fragment, t);
      expected = kutlog_lobe_eval(lobe, t, KUTLOG_PRECISE, normalization);
      if (!same_bits(actual, expected)) fail("inline eval", n, k, t, expected, actual);
      if (t <= fragment.t_cut && !same_bits(actual, 0.0f))
        fail("zero past the cut", n, k, t, 0.0f, actual);
    }
  kutlog_lobe_destroy(lobe);
}

int main(void) {
  kutlog_error error;
  kutlog_lobe* lobe = NULL;
  check_lobe(1000, 3, 0.5, KUTLOG_UNNORMALIZED);
  check_lobe(50, 5, 0.5, KUTLOG_EXACT_COEF);
  check_lobe(2, 3, 0.5, KUTLOG_UNNORMALIZED); /* cut at the horizon: the kernel out of line */
  if (kutlog_lobe_create(0, 3, 0.5, &lobe, &error) != KUTLOG_INVALID_ARGUMENT || lobe != NULL ||
      strstr(error.message, "n = 0") == NULL) {
    printf("FAIL Lobe(0, 3, 0.5): %d, %s\n", (int)error.code, error.message);
    ++failures;
  }
  if (kutlog_acos_u10(NULL, NULL, 1, &error) != KUTLOG_INVALID_ARGUMENT) {
    printf("FAIL acos_u10 on NULL: %s\n", error.message);
    ++failures;
  }
  if (failures) return EXIT_FAILURE;
  printf("c api: ok\n");
  return EXIT_SUCCESS;
}
