#include "scalar_pieces.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "kutlog/detail/float_ulp.hpp"
#include "kutlog/detail/integer_power.hpp"

namespace kutlog::detail {
namespace {

constexpr double kDoubleUnit = 0x1p-53;
// Horner's rule on a cubic, three multiplies and three adds: gamma_6 = 6 u / (1 - 6 u).
constexpr double kHornerGamma = 6 * kDoubleUnit / (1 - 6 * kDoubleUnit);
// Where the ulp bound applies: F >= 0.6 (kutlog/lobe.hpp).
constexpr double kEpicenter = 0.6;
// Nodes of each piece's interpolant: its terms past the cubic bound the truncation, the last
// four (times 4) what the interpolation aliased, as F's terms decay geometrically.
constexpr int kNodes = 10;
// The values at the nodes are doubles, a few ulps each: a floor under every bound.
constexpr double kValueNoise = 0x1p-50;

using Cubic = std::array<double, 4>;

// Piece 0 is expanded about its start, where t = 1 gives u = 0 and the output scale_f exactly;
// the others about their middle, where |u| <= 1/2 halves Horner's error.
double local_center(int piece) { return piece == 0 ? 0.0 : 0.5; }

// sum_j |c_j| |u|^j for |u| <= bound: Horner's rounding error over gamma_6.
double magnitude(const Cubic& c, double bound) {
  return std::fabs(c[0]) + bound * (std::fabs(c[1]) + bound * (std::fabs(c[2]) + bound * std::fabs(c[3])));
}

struct Range {
  double lo, hi;
};
// The cubic's exact range over u in [u_lo, u_hi]: its ends and where its slope vanishes, in
// long double, widened by that arithmetic's own error.
Range cubic_range(const Cubic& c, Real u_lo, Real u_hi) {
  const auto at = [&](Real u) {
    return ((Real(c[3]) * u + Real(c[2])) * u + Real(c[1])) * u + Real(c[0]);
  };
  Real lo = std::min(at(u_lo), at(u_hi)), hi = std::max(at(u_lo), at(u_hi));
  const auto consider = [&](Real u) {
    if (u > u_lo && u < u_hi) lo = std::min(lo, at(u)), hi = std::max(hi, at(u));
  };
  // c1 + 2 c2 u + 3 c3 u^2 = 0.
  const Real a = 3 * Real(c[3]), b = 2 * Real(c[2]), d = c[1];
  if (a == 0) {
    if (b != 0) consider(-d / b);
  } else if (const Real discriminant = b * b - 4 * a * d; discriminant >= 0) {
    consider((-b + std::sqrt(discriminant)) / (2 * a));
    consider((-b - std::sqrt(discriminant)) / (2 * a));
  }
  const double margin = 0x1p-58 * magnitude(c, 1);
  return {double(lo) - margin, double(hi) + margin};
}

}  // namespace

double ScalarPiecesFitter::value(double w) const {
  return integer_power(shape_.base(w), shape_.k);  // past the cut, the base's sign k times
}

const ScalarPiecesFitter::Cut& ScalarPiecesFitter::cut(int pieces) {
  for (const Cut& existing : cuts_)
    if (existing.pieces == pieces) return existing;
  Cut cut;
  cut.pieces = pieces;
  // x(t_cut) at least pieces, exactly as evaluate computes it: every t <= t_cut in the zero
  // piece.
  const double w_cut = 1.0 - double(t_cut_);
  cut.pieces_per_w = pieces / w_cut;
  while (w_cut * cut.pieces_per_w < pieces)
    cut.pieces_per_w = std::nextafter(cut.pieces_per_w, INFINITY);
  for (int i = 0; i < pieces; ++i) {
    const std::vector<Real> chebyshev = chebyshev_coefficients(
        [&](Real f) { return Real(value(double((i + f) / cut.pieces_per_w))); }, 0, 1, kNodes);
    double dropped = 0, last = 0, total = 0;
    for (int j = 0; j < kNodes; ++j) {
      const double magnitude = double(std::fabs(chebyshev[j]));
      total += magnitude;
      if (j > 3) dropped += magnitude;
      if (j >= kNodes - 4) last += magnitude;
    }
    cut.truncation_error.push_back(dropped + 4 * last + kValueNoise * total);
    const std::vector<Real> monomials =
        monomials_from_chebyshev(chebyshev, 3, 0, 1, local_center(i));
    cut.monomials.push_back({monomials[0], monomials[1], monomials[2], monomials[3]});
  }
  for (int i = 0; i <= pieces; ++i) cut.ends.push_back(value(i / cut.pieces_per_w));
  // x's two roundings move it by at most (pieces + 1) 2^-52: a t whose x reaches the zero
  // piece has w above pieces / pieces_per_w (1 - 2^-50), where F is at most this.
  cut.zero_piece_error =
      std::max(0.0, value(pieces / cut.pieces_per_w * (1 - 0x1p-50)));
  cuts_.push_back(std::move(cut));
  return cuts_.back();
}

std::optional<ScalarPiecesFitter::Fitted> ScalarPiecesFitter::certify(
    const Cut& cut, double scale, const CertifiedError& target, double& miss) const {
  Fitted fitted;
  fitted.pieces.t_cut = t_cut_;
  fitted.pieces.pieces_per_w = cut.pieces_per_w;
  fitted.pieces.table.assign(std::size_t(cut.pieces) + 1, {});
  fitted.pieces.table.back().center = cut.pieces;  // the zero piece: its u is finite
  const float scale_f = float(scale);
  // A double below this rounds to at most scale_f.
  const double ceiling =
      double(scale_f) + 0.5 * (double(std::nextafter(scale_f, INFINITY)) - double(scale_f));
  double abs_error = scale * cut.zero_piece_error, epicenter_ulp = 0;
  // The last piece's floats end at the float above t_cut: past it, between the cut-off and
  // t_cut, F continued is negative (k odd), and no float is there.
  const double x_end = (1.0 - double(std::nextafter(t_cut_, 2.0f))) * cut.pieces_per_w;
  const double last_f_end = std::clamp(x_end * (1 + 0x1p-51) - (cut.pieces - 1), 0.0, 1.0);
  for (int i = 0; i < cut.pieces; ++i) {
    const double u_lo = -local_center(i);
    const double u_hi = (i == cut.pieces - 1 ? last_f_end : 1.0) + u_lo;
    const double u_bound = std::max(-u_lo, u_hi);
    Cubic c;
    double coefficient_error = 0;
    for (int j = 0; j < 4; ++j) {
      const Real exact = scale * cut.monomials[i][j];
      c[j] = double(exact);
      coefficient_error += double(std::fabs(exact - Real(c[j])) + 0x1p-60L * std::fabs(exact)) *
                           std::pow(u_bound, j);
    }
    if (i == 0) {  // the peak, t >= 1, exactly what the kernels return there: scale_f
      coefficient_error += double(std::fabs(scale * cut.monomials[0][0] - Real(scale)));
      c[0] = scale;
    }
    const auto horner = [&] { return kHornerGamma * magnitude(c, u_bound); };
    // The range proof: the computed value within [0, ceiling), c[0] moved if it is not.
    Range range = cubic_range(c, u_lo, u_hi);
    const double before = c[0];
    if (range.lo - horner() < 0)
      c[0] += (horner() - range.lo) * (1 + 0x1p-20) + 0x1p-1000;
    else if (range.hi + horner() >= ceiling)
      c[0] -= (range.hi + horner() - ceiling) * (1 + 0x1p-20) + 0x1p-20 * horner();
    if (c[0] != before) {
      range = cubic_range(c, u_lo, u_hi);
      if (range.lo - horner() < 0 || range.hi + horner() >= ceiling) return std::nullopt;
    }
    const double moved = std::fabs(c[0] - before);
    // u off by x's two roundings, (pieces + 1) 2^-52, and by u's own (x - center: exact but
    // in piece 0), times the cubic's slope.
    const double slope =
        std::fabs(c[1]) + u_bound * (2 * std::fabs(c[2]) + 3 * u_bound * std::fabs(c[3]));
    const double input = slope * ((cut.pieces + 1) * 0x1p-51 + 0x1p-53);
    const double unrounded =
        scale * cut.truncation_error[i] + coefficient_error + moved + horner() + input;
    const double error = unrounded + 0.5 * ulp_of_float(range.hi + horner());
    abs_error = std::max(abs_error, error);
    if (cut.ends[i] >= kEpicenter) {  // the piece starts in the epicenter
      const double lowest = scale * std::max(kEpicenter, cut.ends[i + 1]) * (1 - 0x1p-40);
      epicenter_ulp = std::max(epicenter_ulp, error / ulp_of_float(lowest));
    }
    fitted.pieces.table[std::size_t(i)] = {c, i + local_center(i)};
  }
  fitted.certified = {abs_error / scale, epicenter_ulp};
  // Every piece's, so that the next try's count is not underestimated from the first miss.
  miss = std::max(fitted.certified.abs_error / target.abs_error,
                  epicenter_ulp / target.epicenter_ulp);
  if (miss > 1) return std::nullopt;
  return fitted;
}

std::optional<ScalarPiecesFitter::Fitted> ScalarPiecesFitter::fit(double scale,
                                                                  const CertifiedError& target) {
  int pieces = kMinPieces;
  while (pieces <= kMaxPieces) {
    double miss = INFINITY;
    if (std::optional<Fitted> fitted = certify(cut(pieces), scale, target, miss)) return fitted;
    // The cubic's error falls as pieces^-4: the counts that cannot meet the target are skipped
    // (all of them past kMaxPieces, as where the zero piece alone misses).
    const double needed = 1.3 * pieces * std::pow(miss, 0.25);
    if (!(needed <= kMaxPieces)) return std::nullopt;
    pieces = std::max(2 * pieces, int(std::bit_ceil(unsigned(needed))));
  }
  return std::nullopt;
}

}  // namespace kutlog::detail
