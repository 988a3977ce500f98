// The array loops around the batch kernels, instantiated once per arch by src/arch/<arch>.cpp.
// Everything here is a template on the xsimd arch, so no copy compiled with one arch's flags
// can stand in for another's; it calls nothing from the standard library for that reason.
#pragma once

#include <cmath>
#include <cstddef>

#include "arch/kernel_table.hpp"
#include "kutlog/simd/lobe.hpp"
#include "kutlog/simd/math.hpp"
#include "kutlog/simd/sampling.hpp"
#include "kutlog/simd/shade.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::detail {

template <class Arch>
using floats_of = xsimd::batch<float, Arch>;

// The first `count` (< N; AVX-512's also N, and every arch's but SSE4.1's 0) lanes of an array,
// `padding` in the others, and their store. No load or store leaves the arrays. AVX-512 moves them
// with a lane mask; AVX2 loads with one (masked lanes never touch memory) but stores in halves, 4,
// 2 and 1 floats by the bits of count, as SSE4.1 both loads and stores: AMD's AVX2 lane-masked
// store is microcoded, and a local buffer's scalar writes, read back as one vector, wait for
// store forwarding that never comes. Other archs (NEON) go through the buffer. Overloads on
// the arch's tag, the most derived chosen, so that only their code has a buffer (an aligned
// buffer anywhere in a function costs every call a stack realignment).
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::generic, const float* in, std::size_t count,
                                              float padding) {
  using F = xsimd::batch<float, Arch>;
  alignas(64) float buffer[F::size];
  for (std::size_t j = 0; j < F::size; ++j) buffer[j] = j < count ? in[j] : padding;
  return F::load_aligned(buffer);
}
template <class Arch>
inline void store_partial(xsimd::generic, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  alignas(64) float result[xsimd::batch<float, Arch>::size];
  value.store_aligned(result);
  for (std::size_t j = 0; j < count; ++j) out[j] = result[j];
}
#if XSIMD_WITH_SSE4_1
// The first count (< 4) lanes of part, by halves. A template, as everything here.
template <class Arch>
inline void store_first_lanes(float* out, __m128 part, std::size_t count) {
  if (count & 2) {
    _mm_storel_pi(reinterpret_cast<__m64*>(out), part);
    part = _mm_movehl_ps(part, part);
    out += 2;
  }
  if (count & 1) _mm_store_ss(out, part);
}
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::sse4_1, const float* in, std::size_t count,
                                              float padding) {
  static_assert(xsimd::batch<float, Arch>::size == 4, "an arch of 4 float lanes");
  const __m128 pad = _mm_set1_ps(padding);
  if (!(count & 2)) return _mm_move_ss(pad, _mm_load_ss(in));
  const __m128 pair = _mm_loadl_pi(pad, reinterpret_cast<const __m64*>(in));
  return count & 1 ? _mm_insert_ps(pair, _mm_load_ss(in + 2), 2 << 4) : pair;
}
template <class Arch>
inline void store_partial(xsimd::sse4_1, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  static_assert(xsimd::batch<float, Arch>::size == 4, "an arch of 4 float lanes");
  store_first_lanes<Arch>(out, value, count);
}
#endif
#if XSIMD_WITH_AVX2
template <class Arch>
inline __m256i first_lanes_avx2(std::size_t count) {
  return _mm256_cmpgt_epi32(_mm256_set1_epi32(int(count)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::avx2, const float* in, std::size_t count,
                                              float padding) {
  const __m256i lanes = first_lanes_avx2<Arch>(count);
  return _mm256_blendv_ps(_mm256_set1_ps(padding), _mm256_maskload_ps(in, lanes),
                          _mm256_castsi256_ps(lanes));
}
template <class Arch>
inline void store_partial(xsimd::avx2, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  __m128 part = _mm256_castps256_ps128(value);
  if (count & 4) {
    _mm_storeu_ps(out, part);
    part = _mm256_extractf128_ps(value, 1);
    out += 4;
  }
  store_first_lanes<Arch>(out, part, count);
}
#endif
#if XSIMD_WITH_AVX512F
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::avx512f, const float* in, std::size_t count,
                                              float padding) {
  return _mm512_mask_loadu_ps(_mm512_set1_ps(padding), __mmask16((1u << count) - 1), in);
}
template <class Arch>
inline void store_partial(xsimd::avx512f, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  _mm512_mask_storeu_ps(out, __mmask16((1u << count) - 1), value);
}
#endif

// Applies `kernel` to batches of `count` floats from each input array; the tail as a partial
// batch padded with `padding` (a value inside every kernel's domain). Inlined into its caller,
// so that what the kernel captures by reference is seen not to alias the output: out of line
// (GCC 12's choice for some), a loop recomputed its kernel's constants per batch.
template <class Arch, std::size_t Inputs, class Kernel>
[[gnu::always_inline]] inline void map_arrays(const Kernel& kernel,
                                              const float* const (&inputs)[Inputs], float* out,
                                              std::size_t count, float padding = 0.5f) {
  using F = xsimd::batch<float, Arch>;
  constexpr std::size_t N = F::size;
  const auto apply = [&](const auto& load) {
    return [&]<std::size_t... input>(std::index_sequence<input...>) {
      return kernel(load(input)...);
    }(std::make_index_sequence<Inputs>());
  };
  std::size_t i = 0;
  for (; i + N <= count; i += N)
    apply([&](std::size_t input) { return F::load_unaligned(inputs[input] + i); })
        .store_unaligned(out + i);
  if (i == count) return;
  const std::size_t tail = count - i;
  const F value = apply([&](std::size_t input) {
    return load_partial<Arch>(Arch{}, inputs[input] + i, tail, padding);
  });
  store_partial<Arch>(Arch{}, out + i, value, tail);
}

// PowerPoly over an array: one loop per decomposition, variant (E's degree) and log degree,
// picked per call by one lookup.
template <class Arch, bool kDecomposed, int kExpDegree, int kLogDegree>
void power_poly_loop(const PowerPolyKernel& kernel, const float* t, float* out, std::size_t count) {
  map_arrays<Arch, 1>(simd::PreparedPowerPoly<Arch, kDecomposed, kLogDegree, kExpDegree>(kernel),
                      {t}, out, count);
}
template <class Arch>
void power_poly_array(const PowerPolyKernel& kernel, const float* t, float* out, std::size_t count) {
  constexpr int kDegrees = PowerPolyKernel::kMaxLogDegree;
  using Loop = void (*)(const PowerPolyKernel&, const float*, float*, std::size_t);
  static constexpr auto kLoops = []<int... degree>(std::integer_sequence<int, degree...>) {
    constexpr int kPrecise = PowerPolyKernel::kPreciseExpDegree, kFast = PowerPolyKernel::kFastExpDegree;
    return std::array<Loop, 4 * kDegrees>{&power_poly_loop<Arch, false, kPrecise, degree + 1>...,
                                          &power_poly_loop<Arch, false, kFast, degree + 1>...,
                                          &power_poly_loop<Arch, true, kPrecise, degree + 1>...,
                                          &power_poly_loop<Arch, true, kFast, degree + 1>...};
  }(std::make_integer_sequence<int, kDegrees>());
  const int form = 2 * int(kernel.decomposed) +
                   int(kernel.exp_degree == PowerPolyKernel::kFastExpDegree);
  kLoops[std::size_t(form * kDegrees + kernel.log_degree - 1)](kernel, t, out, count);
}

// The lobe over an array: the polynomial form with its degree as a template argument (unrolled,
// coefficients in registers) and its finish fixed, the base_power form generic. The table holds
// one per degree and finish, so that a call picks its loop by the slot its Lobe computed at
// setup, with no further dispatch.
template <class Arch, int kDegree, simd::LobeFinish kFinish, bool kClamped>
[[gnu::noinline]] void kutlog_lobe_loop(const LobeKernel& kernel, const float* t, float* out,
                                        std::size_t count) {
  map_arrays<Arch, 1>(simd::PreparedLobe<Arch, kDegree, kFinish, kClamped>(kernel), {t}, out,
                      count, 1.0f);
}
// A span of at most one batch (a renderer's span of 16 on AVX-512) runs straight through, no
// loop; longer spans jump to the loop. A whole batch is loaded and stored whole, never through
// the lane mask: Zen 4 forwards no masked store to a later load, nor a store to a masked load,
// and a caller who reads back the span it just shaded, as shade() does, would wait for it.
template <class Arch, int kDegree, simd::LobeFinish kFinish = simd::LobeFinish::any,
          bool kClamped = true>
void kutlog_lobe_array(const LobeKernel& kernel, const float* t, float* out, std::size_t count) {
  using F = floats_of<Arch>;
  if (count > F::size)
    return kutlog_lobe_loop<Arch, kDegree, kFinish, kClamped>(kernel, t, out, count);
  const simd::PreparedLobe<Arch, kDegree, kFinish, kClamped> lobe(kernel);
  if (count == F::size) return lobe(F::load_unaligned(t)).store_unaligned(out);
  if (count == 0) return;  // SSE4.1's partial load reads t[0]
  store_partial<Arch>(Arch{}, out, lobe(load_partial<Arch>(Arch{}, t, count, 1.0f)), count);
}
template <class Arch>
constexpr LobeArrayKernels lobe_array_kernels() {
  using simd::LobeFinish;
  // An FMA-less arch runs a compensated kernel (never given it: see LobeArrayKernels) as split.
  constexpr LobeFinish kCompensated =
      simd::has_fused_fma<Arch> ? LobeFinish::compensated : LobeFinish::split;
  LobeArrayKernels kernels{};
  kernels.fused_fma = simd::has_fused_fma<Arch>;
  [&]<int... degree>(std::integer_sequence<int, degree...>) {
    constexpr int kPer = LobeArrayKernels::kSlotsPerDegree;
    ((kernels.by_slot[kPer * degree] = &kutlog_lobe_array<Arch, degree, LobeFinish::plain>,
      kernels.by_slot[kPer * degree + 1] = &kutlog_lobe_array<Arch, degree, LobeFinish::split>,
      kernels.by_slot[kPer * degree + 2] = &kutlog_lobe_array<Arch, degree, kCompensated>,
      kernels.by_slot[kPer * degree + 3] =
          &kutlog_lobe_array<Arch, degree, LobeFinish::plain, false>,
      kernels.by_slot[kPer * degree + 4] =
          &kutlog_lobe_array<Arch, degree, LobeFinish::split, false>),
     ...);
  }(std::make_integer_sequence<int, LobeArrayKernels::kMaxUnrolledDegree + 1>());
  kernels.by_slot[LobeArrayKernels::kSlots - 1] = &kutlog_lobe_array<Arch, -1>;
  return kernels;
}

// The stream loop: kernel(inputs...) on batches of Inputs arrays, stored where mask (if any)
// selects; the tail as a partial batch, as in map_arrays.
template <class Arch, std::size_t Inputs, class Kernel>
inline void map_masked(const Kernel& kernel, const float* const (&inputs)[Inputs], float* out,
                       std::size_t count, const std::uint8_t* mask) {
  using F = xsimd::batch<float, Arch>;
  constexpr std::size_t N = F::size;
  // A batch no lane of which is selected is skipped, one whose every lane is stored whole: a
  // rasterizer's coverage is mostly such batches, and AVX2's lane-masked store is microcoded
  // on AMD.
  const auto run = [&](const float* const (&sources)[Inputs], std::size_t at, float* target,
                       const std::uint8_t* lanes) {
    const auto value = [&] {
      return [&]<std::size_t... input>(std::index_sequence<input...>) {
        return kernel(F::load_unaligned(sources[input] + at)...);
      }(std::make_index_sequence<Inputs>());
    };
    if (!lanes) return value().store_unaligned(target);
    const auto selected = simd::load_mask<Arch>(lanes);
    if (xsimd::all(selected)) value().store_unaligned(target);
    else if (xsimd::any(selected)) simd::store_selected(target, value(), selected);
  };
  std::size_t i = 0;
  for (; i + N <= count; i += N) run(inputs, i, out + i, mask ? mask + i : nullptr);
  if (i == count) return;
  // The tail: a partial batch, merged with what out holds where the mask leaves it.
  const std::size_t tail = count - i;
  const F value = [&]<std::size_t... input>(std::index_sequence<input...>) {
    return kernel(load_partial<Arch>(Arch{}, inputs[input] + i, tail, 0.0f)...);
  }(std::make_index_sequence<Inputs>());
  if (!mask) return store_partial<Arch>(Arch{}, out + i, value, tail);
  std::uint8_t lanes[N] = {};
  for (std::size_t j = 0; j < tail; ++j) lanes[j] = mask[i + j];
  const F kept = load_partial<Arch>(Arch{}, out + i, tail, 0.0f);
  store_partial<Arch>(Arch{}, out + i, xsimd::select(simd::load_mask<Arch>(lanes), value, kept), tail);
}

// The shade forms run a chunk at a time: the chunk's cosines t (and N.L) into local buffers,
// unless the caller gave them; F(t) by the array loop of the kernel's slot, the one
// Lobe::eval runs (degree unrolled, finish fixed, clamp dropped where proven needless); then
// F, times max(N.L, 0) if asked, stored where mask selects. The buffers stay in L1. (One loop
// per form and slot instead would compile each form 86 times per arch.)
constexpr std::size_t kShadeChunk = 256;

// Where a chunk's t and N.L are (N.L only read when options.times_n_dot_l): the given arrays
// or the buffers cosines(begin, size, t_buffer, n_dot_l_buffer) filled.
struct ChunkCosines {
  const float* t;
  const float* n_dot_l;
};
template <class Arch, class Cosines>
void shade_in_chunks(const LobeKernel& kernel, const ShadeOptions& options,
                     const Cosines& cosines, float* out, std::size_t count,
                     const std::uint8_t* mask) {
  using F = floats_of<Arch>;
  static constexpr LobeArrayKernels kLobeLoops = lobe_array_kernels<Arch>();
  const LobeArrayKernel lobe_loop = kLobeLoops.of(kernel);
  alignas(64) float t_buffer[kShadeChunk], n_dot_l_buffer[kShadeChunk], lobe[kShadeChunk];
  for (std::size_t begin = 0; begin < count; begin += kShadeChunk) {
    const std::size_t size = count - begin < kShadeChunk ? count - begin : kShadeChunk;
    const ChunkCosines chunk = cosines(begin, size, t_buffer, n_dot_l_buffer);
    lobe_loop(kernel, chunk.t, lobe, size);
    const std::uint8_t* lanes = mask ? mask + begin : nullptr;
    if (options.times_n_dot_l)
      map_masked<Arch, 2>([](F f, F n_l) { return f * xsimd::max(F(0.0f), n_l); },
                          {lobe, chunk.n_dot_l}, out + begin, size, lanes);
    else
      map_masked<Arch, 1>([](F f) { return f; }, {lobe}, out + begin, size, lanes);
  }
}

// The cosine the lobe takes, by options.reflection: N.H (Blinn) or R.V (Phong).
template <class Arch>
inline floats_of<Arch> lobe_cosine(const ShadeOptions& options, const simd::Vector3<Arch>& n,
                                   const simd::Vector3<Arch>& l, const simd::Vector3<Arch>& v) {
  return options.reflection == Reflection::blinn ? simd::blinn_cosine(n, l, v)
                                                 : simd::phong_cosine(n, l, v, simd::dot(n, l));
}

template <class Arch>
void shade_vectors_array(const LobeKernel& kernel, const ShadeOptions& options, Vectors normal,
                         Vectors to_light, Vectors to_viewer, float* out, std::size_t count,
                         const std::uint8_t* mask) {
  using F = floats_of<Arch>;
  const auto cosines = [&](std::size_t begin, std::size_t size, float* t, float* n_dot_l) {
    const float *nx = normal.x + begin, *ny = normal.y + begin, *nz = normal.z + begin,
                *lx = to_light.x + begin, *ly = to_light.y + begin, *lz = to_light.z + begin;
    map_arrays<Arch, 9>(
        [&](F n_x, F n_y, F n_z, F l_x, F l_y, F l_z, F v_x, F v_y, F v_z) {
          return lobe_cosine<Arch>(options, {n_x, n_y, n_z}, {l_x, l_y, l_z}, {v_x, v_y, v_z});
        },
        {nx, ny, nz, lx, ly, lz, to_viewer.x + begin, to_viewer.y + begin, to_viewer.z + begin},
        t, size);
    if (options.times_n_dot_l)
      map_arrays<Arch, 6>([](F n_x, F n_y, F n_z, F l_x, F l_y, F l_z) {
        return simd::dot<Arch>({n_x, n_y, n_z}, {l_x, l_y, l_z});
      }, {nx, ny, nz, lx, ly, lz}, n_dot_l, size);
    return ChunkCosines{t, n_dot_l};
  };
  shade_in_chunks<Arch>(kernel, options, cosines, out, count, mask);
}

// Blinn's half vector of one light and one viewer, H = (L + V) / |L + V|, in double and rounded
// once per component: the zero vector where L + V = 0 (N.H = 0, as blinn_cosine gives there),
// NaN where L or V has a NaN or an infinity. A template, as everything here, though it does not
// depend on the arch (std::sqrt of a double is the compiler's instruction or libm's call).
template <class Arch>
Direction half_vector(Direction to_light, Direction to_viewer) {
  const double x = double(to_light.x) + double(to_viewer.x),
               y = double(to_light.y) + double(to_viewer.y),
               z = double(to_light.z) + double(to_viewer.z);
  const double length = std::sqrt(x * x + y * y + z * z);
  if (length == 0) return {0.0f, 0.0f, 0.0f};
  return {float(x / length), float(y / length), float(z / length)};
}

// One light and one viewer for every lane: Blinn's H is formed once per call, so that a lane
// computes N.H alone (blinn_cosine per lane took a square root and a division per batch), and
// closer to the exact cosine: 4 units of float rounding against 8.5 (tests/cosine_error.hpp).
template <class Arch>
void shade_directions_array(const LobeKernel& kernel, const ShadeOptions& options, Vectors normal,
                            Direction to_light, Direction to_viewer, float* out,
                            std::size_t count, const std::uint8_t* mask) {
  using F = floats_of<Arch>;
  const simd::Vector3<Arch> l{F(to_light.x), F(to_light.y), F(to_light.z)},
      v{F(to_viewer.x), F(to_viewer.y), F(to_viewer.z)};
  const Direction half = half_vector<Arch>(to_light, to_viewer);
  const simd::Vector3<Arch> h{F(half.x), F(half.y), F(half.z)};
  const bool blinn = options.reflection == Reflection::blinn;
  const auto cosines = [&](std::size_t begin, std::size_t size, float* t, float* n_dot_l) {
    const float* const n[3] = {normal.x + begin, normal.y + begin, normal.z + begin};
    if (blinn)
      map_arrays<Arch, 3>([&](F n_x, F n_y, F n_z) { return simd::dot<Arch>({n_x, n_y, n_z}, h); },
                          n, t, size);
    else
      map_arrays<Arch, 3>(
          [&](F n_x, F n_y, F n_z) { return lobe_cosine<Arch>(options, {n_x, n_y, n_z}, l, v); },
          n, t, size);
    if (options.times_n_dot_l)
      map_arrays<Arch, 3>([&](F n_x, F n_y, F n_z) { return simd::dot<Arch>({n_x, n_y, n_z}, l); },
                          n, n_dot_l, size);
    return ChunkCosines{t, n_dot_l};
  };
  shade_in_chunks<Arch>(kernel, options, cosines, out, count, mask);
}

template <class Arch>
void shade_cosines_array(const LobeKernel& kernel, const ShadeOptions& options, const float* t,
                         const float* n_dot_l, float* out, std::size_t count,
                         const std::uint8_t* mask) {
  const auto given = [&](std::size_t begin, std::size_t, float*, float*) {
    return ChunkCosines{t + begin, options.times_n_dot_l ? n_dot_l + begin : nullptr};
  };
  shade_in_chunks<Arch>(kernel, options, given, out, count, mask);
}

// The sampler over arrays: four outputs per pair of inputs, the tail as a partial batch.
template <class Arch>
void sample_lobe_array(const SamplerKernel& kernel, const float* u1, const float* u2,
                       DirectionSamples out, std::size_t count) {
  using F = floats_of<Arch>;
  constexpr std::size_t N = F::size;
  const simd::PreparedSampler<Arch> sampler(kernel);
  std::size_t i = 0;
  for (; i + N <= count; i += N) {
    const simd::SampleBatch<Arch> sample = sampler(F::load_unaligned(u1 + i), F::load_unaligned(u2 + i));
    sample.x.store_unaligned(out.x + i);
    sample.y.store_unaligned(out.y + i);
    sample.z.store_unaligned(out.z + i);
    sample.pdf.store_unaligned(out.pdf + i);
  }
  if (i == count) return;
  const std::size_t tail = count - i;
  const simd::SampleBatch<Arch> sample = sampler(load_partial<Arch>(Arch{}, u1 + i, tail, 0.5f),
                                                 load_partial<Arch>(Arch{}, u2 + i, tail, 0.5f));
  store_partial<Arch>(Arch{}, out.x + i, sample.x, tail);
  store_partial<Arch>(Arch{}, out.y + i, sample.y, tail);
  store_partial<Arch>(Arch{}, out.z + i, sample.z, tail);
  store_partial<Arch>(Arch{}, out.pdf + i, sample.pdf, tail);
}

template <class Arch>
KernelTable make_kernel_table() {
  using F = xsimd::batch<float, Arch>;
  KernelTable table{};
#define KUTLOG_UNARY_SLOT(function, kernel, ...)                               \
  table.kernel = [](const float* x, float* out, std::size_t count) {           \
    map_arrays<Arch, 1>([](F v) { return simd::kernel(v); }, {x}, out, count); \
  };
#define KUTLOG_BINARY_SLOTS(function, kernel, ...)                                             \
  table.kernel = [](const float* x, const float* y, float* out, std::size_t count) {           \
    map_arrays<Arch, 2>([](F a, F b) { return simd::kernel(a, b); }, {x, y}, out, count);      \
  };                                                                                           \
  table.kernel##_scalar = [](const float* x, float y, float* out, std::size_t count) {         \
    const F second(y);                                                                         \
    map_arrays<Arch, 1>([second](F a) { return simd::kernel(a, second); }, {x}, out, count);   \
  };
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_UNARY_SLOT)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_BINARY_SLOTS)
#undef KUTLOG_UNARY_SLOT
#undef KUTLOG_BINARY_SLOTS
  static_cast<LobeArrayKernels&>(table) = lobe_array_kernels<Arch>();
  table.kutlog_per_lane = [](const PerLaneKernel& kernel, bool normalized, const float* t,
                             const float* n, float* out, std::size_t count) {
    map_arrays<Arch, 2>(simd::PreparedPerLaneLobe<Arch>(kernel, normalized), {t, n}, out, count,
                        1.0f);
  };
  table.blinn_phong_xsimd = [](const float* t, float n, float scale, float* out, std::size_t count) {
    const F exponent(n), factor(scale);
    map_arrays<Arch, 1>([&](F v) { return simd::blinn_phong_xsimd(v, exponent, factor); }, {t},
                        out, count);
  };
  table.blinn_phong_u10 = [](const float* t, float n, float scale, float* out, std::size_t count) {
    const F exponent(n), factor(scale);
    map_arrays<Arch, 1>([&](F v) { return simd::blinn_phong_u10(v, exponent, factor); }, {t},
                        out, count);
  };
  table.power_poly = &power_poly_array<Arch>;
  table.shade_vectors = &shade_vectors_array<Arch>;
  table.shade_directions = &shade_directions_array<Arch>;
  table.shade_cosines = &shade_cosines_array<Arch>;
  table.sample_lobe = &sample_lobe_array<Arch>;
  table.sample_one = &simd::one_sample::sample<Arch>;
  table.schlick = [](const float* t, float n, float* out, std::size_t count) {
    const F exponent(n);
    map_arrays<Arch, 1>([&](F v) { return simd::schlick(v, exponent); }, {t}, out, count);
  };
  return table;
}

}  // namespace kutlog::detail
