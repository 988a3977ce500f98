/* kutlog/kutlog.h: the C API (C99, and C++11 or later), the same kernels as the C++ API of
 * kutlog/lobe.hpp, kutlog/shade.hpp, kutlog/sampling.hpp, kutlog/math.hpp and
 * kutlog/dispatch.hpp, whose doc blocks give each call's contract, bounds and data rule.
 *
 * Errors: every call that can fail returns a kutlog_status and, where `error` is not NULL,
 * writes the code and a message naming the parameter and its valid range to it (the C++
 * exception's text). Nothing is thrown, aborted or leaked across this header.
 * Pointers and counts, for every array call: count 0 writes nothing and accepts NULL arrays; a
 * NULL array with count > 0, or a count above KUTLOG_MAX_COUNT (no float array is that large),
 * gives KUTLOG_INVALID_ARGUMENT and writes nothing. A NULL handle gives KUTLOG_INVALID_ARGUMENT
 * where a status is returned, NaN where a value is (and kutlog_eval of a zeroed fragment);
 * destroying NULL does nothing.
 * Per fragment: kutlog_lobe_fragment() gives a 32-byte plain struct, valid while its lobe lives,
 * that kutlog_eval() evaluates inline: the code of C++'s Lobe::eval(t), not a call, and its bits
 * where both are compiled with the same contraction (GCC fuses a * b + c in C++ on FMA targets
 * by default, not in ISO C: -ffp-contract=off or =fast for both). */
#ifndef KUTLOG_KUTLOG_H
#define KUTLOG_KUTLOG_H

#include <stddef.h>
#include <stdint.h>

#include "kutlog/detail/math_functions.hpp" /* the list: preprocessor only */

#if defined(__GNUC__) || defined(__clang__)
#define KUTLOG_C_API __attribute__((visibility("default")))
#define KUTLOG_ALIGNED(bytes) __attribute__((aligned(bytes)))
#define KUTLOG_LIKELY(condition) __builtin_expect(!!(condition), 1)
#else
#define KUTLOG_C_API
#define KUTLOG_ALIGNED(bytes)
#define KUTLOG_LIKELY(condition) (condition)
#endif
/* The header's inline code compiles warning-free as C and as C++ (-Wold-style-cast). */
#ifdef __cplusplus
#define KUTLOG_CONVERT(type, value) static_cast<type>(value)
#else
#define KUTLOG_CONVERT(type, value) ((type)(value))
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef enum kutlog_status {
  KUTLOG_OK = 0,
  KUTLOG_INVALID_ARGUMENT = 1, /* a parameter outside its range: C++'s std::invalid_argument */
  KUTLOG_UNSUPPORTED = 2,      /* a CPU that runs no compiled arch, or a forced arch it lacks */
  KUTLOG_OUT_OF_MEMORY = 3,
  KUTLOG_INTERNAL_ERROR = 4 /* a setup that met no bound: seen on no lobe tried */
} kutlog_status;

/* Written by a failing call where the caller passes it; message is "" on success. */
typedef struct kutlog_error {
  kutlog_status code;
  char message[320];
} kutlog_error;

/* The largest count an array call takes: PTRDIFF_MAX / sizeof(float). */
#define KUTLOG_MAX_COUNT (PTRDIFF_MAX / 4)

/* As kutlog::Variant, kutlog::Normalization, kutlog::Reflection and kutlog::LobeUse: ints, as a
 * C caller may pass any, each checked (KUTLOG_INVALID_ARGUMENT outside its constants). */
typedef int kutlog_variant;
enum {
  KUTLOG_PRECISE = 0,
  KUTLOG_FAST = 1,
  KUTLOG_DETERMINISTIC = 2 /* precise's bounds, the same bits on every CPU; no inline form */
};
typedef int kutlog_normalization;
enum {
  KUTLOG_UNNORMALIZED = 0, /* F in [0, 1] */
  KUTLOG_EXACT_COEF = 1    /* coef_exact F, the energy-conserving lobe */
};
typedef int kutlog_reflection;
enum { KUTLOG_REFLECT_BLINN = 0, KUTLOG_REFLECT_PHONG = 1 };
typedef int kutlog_lobe_use;
enum { KUTLOG_USE_MICROFACET = 0, KUTLOG_USE_PHONG = 1 };

/* Opaque handles: kutlog::Lobe, kutlog::PerLaneLobe and kutlog::LobeSampler. */
typedef struct kutlog_lobe kutlog_lobe;
typedef struct kutlog_per_lane_lobe kutlog_per_lane_lobe;
typedef struct kutlog_sampler kutlog_sampler;

/* ---- One material's lobe (kutlog::Lobe) ---- */

/* n finite and > 0 with coef_exact <= FLT_MAX, k in [1, 64], Q in (0, 1); *lobe is NULL on
 * failure. Tens of microseconds: once per material. */
KUTLOG_C_API kutlog_status kutlog_lobe_create(double n, int k, double Q, kutlog_lobe** lobe,
                                              kutlog_error* error);
KUTLOG_C_API void kutlog_lobe_destroy(kutlog_lobe* lobe);
/* Lobe::coef_exact() and Lobe::t_cut() (every eval at or below t_cut is 0); NaN for NULL. */
KUTLOG_C_API double kutlog_lobe_coef_exact(const kutlog_lobe* lobe);
KUTLOG_C_API float kutlog_lobe_t_cut(const kutlog_lobe* lobe);

/* One piece of the lobe's certified table (Lobe's scalar path): a cubic in double, 64 bytes. */
typedef struct KUTLOG_ALIGNED(64) kutlog_piece {
  double polynomial[4]; /* in powers of u = x - center, lowest first */
  double center;
  double unused[3]; /* the same size, 64 bytes, where KUTLOG_ALIGNED is empty */
} kutlog_piece;
/* The fast variant's: a quadratic in float, 16 bytes. */
typedef struct KUTLOG_ALIGNED(16) kutlog_fast_piece {
  float polynomial[3];
  float center;
} kutlog_fast_piece;

/* What evaluating one fragment needs of a lobe, by variant, 32 bytes: small enough to keep in
 * a renderer's material beside its colors. pieces is NULL where the setup could not certify a
 * table (lobes cut at the horizon, k above about 12): kutlog_eval then calls the lobe's kernel
 * out of line. Valid while its lobe lives; copy it freely. */
typedef struct kutlog_fragment {
  const kutlog_piece* pieces;
  const void* kernel; /* the fallback: the lobe's scalar kernel, or NULL (NaN) */
  double pieces_per_w;
  uint32_t last_piece;
  float t_cut; /* kutlog_eval(f, t) is 0 for t <= t_cut: skip such fragments on a branch */
} kutlog_fragment;
typedef struct kutlog_fast_fragment {
  const kutlog_fast_piece* pieces;
  const void* kernel;
  float pieces_per_w;
  uint32_t last_piece;
  float t_cut;
} kutlog_fast_fragment;

/* The lobe's fragment handle, precise or fast (Variant), for that normalization. */
KUTLOG_C_API kutlog_status kutlog_lobe_fragment(const kutlog_lobe* lobe,
                                                kutlog_normalization normalization,
                                                kutlog_fragment* fragment, kutlog_error* error);
KUTLOG_C_API kutlog_status kutlog_lobe_fast_fragment(const kutlog_lobe* lobe,
                                                     kutlog_normalization normalization,
                                                     kutlog_fast_fragment* fragment,
                                                     kutlog_error* error);
/* The out-of-line kernels behind kutlog_eval where pieces is NULL. */
KUTLOG_C_API float kutlog_fragment_kernel_eval(const kutlog_fragment* fragment, float t);
KUTLOG_C_API float kutlog_fast_fragment_kernel_eval(const kutlog_fast_fragment* fragment,
                                                    float t);

/* The scalar path's table lookup, shared with C++'s Lobe::eval: x = (1 - min(t, 1)) pieces_per_w
 * picks the piece floor(x) (at most the last, the zero piece), evaluated by Horner's rule in u =
 * x - center. NaN gives NaN; t below -1, past every cut-off, 0 before x is formed: x's
 * conversion to an integer is then in range. Pieces certified with their roundings whatever the
 * compiler fuses (src/scalar_pieces.hpp). */
static inline float kutlog_pieces_eval_(const kutlog_piece* pieces, uint32_t last_piece,
                                        double pieces_per_w, float t) {
  double x, u;
  size_t index;
  const kutlog_piece* piece;
  if (!(t >= -1.0f)) return t != t ? t : 0.0f;
  x = (1.0 - KUTLOG_CONVERT(double, t < 1.0f ? t : 1.0f)) * pieces_per_w;
  index = KUTLOG_CONVERT(size_t, KUTLOG_CONVERT(int64_t, x));
  piece = pieces + (index < last_piece ? index : last_piece);
  u = x - piece->center;
  return KUTLOG_CONVERT(
      float, ((piece->polynomial[3] * u + piece->polynomial[2]) * u + piece->polynomial[1]) * u +
                 piece->polynomial[0]);
}
static inline float kutlog_fast_pieces_eval_(const kutlog_fast_piece* pieces,
                                             uint32_t last_piece, float pieces_per_w, float t) {
  float x, u;
  size_t index;
  const kutlog_fast_piece* piece;
  if (!(t >= -1.0f)) return t != t ? t : 0.0f;
  x = (1.0f - (t < 1.0f ? t : 1.0f)) * pieces_per_w;
  index = KUTLOG_CONVERT(size_t, KUTLOG_CONVERT(int64_t, x));
  piece = pieces + (index < last_piece ? index : last_piece);
  u = x - piece->center;
  return (piece->polynomial[2] * u + piece->polynomial[1]) * u + piece->polynomial[0];
}

/* F(t) (or coef_exact F) for one fragment, where pow(max(t, 0), n) was, inline, with Lobe's
 * contract and data rule (t > 1 gives the peak, t <= t_cut 0, NaN NaN). */
static inline float kutlog_eval(const kutlog_fragment* fragment, float t) {
  if (KUTLOG_LIKELY(fragment->pieces != NULL))
    return kutlog_pieces_eval_(fragment->pieces, fragment->last_piece, fragment->pieces_per_w, t);
  return kutlog_fragment_kernel_eval(fragment, t);
}
static inline float kutlog_eval_fast(const kutlog_fast_fragment* fragment, float t) {
  if (KUTLOG_LIKELY(fragment->pieces != NULL))
    return kutlog_fast_pieces_eval_(fragment->pieces, fragment->last_piece,
                                    fragment->pieces_per_w, t);
  return kutlog_fast_fragment_kernel_eval(fragment, t);
}

/* C++'s Lobe::eval(t), out of line: kutlog_eval's bits without a fragment; NaN for a NULL lobe or
 * an enum out of range. */
KUTLOG_C_API float kutlog_lobe_eval(const kutlog_lobe* lobe, float t, kutlog_variant variant,
                                    kutlog_normalization normalization);
/* out[i] = F(t[i]) on the active arch; out may equal t, else no overlap. */
KUTLOG_C_API kutlog_status kutlog_lobe_eval_array(const kutlog_lobe* lobe, const float* t,
                                                  float* out, size_t count,
                                                  kutlog_variant variant,
                                                  kutlog_normalization normalization,
                                                  kutlog_error* error);

/* ---- n per lane (kutlog::PerLaneLobe) ---- */

/* k <= n_min <= n_max <= FLT_MAX, k in [1, 64], Q in (0, 1); *lobe is NULL on failure. */
KUTLOG_C_API kutlog_status kutlog_per_lane_lobe_create(double n_min, double n_max, int k,
                                                       double Q, kutlog_per_lane_lobe** lobe,
                                                       kutlog_error* error);
KUTLOG_C_API void kutlog_per_lane_lobe_destroy(kutlog_per_lane_lobe* lobe);
/* One fragment, out of line; NaN for a NULL lobe or an enum out of range. */
KUTLOG_C_API float kutlog_per_lane_lobe_eval(const kutlog_per_lane_lobe* lobe, float t, float n,
                                             kutlog_variant variant,
                                             kutlog_normalization normalization);
/* out[i] = F(t[i]) at n[i]; out may equal t or n, else no overlap. */
KUTLOG_C_API kutlog_status kutlog_per_lane_lobe_eval_array(
    const kutlog_per_lane_lobe* lobe, const float* t, const float* n, float* out, size_t count,
    kutlog_variant variant, kutlog_normalization normalization, kutlog_error* error);

/* ---- Shading a span (kutlog/shade.hpp) ---- */

/* count vectors as three arrays (structure of arrays), and one vector for every lane. */
typedef struct kutlog_vectors {
  const float* x;
  const float* y;
  const float* z;
} kutlog_vectors;
typedef struct kutlog_direction {
  float x, y, z;
} kutlog_direction;
/* kutlog::ShadeOptions; a NULL options pointer means kutlog_default_shade_options(). */
typedef struct kutlog_shade_options {
  kutlog_variant variant;
  kutlog_normalization normalization;
  kutlog_reflection reflection;
  int times_n_dot_l; /* 0: F(t) alone, for a caller that applies its own N.L */
} kutlog_shade_options;
KUTLOG_C_API kutlog_shade_options kutlog_default_shade_options(void);

/* out[i] = F(t_i) max(N_i.L_i, 0), t_i = N.H (Blinn) or R.V (Phong); mask may be NULL, else
 * lane i is shaded where mask[i] != 0. Every lane its own normal, light and viewer. */
KUTLOG_C_API kutlog_status kutlog_shade(const kutlog_lobe* lobe, kutlog_vectors normal,
                                        kutlog_vectors to_light, kutlog_vectors to_viewer,
                                        float* out, size_t count, const uint8_t* mask,
                                        const kutlog_shade_options* options,
                                        kutlog_error* error);
/* One directional light and a distant viewer: only the normals vary. */
KUTLOG_C_API kutlog_status kutlog_shade_directional(const kutlog_lobe* lobe,
                                                    kutlog_vectors normal,
                                                    kutlog_direction to_light,
                                                    kutlog_direction to_viewer, float* out,
                                                    size_t count, const uint8_t* mask,
                                                    const kutlog_shade_options* options,
                                                    kutlog_error* error);
/* The cosines given: out[i] = F(t[i]) max(n_dot_l[i], 0); n_dot_l may be NULL where
 * options->times_n_dot_l is 0. */
KUTLOG_C_API kutlog_status kutlog_shade_cosines(const kutlog_lobe* lobe, const float* t,
                                                const float* n_dot_l, float* out, size_t count,
                                                const uint8_t* mask,
                                                const kutlog_shade_options* options,
                                                kutlog_error* error);

/* ---- Importance sampling (kutlog::LobeSampler) ---- */

/* n finite and > 0 (peak pdf within FLT_MAX), k in [1, 64], Q in (0, 1); *sampler is NULL on
 * failure. About a millisecond: once per material. */
KUTLOG_C_API kutlog_status kutlog_sampler_create(double n, int k, double Q, kutlog_lobe_use use,
                                                 kutlog_sampler** sampler, kutlog_error* error);
KUTLOG_C_API void kutlog_sampler_destroy(kutlog_sampler* sampler);
/* One direction in the use's frame and its pdf over solid angle. */
typedef struct kutlog_sample {
  float x, y, z, pdf;
} kutlog_sample;
/* One sample, out of line; every field NaN for a NULL sampler or a variant out of range.
 * KUTLOG_DETERMINISTIC: the same bits on every CPU and as the arrays'; KUTLOG_FAST samples as
 * KUTLOG_PRECISE. */
KUTLOG_C_API kutlog_sample kutlog_sampler_sample(const kutlog_sampler* sampler, float u1,
                                                 float u2, kutlog_variant variant);
/* count samples into x, y, z and pdf, which must not overlap u1 or u2. */
KUTLOG_C_API kutlog_status kutlog_sampler_sample_array(const kutlog_sampler* sampler,
                                                       const float* u1, const float* u2,
                                                       float* x, float* y, float* z, float* pdf,
                                                       size_t count, kutlog_variant variant,
                                                       kutlog_error* error);

/* ---- Math over arrays (kutlog/math.hpp), one per kernel of the list ---- */

/* kutlog_<kernel>(x, out, count, error), e.g. kutlog_acos_u10; for binary ones (pow_u10)
 * kutlog_<kernel>(x, y, out, count, error) and kutlog_<kernel>_scalar_y(x, y, out, count, error)
 * with one y for every lane. out may equal an input, else no overlap. */
#define KUTLOG_C_DECLARE_UNARY(function, kernel, ...)                               \
  KUTLOG_C_API kutlog_status kutlog_##kernel(const float* x, float* out, size_t count, \
                                             kutlog_error* error);
#define KUTLOG_C_DECLARE_BINARY(function, kernel, ...)                                       \
  KUTLOG_C_API kutlog_status kutlog_##kernel(const float* x, const float* y, float* out,    \
                                             size_t count, kutlog_error* error);            \
  KUTLOG_C_API kutlog_status kutlog_##kernel##_scalar_y(const float* x, float y, float* out, \
                                                        size_t count, kutlog_error* error);
KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_C_DECLARE_UNARY)
KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_C_DECLARE_BINARY)
#undef KUTLOG_C_DECLARE_UNARY
#undef KUTLOG_C_DECLARE_BINARY

/* ---- The arch (kutlog/dispatch.hpp) ---- */

/* The active arch's name ("avx512", "avx2", "sse4.1", "neon64", "portable"), a static string;
 * NULL, with the error, on a CPU that runs no compiled arch. */
KUTLOG_C_API const char* kutlog_active_arch(kutlog_error* error);
/* Makes every thread's array calls run on the named arch: KUTLOG_INVALID_ARGUMENT for an unknown
 * name (the message lists the valid ones), KUTLOG_UNSUPPORTED for one this CPU lacks. */
KUTLOG_C_API kutlog_status kutlog_force_arch(const char* name, kutlog_error* error);
/* Back to the automatic choice. */
KUTLOG_C_API void kutlog_reset_arch(void);

#ifdef __cplusplus
}
#endif

#endif /* KUTLOG_KUTLOG_H */
