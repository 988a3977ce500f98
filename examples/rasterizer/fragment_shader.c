/* The rasterizer's fragment function in C, as a C renderer writes it where pow(N.H, n) was:
 * the normalized highlight coef F(N.H) max(N.L, 0) through kutlog/kutlog.h's inline
 * kutlog_eval, skipping the pixels past the lobe's cut on a branch (they come in runs along
 * each scanline). The C++ path (main.cpp, Lobe::eval) gives the same bits. */
#include "fragment_shader.h"

void shade_fragments_c(const kutlog_fragment* lobe, const float* t, const float* n_dot_l,
                       const unsigned char* covered, float* specular, int count) {
  const kutlog_fragment local = *lobe; /* in registers across the loop */
  int i;
  for (i = 0; i < count; ++i) {
    if (!covered[i]) continue;
    specular[i] = t[i] <= local.t_cut
                      ? 0.0f
                      : kutlog_eval(&local, t[i]) * (n_dot_l[i] < 0.0f ? 0.0f : n_dot_l[i]);
  }
}
