// The scalar path's pieces (kutlog/detail/lobe_kernel.hpp's ScalarPieces), for the setup of
// src/lobe.cpp. On each piece of the support, the cubic truncation of scale F's Chebyshev
// interpolant there, kept only when a bound on every error it can have, over every float t of
// the piece, meets the variant's promise:
//   approximation:  the dropped Chebyshev terms, and the aliasing the last ones tell;
//   coefficients:   each rounded to double, and moved where the range proof needs it;
//   Horner's rule:  gamma_6 sum |c_j u^j| (Higham), whether the caller's flags fuse or not;
//   input:          x = (1 - t) pieces_per_w, two roundings of x in double, and u = x - center;
//   output:         the rounding to float; near the cut, the zero piece's 0 against F there.
// The range proof: the computed cubic within [0, scale_f] after its rounding to float, over
// the whole piece, so that the evaluation needs no clamp.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "kutlog/lobe.hpp"
#include "lobe_bound.hpp"
#include "polynomial_fit.hpp"

namespace kutlog::detail {

class ScalarPiecesFitter {
 public:
  // More pieces fit closer, in a larger table (128 pieces are 8 KB) and a longer setup.
  static constexpr int kMinPieces = 8, kMaxPieces = 128;

  ScalarPiecesFitter(const LobeShape& shape, float t_cut) : shape_(shape), t_cut_(t_cut) {}

  struct Fitted {
    ScalarPieces pieces;
    CertifiedError certified;
  };
  // The fewest pieces (a power of two) whose bound meets the target, if any does.
  std::optional<Fitted> fit(double scale, const CertifiedError& target);

 private:
  // The support in equal pieces, unscaled: each normalization scales it.
  struct Cut {
    int pieces;
    double pieces_per_w;
    std::vector<std::array<Real, 4>> monomials;  // F on each piece, in u
    std::vector<double> truncation_error;        // of each piece's cubic
    std::vector<double> ends;                    // F at w = i / pieces_per_w, i <= pieces
    double zero_piece_error;  // F at the lowest w whose x can reach the zero piece
  };
  const Cut& cut(int pieces);
  // The pieces and their bound if it meets the target; else how far the worst piece missed.
  std::optional<Fitted> certify(const Cut& cut, double scale, const CertifiedError& target,
                                double& miss) const;
  double value(double w) const;  // F, continued a little past the cut-off

  LobeShape shape_;
  float t_cut_;
  std::vector<Cut> cuts_;  // by pieces, as asked for
};

}  // namespace kutlog::detail
