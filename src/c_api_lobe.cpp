// The C API's calls on one lobe that need no kernel table (kutlog/kutlog.h): create, destroy,
// its parameters and its fragment handles. Apart from src/c_api.cpp, so that a C program that
// only evaluates fragments links what a C++ one calling Lobe::eval does.
#include <cstdint>
#include <type_traits>

#include "c_api_boundary.hpp"
#include "kutlog/detail/inspector.hpp"
#include "scalar_kernel.hpp"

using namespace kutlog::c_api;

namespace {

// A lobe's fragment handle (precise or fast, by Fragment): its pieces and fallback kernel.
template <class Fragment>
kutlog_status fill_fragment(const kutlog_lobe* lobe, kutlog_normalization normalization,
                            Fragment* fragment, kutlog_error* error) {
  return guarded(error, [&] {
    if (const kutlog_status status =
            Check(error).handle(lobe, "lobe").handle(fragment, "fragment").normalization(
                normalization))
      return status;
    constexpr bool kFast = std::is_same_v<Fragment, kutlog_fast_fragment>;
    const kutlog::Normalization chosen = kutlog::Normalization(normalization);
    const auto& pieces = [&]() -> const auto& {
      if constexpr (kFast) return kutlog::detail::Inspector::fast_pieces(lobe->lobe, chosen);
      else return kutlog::detail::Inspector::precise_pieces(lobe->lobe, chosen);
    }();
    const kutlog::detail::LobeKernel& kernel =
        kutlog::detail::Inspector::kernel(
            lobe->lobe, kutlog::detail::Inspector::index(
                            kFast ? kutlog::Variant::fast : kutlog::Variant::precise, chosen,
                            kutlog::detail::Arithmetic::scalar));
    *fragment = {pieces.table.empty() ? nullptr : pieces.table.data(), &kernel,
                 pieces.pieces_per_w, std::uint32_t(pieces.table.size() - 1), lobe->lobe.t_cut()};
    return KUTLOG_OK;
  });
}
template <class Fragment>
float kernel_eval(const Fragment* fragment, float t) {
  if (!fragment || !fragment->kernel) return kNaN;
  return kutlog::detail::evaluate_scalar_kernel(
      *static_cast<const kutlog::detail::LobeKernel*>(fragment->kernel), t);
}

}  // namespace

extern "C" {

kutlog_status kutlog_lobe_create(double n, int k, double Q, kutlog_lobe** lobe,
                                 kutlog_error* error) {
  return create(lobe, error, n, k, Q);
}
void kutlog_lobe_destroy(kutlog_lobe* lobe) { delete lobe; }
double kutlog_lobe_coef_exact(const kutlog_lobe* lobe) {
  return lobe ? lobe->lobe.coef_exact() : std::numeric_limits<double>::quiet_NaN();
}
float kutlog_lobe_t_cut(const kutlog_lobe* lobe) { return lobe ? lobe->lobe.t_cut() : kNaN; }

kutlog_status kutlog_lobe_fragment(const kutlog_lobe* lobe, kutlog_normalization normalization,
                                   kutlog_fragment* fragment, kutlog_error* error) {
  return fill_fragment(lobe, normalization, fragment, error);
}
kutlog_status kutlog_lobe_fast_fragment(const kutlog_lobe* lobe,
                                        kutlog_normalization normalization,
                                        kutlog_fast_fragment* fragment, kutlog_error* error) {
  return fill_fragment(lobe, normalization, fragment, error);
}
float kutlog_fragment_kernel_eval(const kutlog_fragment* fragment, float t) {
  return kernel_eval(fragment, t);
}
float kutlog_fast_fragment_kernel_eval(const kutlog_fast_fragment* fragment, float t) {
  return kernel_eval(fragment, t);
}

float kutlog_lobe_eval(const kutlog_lobe* lobe, float t, kutlog_variant variant,
                       kutlog_normalization normalization) {
  if (!lobe || !valid_variant(variant) || !valid_normalization(normalization)) return kNaN;
  return lobe->lobe.eval(t, kutlog::Variant(variant), kutlog::Normalization(normalization));
}

}  // extern "C"
