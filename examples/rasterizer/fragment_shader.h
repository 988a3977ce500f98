/* examples/rasterizer/fragment_shader.c: the fragment function compiled as C. */
#ifndef KUTLOG_EXAMPLE_FRAGMENT_SHADER_H
#define KUTLOG_EXAMPLE_FRAGMENT_SHADER_H

#include <kutlog/kutlog.h>

#ifdef __cplusplus
extern "C" {
#endif
/* specular[i] = coef F(t[i]) max(n_dot_l[i], 0) where covered[i], for a fragment handle of
 * KUTLOG_EXACT_COEF; uncovered lanes are left as they are. */
void shade_fragments_c(const kutlog_fragment* lobe, const float* t, const float* n_dot_l,
                       const unsigned char* covered, float* specular, int count);
#ifdef __cplusplus
}
#endif

#endif
