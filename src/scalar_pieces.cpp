#include "scalar_pieces.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <type_traits>

#include "kutlog/detail/float_ulp.hpp"
#include "kutlog/detail/integer_power.hpp"
#include "fixed_math.hpp"

namespace kutlog::detail {
namespace {

// Nodes of each piece's interpolant: its terms past the table's degree bound the truncation,
// the last four (times 4) what the interpolation aliased, as F's terms decay geometrically.
constexpr int kNodes = 10;
// The values at the nodes are doubles, a few ulps each: a floor under every bound.
constexpr Real kValueNoise = 0x1p-50L;

// Piece 0 is expanded about its start, where t = 1 gives u = 0 and the output scale_f exactly;
// the others about their middle, where |u| <= 1/2 shrinks Horner's error.
double local_center(int piece) { return piece == 0 ? 0.0 : 0.5; }

template <std::size_t kTerms>
double magnitude(const std::array<double, kTerms>& c, double u_bound) {  // sum |c_j| u_bound^j
  double sum = 0;
  for (std::size_t j = kTerms; j-- > 0;) sum = sum * u_bound + std::fabs(c[j]);
  return sum;
}

struct Range {
  double lo, hi;
};
// The polynomial's exact range over u in [u_lo, u_hi]: its ends and where its slope vanishes
// (degree 3 at most), in long double, widened by that arithmetic's own error.
template <std::size_t kTerms>
Range polynomial_range(const std::array<double, kTerms>& c, Real u_lo, Real u_hi) {
  static_assert(kTerms <= 4);
  const auto at = [&](Real u) {
    Real sum = 0;
    for (std::size_t j = kTerms; j-- > 0;) sum = sum * u + Real(c[j]);
    return sum;
  };
  Real lo = std::min(at(u_lo), at(u_hi)), hi = std::max(at(u_lo), at(u_hi));
  const auto consider = [&](Real u) {
    if (u > u_lo && u < u_hi) lo = std::min(lo, at(u)), hi = std::max(hi, at(u));
  };
  // The slope c1 + 2 c2 u + 3 c3 u^2 = 0.
  const Real a = kTerms > 3 ? 3 * Real(c[3]) : 0, b = kTerms > 2 ? 2 * Real(c[2]) : 0;
  const Real d = kTerms > 1 ? Real(c[1]) : 0;
  if (a == 0) {
    if (b != 0) consider(-d / b);
  } else if (const Real discriminant = b * b - 4 * a * d; discriminant >= 0) {
    consider((-b + std::sqrt(discriminant)) / (2 * a));
    consider((-b - std::sqrt(discriminant)) / (2 * a));
  }
  const double margin = 0x1p-58 * magnitude(c, 1);
  return {double(lo) - margin, double(hi) + margin};
}


// A piece's polynomial as the table stores it, in double, on u in [u_lo, u_hi].
template <class Type, std::size_t kTerms>
struct PiecePolynomial {
  static constexpr bool kInDouble = std::is_same_v<Type, double>;
  static constexpr double kUnit = kInDouble ? kDoubleUnit : kFloatUnit;
  std::array<double, kTerms> c;
  double u_lo, u_hi;

  // Horner's rule's roundings, fused or not, as the caller's flags compile it.
  double horner() const {
    return horner_bound(c, {u_lo, u_hi}, Rounding{!kInDouble}, true).error;
  }
  // At the peak, piece 0 (u >= 0): where the rest of Horner's rule, r(u) = c1 + c2 u + ...,
  // is below 0 with its roundings, the computed u r(u) <= 0 and c0 + u r(u) rounds to at most
  // c0 = scale: the peak is proven without the bound's slack.
  bool peak_proven() const {
    std::array<double, kTerms - 1> rest;
    for (std::size_t j = 0; j + 1 < kTerms; ++j) rest[j] = c[j + 1];
    const double rest_error = horner_bound(rest, {0, u_hi}, Rounding{!kInDouble}, true).error;
    return polynomial_range(rest, 0, u_hi).hi + rest_error < 0;
  }
  // The range proof: the computed value within [0, ceiling) over the piece.
  bool within(const Range& range, double ceiling, bool at_peak) const {
    return range.lo - horner() >= 0 &&
           ((at_peak && peak_proven()) || range.hi + horner() < ceiling);
  }
  // Moves c[0] where the range proof needs it; how far, or nothing if the proof still fails.
  // `range` becomes the polynomial's range.
  std::optional<double> prove_range(double ceiling, bool at_peak, Range& range) {
    range = polynomial_range(c, u_lo, u_hi);
    const double before = c[0];
    if (range.lo - horner() < 0)
      c[0] = double(Type(c[0] + (horner() - range.lo) * (1 + 0x1p-20) +
                         4 * kUnit * std::fabs(c[0]) + 0x1p-140));
    else if (!within(range, ceiling, at_peak))
      c[0] = double(Type(c[0] - (range.hi + horner() - ceiling) * (1 + 0x1p-20) -
                         4 * kUnit * std::fabs(c[0])));
    if (c[0] != before) range = polynomial_range(c, u_lo, u_hi);
    if (!within(range, ceiling, at_peak)) return std::nullopt;
    return std::fabs(c[0] - before);
  }
  // |p'(u)| over the piece.
  double slope() const {
    const double u_bound = std::max(-u_lo, u_hi);
    double slope = 0;
    for (std::size_t j = kTerms - 1; j >= 1; --j)
      slope = slope * u_bound + double(j) * std::fabs(c[j]);
    return slope;
  }
};

// x = (1 - t) pieces_per_w, as the pieces' evaluation computes it.
template <class Type>
Type x_of(float t, Type pieces_per_w) {
  return (Type(1) - Type(std::min(t, 1.0f))) * pieces_per_w;
}

}  // namespace

double ScalarPiecesFitter::value(double w) const {
  return integer_power(shape_.base(w), shape_.k);  // past the cut, the base's sign k times
}

const ScalarPiecesFitter::Cut& ScalarPiecesFitter::cut(int pieces, std::size_t degree) {
  auto existing = std::find_if(cuts_.begin(), cuts_.end(),
                               [&](const Cut& c) { return c.pieces == pieces; });
  if (existing == cuts_.end()) existing = cuts_.insert(cuts_.end(), new_cut(pieces));
  std::vector<std::vector<Real>>& monomials = existing->monomials[degree];
  for (int i = int(monomials.size()); i < pieces; ++i)
    monomials.push_back(
        existing->series[std::size_t(i)].monomials(int(degree), local_center(i)));
  return *existing;
}

ScalarPiecesFitter::Cut ScalarPiecesFitter::new_cut(int pieces) const {
  Cut cut;
  cut.pieces = pieces;
  cut.pieces_per_w = pieces / (1.0 - double(t_cut_));
  for (int i = 0; i < pieces; ++i)
    cut.series.push_back(chebyshev_interpolant(
        [&](Real f) { return Real(value(double((i + f) / cut.pieces_per_w))); }, 0, 1, kNodes));
  for (int i = 0; i <= pieces; ++i) cut.ends.push_back(value(i / cut.pieces_per_w));
  return cut;
}

template <class Pieces>
std::optional<double> ScalarPiecesFitter::certify_piece(const Cut& cut, int i, double scale,
                                                        const PieceInputs& inputs,
                                                        typename Pieces::Piece& piece) const {
  using Type = std::remove_cvref_t<decltype(Pieces::pieces_per_w)>;
  constexpr std::size_t kDegree = Pieces::degree;
  using Polynomial = PiecePolynomial<Type, kDegree + 1>;
  Polynomial p{{}, -local_center(i), 0};
  p.u_hi = (i == cut.pieces - 1 ? inputs.last_f_end : 1.0) + p.u_lo;
  const std::vector<Real>& monomials = cut.monomials[kDegree][std::size_t(i)];
  std::array<Real, kDegree + 1> exact;
  for (std::size_t j = 0; j <= kDegree; ++j) {
    exact[j] = scale * monomials[j];
    p.c[j] = double(Type(exact[j]));  // the table's, exactly
  }
  double coefficients = coefficient_rounding(exact, p.c, std::max(-p.u_lo, p.u_hi));
  if (i == 0) {  // the peak, t >= 1, exactly what the kernels return there: scale_f
    coefficients += double(std::fabs(scale * monomials[0] - Real(Type(scale))));
    p.c[0] = double(Type(scale));
  }
  Range range;
  const std::optional<double> moved = p.prove_range(inputs.ceiling, i == 0, range);
  if (!moved) return std::nullopt;
  const PieceBudget budget{scale * cut.series[std::size_t(i)].truncation_error(int(kDegree), kValueNoise),
                           coefficients, *moved, p.horner(), p.slope() * inputs.x_error};
  for (std::size_t j = 0; j <= kDegree; ++j) piece.polynomial[j] = Type(p.c[j]);
  piece.center = Type(i + local_center(i));
  return budget.total() + (Polynomial::kInDouble ? Rounding{true}(range.hi + p.horner()) : 0.0);
}

template <class Pieces>
std::optional<ScalarPiecesFitter::Fitted<Pieces>> ScalarPiecesFitter::certify(
    const Cut& cut, double scale, const CertifiedError& target, double& miss) const {
  using Type = std::remove_cvref_t<decltype(Pieces::pieces_per_w)>;
  constexpr bool kInDouble = std::is_same_v<Type, double>;
  const int count = cut.pieces;
  Fitted<Pieces> fitted;
  Pieces& pieces = fitted.pieces;
  // Every t <= t_cut in the zero piece: x(t_cut) at least count, computed.
  pieces.pieces_per_w = Type(cut.pieces_per_w);
  while (x_of(t_cut_, pieces.pieces_per_w) < Type(count))
    pieces.pieces_per_w = std::nextafter(pieces.pieces_per_w, Type(INFINITY));
  PieceInputs inputs;
  // x against w cut.pieces_per_w: off by the table's pieces_per_w and two roundings (1 - t
  // is exact from t = 1/2 up).
  inputs.x_error = (count + 1) * (std::fabs(double(pieces.pieces_per_w) / cut.pieces_per_w - 1) +
                                  2.01 * (kInDouble ? kDoubleUnit : kFloatUnit));
  pieces.table.assign(std::size_t(count) + 1, {});
  pieces.table.back().center = Type(count);  // the zero piece: its u is finite
  const float scale_f = float(scale);
  // A computed value below this is at most scale_f as a float.
  inputs.ceiling =
      kInDouble ? double(scale_f) + 0.5 * (double(std::nextafter(scale_f, INFINITY)) - scale_f)
                : double(std::nextafter(scale_f, INFINITY));
  // The last piece's floats end at the float above t_cut: past it, between the cut-off and
  // t_cut, F continued is negative (k odd), and no float is there.
  inputs.last_f_end = std::clamp(
      double(x_of(std::nextafter(t_cut_, 2.0f), pieces.pieces_per_w)) - (count - 1), 0.0, 1.0);
  CertifiedError& certified = fitted.certified;
  certified = {0, 0};
  // Near the cut, a t whose x reaches the zero piece: w above (count - x_error) / pieces_per_w.
  certified.take_piece(
      scale * std::max(0.0, value((count - inputs.x_error) / cut.pieces_per_w)), scale, 0);
  for (int i = 0; i < count; ++i) {
    const std::optional<double> error =
        certify_piece<Pieces>(cut, i, scale, inputs, pieces.table[std::size_t(i)]);
    if (!error) return std::nullopt;
    const bool in_epicenter = cut.ends[std::size_t(i)] >= kEpicenter;  // where the piece starts
    certified.take_piece(
        *error, scale,
        in_epicenter ? scale * std::max(kEpicenter, cut.ends[std::size_t(i) + 1]) * (1 - 0x1p-40)
                     : 0);
  }
  // Every piece's, so that the next try's count is not underestimated from the first miss.
  miss = std::max(certified.abs_error / target.abs_error,
                  certified.epicenter_ulp / target.epicenter_ulp);
  if (miss > 1) return std::nullopt;
  return fitted;
}

template <class Pieces>
std::optional<ScalarPiecesFitter::Fitted<Pieces>> ScalarPiecesFitter::fit(
    double scale, const CertifiedError& target) {
  int pieces = kMinPieces;
  while (pieces <= kMaxPieces) {
    double miss = INFINITY;
    if (auto fitted = certify<Pieces>(cut(pieces, Pieces::degree), scale, target, miss))
      return fitted;
    // The error falls as pieces^-(degree + 1): the counts that cannot meet the target are
    // skipped (all of them past kMaxPieces, as where the zero piece alone misses).
    const double needed = 1.3 * pieces * fixed::pow(miss, 1.0 / double(Pieces::degree + 1));
    if (!(needed <= kMaxPieces)) return std::nullopt;
    pieces = std::max(2 * pieces, int(std::bit_ceil(unsigned(needed))));
  }
  return std::nullopt;
}

template std::optional<ScalarPiecesFitter::Fitted<detail::ScalarPieces>>
ScalarPiecesFitter::fit<detail::ScalarPieces>(double, const CertifiedError&);
template std::optional<ScalarPiecesFitter::Fitted<detail::FastScalarPieces>>
ScalarPiecesFitter::fit<detail::FastScalarPieces>(double, const CertifiedError&);

}  // namespace kutlog::detail
