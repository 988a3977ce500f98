// The scalar path's pieces (kutlog/detail/lobe_kernel.hpp's PiecewisePolynomial: cubics in
// double for the precise variant, quadratics in float for the fast one), for the setup of
// src/lobe.cpp. On each piece of the support, the truncation of scale F's Chebyshev
// interpolant there, kept only when a bound on every error it can have, over every float t of
// the piece, meets the variant's promise; the terms add up as the array kernels' do
// (PieceBudget, src/lobe_bound.hpp):
//   approximation:  the dropped Chebyshev terms, and the aliasing the last ones tell;
//   coefficients:   each rounded to the table's type, and moved where the range proof needs it;
//   Horner's rule:  horner_bound (src/lobe_bound.hpp), whether the caller's flags fuse or not;
//   input:          x = (1 - t) pieces_per_w, its roundings times the polynomial's slope;
//   output:         the rounding to float of the double table; near the cut, the zero piece's
//                   0 against F there.
// The range proof: the computed value within [0, scale_f] after any rounding to float, over
// the whole piece, so that the evaluation needs no clamp.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "kutlog/lobe.hpp"
#include "lobe_bound.hpp"
#include "polynomial_fit.hpp"

namespace kutlog::detail {

class ScalarPiecesFitter {
 public:
  // More pieces fit closer, in a larger table (128 double cubics are 8 KB) and a longer setup.
  static constexpr int kMinPieces = 8, kMaxPieces = 128;

  ScalarPiecesFitter(const LobeShape& shape, float t_cut) : shape_(shape), t_cut_(t_cut) {}

  template <class Pieces>
  struct Fitted {
    Pieces pieces;
    CertifiedError certified;
  };
  // The fewest pieces (a power of two) whose bound meets the target, if any does.
  template <class Pieces>
  std::optional<Fitted<Pieces>> fit(double scale, const CertifiedError& target);

 private:
  // The support in equal pieces, unscaled: each variant and normalization takes its terms.
  struct Cut {
    int pieces;
    double pieces_per_w;                        // exact, rounded by each table to its type
    std::vector<ChebyshevSeries> series;        // F on each piece, f = x - piece in [0, 1]
    std::vector<double> ends;                   // F at w = i / pieces_per_w, i <= pieces
    // Each piece's truncation to a degree as monomials, by degree, when first asked for (both
    // normalizations scale the same ones).
    std::array<std::vector<std::vector<Real>>, 4> monomials;
  };
  // The cut with its monomials of that degree.
  const Cut& cut(int pieces, std::size_t degree);
  // The table and its bound if it meets the target; else how far it missed (infinite: no
  // count of pieces can meet it).
  template <class Pieces>
  std::optional<Fitted<Pieces>> certify(const Cut& cut, double scale,
                                        const CertifiedError& target, double& miss) const;
  // What every piece of one table's certification shares.
  struct PieceInputs {
    double x_error;     // of the computed x, absolute
    double ceiling;     // a computed value below it is at most scale_f as a float
    double last_f_end;  // where the last piece's floats end, in its f
  };
  // Fits piece i of the table (its polynomial and center) and bounds its error, absolute; or
  // nothing if its range cannot be proven.
  template <class Pieces>
  std::optional<double> certify_piece(const Cut& cut, int i, double scale,
                                      const PieceInputs& inputs,
                                      typename Pieces::Piece& piece) const;
  Cut new_cut(int pieces) const;
  double value(double w) const;  // F, continued a little past the cut-off

  LobeShape shape_;
  float t_cut_;
  std::vector<Cut> cuts_;  // by pieces, as asked for
};

}  // namespace kutlog::detail
