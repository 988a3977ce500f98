// kutlog/simd/detail/portable.hpp: kutlog::simd::portable, an xsimd arch made of the compiler's own
// vectors (GCC's and clang's vector_size extension), so that the kernel templates of
// kutlog/simd/ compile for any CPU with no SIMD flag and no intrinsic: the portable entry of
// the arch registry (cmake/KutlogArchs.cmake), the baseline where kutlog has no SIMD arch.
//
// xsimd 8.1 has no emulated or scalar arch, and on a CPU it has no arch for it does not even
// define xsimd::batch. A batch here is 16 bytes (4 floats, 2 doubles), and each operation is
// the compiler's lane-wise vector arithmetic: IEEE-754 in every lane, correctly rounded, as in
// the scalar code the compiler emits for that CPU (SSE2 on x86-64, scalar instructions where
// there are no vectors). What xsimd's generic layer builds from primitives (pow, exp, to_float
// ...) comes from those below. No fused multiply-add: has_fused_fma is false, so the kernels
// take the FMA-free paths certified for SSE4.1 (kutlog compiles them with -ffp-contract=off).
//
// This must come before xsimd's batch is defined: xsimd calls its kernels by qualified name
// (kernel::add<A>(...)), which finds only the overloads declared before that call is written.
// kutlog/simd/xsimd.hpp includes it first.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include <xsimd/config/xsimd_arch.hpp>
#include <xsimd/types/xsimd_utils.hpp>

namespace kutlog::simd {

struct portable : xsimd::generic {
  static constexpr bool supported() noexcept { return true; }
  static constexpr bool available() noexcept { return true; }
  static constexpr bool requires_alignment() noexcept { return false; }
  static constexpr std::size_t alignment() noexcept { return 16; }
  static constexpr unsigned version() noexcept { return generic::version(0, 1, 0); }
  static constexpr const char* name() noexcept { return "kutlog_portable"; }
};

namespace portable_detail {
template <class T>
struct vector {
  typedef T type __attribute__((vector_size(16)));
};
template <class T>
using vector_t = typename vector<T>::type;

// The signed integer as wide as T: a comparison's lanes are 0 or -1 of this type, and the
// bitwise operations on float lanes go through it.
template <class T>
using lane_int = std::conditional_t<
    sizeof(T) == 1, std::int8_t,
    std::conditional_t<sizeof(T) == 2, std::int16_t,
                       std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>>>;
template <class T>
using mask_t = vector_t<lane_int<T>>;

// The same bits as a vector of another lane type of the same size (what GCC's and clang's
// vector casts do, said without a C-style cast).
template <class To, class From>
inline To same_bits(From v) {
  static_assert(sizeof(To) == sizeof(From));
  return std::bit_cast<To>(v);
}
template <class T>
inline mask_t<T> bits(vector_t<T> v) {
  return same_bits<mask_t<T>>(v);
}
template <class T>
inline vector_t<T> from_bits(mask_t<T> v) {
  return same_bits<vector_t<T>>(v);
}
// Every lane set by f(lane): for what has no vector operator (sqrt, nearbyint).
template <class T, class Function>
inline vector_t<T> each_lane(vector_t<T> v, Function&& f) {
  for (std::size_t i = 0; i < sizeof(v) / sizeof(T); ++i) v[i] = f(v[i]);
  return v;
}
}  // namespace portable_detail
}  // namespace kutlog::simd

namespace xsimd {
namespace types {
#define KUTLOG_PORTABLE_REGISTER(T) \
  XSIMD_DECLARE_SIMD_REGISTER(T, kutlog::simd::portable, kutlog::simd::portable_detail::vector_t<T>)
KUTLOG_PORTABLE_REGISTER(signed char);
KUTLOG_PORTABLE_REGISTER(unsigned char);
KUTLOG_PORTABLE_REGISTER(char);
KUTLOG_PORTABLE_REGISTER(short);
KUTLOG_PORTABLE_REGISTER(unsigned short);
KUTLOG_PORTABLE_REGISTER(int);
KUTLOG_PORTABLE_REGISTER(unsigned int);
KUTLOG_PORTABLE_REGISTER(long);
KUTLOG_PORTABLE_REGISTER(unsigned long);
KUTLOG_PORTABLE_REGISTER(long long);
KUTLOG_PORTABLE_REGISTER(unsigned long long);
KUTLOG_PORTABLE_REGISTER(float);
KUTLOG_PORTABLE_REGISTER(double);
#undef KUTLOG_PORTABLE_REGISTER

// A batch_bool holds a comparison's result as it comes: lanes of 0 or -1.
template <class T>
struct get_bool_simd_register<T, kutlog::simd::portable> {
  using type = simd_register<kutlog::simd::portable_detail::lane_int<T>, kutlog::simd::portable>;
};
}  // namespace types

namespace kernel {
namespace kutlog_portable {
using kutlog::simd::portable;
using kutlog::simd::portable_detail::bits;
using kutlog::simd::portable_detail::each_lane;
using kutlog::simd::portable_detail::from_bits;
using kutlog::simd::portable_detail::mask_t;
using kutlog::simd::portable_detail::same_bits;
using kutlog::simd::portable_detail::vector_t;
}  // namespace kutlog_portable

// ---- memory --------------------------------------------------------------------------------
template <class A, class T>
inline batch<T, A> broadcast(T value, requires_arch<kutlog_portable::portable>) noexcept {
  // Every lane in one initializer: GCC makes it one shuffle, where lane by lane it inserted each.
  return [value]<std::size_t... lane>(std::index_sequence<lane...>) {
    return kutlog_portable::vector_t<T>{(static_cast<void>(lane), value)...};
  }(std::make_index_sequence<batch<T, A>::size>());
}
template <class A, class T, class... Values>
inline batch<T, A> set(batch<T, A> const&, requires_arch<kutlog_portable::portable>,
                       Values... values) noexcept {
  static_assert(sizeof...(Values) == batch<T, A>::size, "one value per lane");
  return kutlog_portable::vector_t<T>{static_cast<T>(values)...};
}
template <class A, class T, class... Values>
inline batch_bool<T, A> set(batch_bool<T, A> const&, requires_arch<kutlog_portable::portable>,
                            Values... values) noexcept {
  static_assert(sizeof...(Values) == batch<T, A>::size, "one value per lane");
  using Lane = kutlog::simd::portable_detail::lane_int<T>;
  return kutlog_portable::mask_t<T>{static_cast<Lane>(values ? -1 : 0)...};
}
template <class A, class T>
inline batch<T, A> load_unaligned(T const* memory, convert<T>,
                                  requires_arch<kutlog_portable::portable>) noexcept {
  kutlog_portable::vector_t<T> v;
  std::memcpy(&v, memory, sizeof v);
  return v;
}
template <class A, class T>
inline batch<T, A> load_aligned(T const* memory, convert<T>,
                                requires_arch<kutlog_portable::portable>) noexcept {
  return load_unaligned<A>(memory, convert<T>{}, A{});
}
template <class A, class T>
inline void store_unaligned(T* memory, batch<T, A> const& self,
                            requires_arch<kutlog_portable::portable>) noexcept {
  std::memcpy(memory, &self.data, sizeof self.data);
}
template <class A, class T>
inline void store_aligned(T* memory, batch<T, A> const& self,
                          requires_arch<kutlog_portable::portable>) noexcept {
  store_unaligned<A>(memory, self, A{});
}
template <class A, class T>
inline void store(batch_bool<T, A> const& self, bool* memory,
                  requires_arch<kutlog_portable::portable>) noexcept {
  for (std::size_t i = 0; i < batch<T, A>::size; ++i) memory[i] = self.data[i] != 0;
}
// One lane replaced: what xsimd's generic gather is made of (the lobe sampler's table
// lookups); the generic insert would need a select on a compile-time mask.
template <class A, class T, std::size_t I>
inline batch<T, A> insert(batch<T, A> const& self, T value, index<I>,
                          requires_arch<kutlog_portable::portable>) noexcept {
  kutlog_portable::vector_t<T> lanes = self.data;
  lanes[I] = value;
  return lanes;
}

// ---- arithmetic ----------------------------------------------------------------------------
template <class A, class T>
inline batch<T, A> add(batch<T, A> const& self, batch<T, A> const& other,
                       requires_arch<kutlog_portable::portable>) noexcept {
  return self.data + other.data;
}
template <class A, class T>
inline batch<T, A> sub(batch<T, A> const& self, batch<T, A> const& other,
                       requires_arch<kutlog_portable::portable>) noexcept {
  return self.data - other.data;
}
template <class A, class T>
inline batch<T, A> mul(batch<T, A> const& self, batch<T, A> const& other,
                       requires_arch<kutlog_portable::portable>) noexcept {
  return self.data * other.data;
}
template <class A, class T>
inline batch<T, A> div(batch<T, A> const& self, batch<T, A> const& other,
                       requires_arch<kutlog_portable::portable>) noexcept {
  return self.data / other.data;
}
template <class A, class T>
inline batch<T, A> neg(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  return -self.data;
}
template <class A, class T, class = std::enable_if_t<std::is_floating_point_v<T>>>
inline batch<T, A> abs(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::each_lane<T>(self.data, [](T x) { return std::fabs(x); });
}
template <class A, class T>
inline batch<T, A> sqrt(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::each_lane<T>(self.data, [](T x) { return std::sqrt(x); });
}
// Exact (one division), where SIMD archs give a 12-bit estimate: the kernels refine it anyway.
template <class A, class T>
inline batch<T, A> reciprocal(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  return T(1) / self.data;
}
template <class A, class T>
inline batch<T, A> rsqrt(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  return T(1) / sqrt<A>(self, A{}).data;
}

// ---- bitwise -------------------------------------------------------------------------------
template <class A, class T>
inline batch<T, A> bitwise_and(batch<T, A> const& self, batch<T, A> const& other,
                               requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::from_bits<T>(kutlog_portable::bits<T>(self.data) &
                                       kutlog_portable::bits<T>(other.data));
}
template <class A, class T>
inline batch<T, A> bitwise_or(batch<T, A> const& self, batch<T, A> const& other,
                              requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::from_bits<T>(kutlog_portable::bits<T>(self.data) |
                                       kutlog_portable::bits<T>(other.data));
}
template <class A, class T>
inline batch<T, A> bitwise_xor(batch<T, A> const& self, batch<T, A> const& other,
                               requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::from_bits<T>(kutlog_portable::bits<T>(self.data) ^
                                       kutlog_portable::bits<T>(other.data));
}
// self & ~other, as xsimd defines it.
template <class A, class T>
inline batch<T, A> bitwise_andnot(batch<T, A> const& self, batch<T, A> const& other,
                                  requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::from_bits<T>(kutlog_portable::bits<T>(self.data) &
                                       ~kutlog_portable::bits<T>(other.data));
}
template <class A, class T>
inline batch<T, A> bitwise_not(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::from_bits<T>(~kutlog_portable::bits<T>(self.data));
}
template <class A, class T>
inline batch_bool<T, A> bitwise_and(batch_bool<T, A> const& self, batch_bool<T, A> const& other,
                                    requires_arch<kutlog_portable::portable>) noexcept {
  return self.data & other.data;
}
template <class A, class T>
inline batch_bool<T, A> bitwise_or(batch_bool<T, A> const& self, batch_bool<T, A> const& other,
                                   requires_arch<kutlog_portable::portable>) noexcept {
  return self.data | other.data;
}
template <class A, class T>
inline batch_bool<T, A> bitwise_xor(batch_bool<T, A> const& self, batch_bool<T, A> const& other,
                                    requires_arch<kutlog_portable::portable>) noexcept {
  return self.data ^ other.data;
}
template <class A, class T>
inline batch_bool<T, A> bitwise_andnot(batch_bool<T, A> const& self,
                                       batch_bool<T, A> const& other,
                                       requires_arch<kutlog_portable::portable>) noexcept {
  return self.data & ~other.data;
}
template <class A, class T>
inline batch_bool<T, A> bitwise_not(batch_bool<T, A> const& self,
                                    requires_arch<kutlog_portable::portable>) noexcept {
  return ~self.data;
}
template <class A, class T, class = std::enable_if_t<std::is_integral_v<T>>>
inline batch<T, A> bitwise_lshift(batch<T, A> const& self, int32_t other,
                                  requires_arch<kutlog_portable::portable>) noexcept {
  return self.data << other;
}
// Arithmetic for signed lanes, logical for unsigned ones, as C++ shifts.
template <class A, class T, class = std::enable_if_t<std::is_integral_v<T>>>
inline batch<T, A> bitwise_rshift(batch<T, A> const& self, int32_t other,
                                  requires_arch<kutlog_portable::portable>) noexcept {
  return self.data >> other;
}
template <class A, class T, class = std::enable_if_t<std::is_integral_v<T>>>
inline batch<T, A> bitwise_lshift(batch<T, A> const& self, batch<T, A> const& other,
                                  requires_arch<kutlog_portable::portable>) noexcept {
  return self.data << other.data;
}
template <class A, class T, class = std::enable_if_t<std::is_integral_v<T>>>
inline batch<T, A> bitwise_rshift(batch<T, A> const& self, batch<T, A> const& other,
                                  requires_arch<kutlog_portable::portable>) noexcept {
  return self.data >> other.data;
}
template <class A, class T, class To>
inline batch<To, A> bitwise_cast(batch<T, A> const& self, batch<To, A> const&,
                                 requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::same_bits<kutlog_portable::vector_t<To>>(self.data);
}
// A float lane's mask is an int32 lane's, a double's an int64's: the same register.
#define KUTLOG_PORTABLE_BOOL_CAST(From, To)                                           \
  template <class A>                                                                 \
  inline batch_bool<To, A> bool_cast(batch_bool<From, A> const& self,                \
                                     requires_arch<kutlog_portable::portable>) noexcept {      \
    return self.data;                                                                \
  }
KUTLOG_PORTABLE_BOOL_CAST(int32_t, float)
KUTLOG_PORTABLE_BOOL_CAST(float, int32_t)
KUTLOG_PORTABLE_BOOL_CAST(int64_t, double)
KUTLOG_PORTABLE_BOOL_CAST(double, int64_t)
#undef KUTLOG_PORTABLE_BOOL_CAST

// ---- comparisons and selection -------------------------------------------------------------
// The compiler's comparison gives a vector of the signed integer as wide as T (long or long
// long for 64-bit lanes, whichever it picks): cast to the one the mask register holds.
#define KUTLOG_PORTABLE_COMPARISON(name, op)                                             \
  template <class A, class T>                                                           \
  inline batch_bool<T, A> name(batch<T, A> const& self, batch<T, A> const& other,       \
                               requires_arch<kutlog_portable::portable>) noexcept {               \
    return kutlog_portable::same_bits<kutlog_portable::mask_t<T>>(self.data op other.data); \
  }
KUTLOG_PORTABLE_COMPARISON(eq, ==)
KUTLOG_PORTABLE_COMPARISON(neq, !=)
KUTLOG_PORTABLE_COMPARISON(lt, <)
KUTLOG_PORTABLE_COMPARISON(le, <=)
KUTLOG_PORTABLE_COMPARISON(gt, >)
KUTLOG_PORTABLE_COMPARISON(ge, >=)
#undef KUTLOG_PORTABLE_COMPARISON
template <class A, class T>
inline batch_bool<T, A> eq(batch_bool<T, A> const& self, batch_bool<T, A> const& other,
                           requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::same_bits<kutlog_portable::mask_t<T>>(self.data == other.data);
}
template <class A, class T>
inline batch_bool<T, A> neq(batch_bool<T, A> const& self, batch_bool<T, A> const& other,
                            requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::same_bits<kutlog_portable::mask_t<T>>(self.data != other.data);
}
template <class A, class T, class = std::enable_if_t<std::is_floating_point_v<T>>>
inline batch_bool<T, A> isnan(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::same_bits<kutlog_portable::mask_t<T>>(self.data != self.data);
}
template <class A, class T>
inline batch<T, A> select(batch_bool<T, A> const& condition, batch<T, A> const& if_true,
                          batch<T, A> const& if_false, requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::from_bits<T>((kutlog_portable::bits<T>(if_true.data) & condition.data) |
                                       (kutlog_portable::bits<T>(if_false.data) & ~condition.data));
}
// Like x86's minps and maxps (and what kutlog's clamps are written for): the second operand
// where either is NaN.
template <class A, class T>
inline batch<T, A> min(batch<T, A> const& self, batch<T, A> const& other,
                       requires_arch<kutlog_portable::portable>) noexcept {
  return select<A>(lt<A>(self, other, A{}), self, other, A{});
}
template <class A, class T>
inline batch<T, A> max(batch<T, A> const& self, batch<T, A> const& other,
                       requires_arch<kutlog_portable::portable>) noexcept {
  return select<A>(gt<A>(self, other, A{}), self, other, A{});
}
// In the current rounding mode, which kutlog's contracts require to be to-nearest: |x| plus
// 2^(mantissa bits) rounds away its fraction, and subtracting it again is exact; the sign of x
// goes back on (-0.4 gives -0). |x| at or above that is an integer already, or inf or NaN.
// Vector arithmetic, not std::nearbyint, a library call per lane.
template <class A, class T, class = std::enable_if_t<std::is_floating_point_v<T>>>
inline batch<T, A> nearbyint(batch<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  const batch<T, A> magnitude = abs<A>(self, A{}),
                    shift(T(std::uint64_t(1) << (std::numeric_limits<T>::digits - 1)));
  const batch<T, A> rounded = bitwise_or<A>((magnitude + shift) - shift, self ^ magnitude, A{});
  return select<A>(lt<A>(magnitude, shift, A{}), rounded, self, A{});
}
template <class A, class T>
inline bool all(batch_bool<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  for (std::size_t i = 0; i < batch<T, A>::size; ++i)
    if (!self.data[i]) return false;
  return true;
}
template <class A, class T>
inline bool any(batch_bool<T, A> const& self, requires_arch<kutlog_portable::portable>) noexcept {
  for (std::size_t i = 0; i < batch<T, A>::size; ++i)
    if (self.data[i]) return true;
  return false;
}

// ---- what kutlog does not call but xsimd's API names -----------------------------------------
// xsimd_api.hpp calls these by qualified name, so they must exist where xsimd itself has no arch
// to declare them; written lane by lane.
namespace kutlog_portable {
// self + other (or self - other), integers clamped to T's range where it overflows.
template <bool kSubtract, class A, class T>
inline batch<T, A> saturated(batch<T, A> const& self, batch<T, A> const& other) noexcept {
  if constexpr (std::is_floating_point_v<T>) {
    return kSubtract ? self.data - other.data : self.data + other.data;
  } else {
    vector_t<T> v;
    for (std::size_t i = 0; i < batch<T, A>::size; ++i) {
      T lane;
      const bool overflows = kSubtract ? __builtin_sub_overflow(self.data[i], other.data[i], &lane)
                                       : __builtin_add_overflow(self.data[i], other.data[i], &lane);
      if (overflows)
        lane = (other.data[i] > 0) != kSubtract ? std::numeric_limits<T>::max()
                                                : std::numeric_limits<T>::min();
      v[i] = lane;
    }
    return v;
  }
}
// The lanes of self and other interleaved, from lane `first` on (0: the low halves).
template <class A, class T>
inline batch<T, A> zipped(batch<T, A> const& self, batch<T, A> const& other,
                          std::size_t first) noexcept {
  vector_t<T> v;
  for (std::size_t i = 0; i < batch<T, A>::size / 2; ++i)
    v[2 * i] = self.data[first + i], v[2 * i + 1] = other.data[first + i];
  return v;
}
}  // namespace kutlog_portable
template <class A, class T>
inline batch<T, A> sadd(batch<T, A> const& self, batch<T, A> const& other,
                        requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::saturated<false>(self, other);
}
template <class A, class T>
inline batch<T, A> ssub(batch<T, A> const& self, batch<T, A> const& other,
                        requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::saturated<true>(self, other);
}
template <class A, class T>
inline batch<T, A> zip_lo(batch<T, A> const& self, batch<T, A> const& other,
                          requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::zipped(self, other, 0);
}
template <class A, class T>
inline batch<T, A> zip_hi(batch<T, A> const& self, batch<T, A> const& other,
                          requires_arch<kutlog_portable::portable>) noexcept {
  return kutlog_portable::zipped(self, other, batch<T, A>::size / 2);
}
// Lane i: the sum of row[i]'s lanes.
template <class A, class T>
inline batch<T, A> haddp(batch<T, A> const* row, requires_arch<kutlog_portable::portable>) noexcept {
  kutlog_portable::vector_t<T> v;
  for (std::size_t i = 0; i < batch<T, A>::size; ++i) {
    v[i] = row[i].data[0];
    for (std::size_t j = 1; j < batch<T, A>::size; ++j) v[i] += row[i].data[j];
  }
  return v;
}

// ---- conversions between integer and floating lanes of one width ----------------------------
// int32 <-> float and int64 <-> double: what C++'s conversions do, lane by lane (float to
// integer truncates, like cvttps2dq; out of range it is undefined, and xsimd calls it only in
// range).
namespace detail {
template <class A, class From, class To>
  requires(sizeof(From) == sizeof(To) && std::is_floating_point_v<From> != std::is_floating_point_v<To> &&
           std::is_signed_v<From> && std::is_signed_v<To>)
inline batch<To, A> fast_cast(batch<From, A> const& self, batch<To, A> const&,
                              requires_arch<kutlog_portable::portable>) noexcept {
  return __builtin_convertvector(self.data, kutlog_portable::vector_t<To>);
}
}  // namespace detail

}  // namespace kernel
}  // namespace xsimd

#endif  // KUTLOG_HAS_CXX20
