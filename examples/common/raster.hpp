// The visibility pass of the example renderers: a pinhole camera, and a z-buffer rasterizer
// that keeps, per pixel, the nearest triangle and its perspective-correct barycentric
// coordinates, from which the surface's position and interpolated normal follow. Shading is
// not here: it is what the renderers hand to kutlog's stream API.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "mesh.hpp"

namespace kutlog::examples {

struct Camera {
  Vec3 eye, forward, right, up;
  float focal;  // in pixels
  float center_x, center_y;

  Camera(Vec3 eye_at, Vec3 target, float vertical_fov_radians, int width, int height)
      : eye(eye_at),
        forward(normalize(target - eye_at)),
        right(normalize(cross(forward, {0, 1, 0}))),
        up(cross(right, forward)),
        focal(0.5f * float(height) / std::tan(0.5f * vertical_fov_radians)),
        center_x(0.5f * float(width)),
        center_y(0.5f * float(height)) {}

  // Pixel coordinates (y down) and 1/depth; 1/depth <= 0 behind the camera.
  Vec3 project(Vec3 p) const {
    const Vec3 d = p - eye;
    const float depth = dot(d, forward);
    return {center_x + focal * dot(d, right) / depth, center_y - focal * dot(d, up) / depth, 1 / depth};
  }
};

// Per pixel: the nearest triangle (-1 for none), 1/depth, and the perspective-correct
// barycentric weights of its 2nd and 3rd vertices.
struct VisibilityBuffer {
  int width = 0, height = 0;
  std::vector<float> inverse_depth, b1, b2;
  std::vector<int> triangle;

  VisibilityBuffer(int w, int h) : width(w), height(h) { clear(); }
  void clear() {
    const std::size_t pixels = std::size_t(width) * height;
    inverse_depth.assign(pixels, 0), b1.assign(pixels, 0), b2.assign(pixels, 0);
    triangle.assign(pixels, -1);
  }
};

// Every vertex of the mesh through the camera.
inline std::vector<Vec3> project(const Mesh& mesh, const Camera& camera) {
  std::vector<Vec3> screen;
  screen.reserve(mesh.position.size());
  for (const Vec3& p : mesh.position) screen.push_back(camera.project(p));
  return screen;
}

// Rasterizes every triangle into the rows [row_begin, row_end) of the buffer, sampling at
// pixel centres; rows split the work across threads. Both faces are drawn: the teapot is not
// closed (the spout's mouth shows its inside), and the renderers light the side facing the
// viewer.
inline void rasterize(const Mesh& mesh, const std::vector<Vec3>& screen, VisibilityBuffer& buffer,
                      int row_begin, int row_end) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [i0, i1, i2] = mesh.triangles[t];
    const Vec3 a = screen[i0], b = screen[i1], c = screen[i2];
    if (a.z <= 0 || b.z <= 0 || c.z <= 0) continue;  // behind the camera (no clipping)
    const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0) continue;
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(buffer.width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(row_begin, int(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(row_end - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const float px = float(x) + 0.5f, py = float(y) + 0.5f;
        const float w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
        const float w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
        const float w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const float inverse_depth = w0 * a.z + w1 * b.z + w2 * c.z;  // linear on the screen
        const std::size_t p = std::size_t(y) * buffer.width + x;
        if (inverse_depth <= buffer.inverse_depth[p]) continue;
        buffer.inverse_depth[p] = inverse_depth;
        buffer.triangle[p] = int(t);
        buffer.b1[p] = w1 * b.z / inverse_depth;  // screen weights -> surface weights
        buffer.b2[p] = w2 * c.z / inverse_depth;
      }
  }
}

// What a pixel shows: the surface point, its unit normal turned towards the viewer, and the
// unit vector to the viewer. Nothing where no triangle covers the pixel.
struct SurfacePoint {
  Vec3 position, normal, to_viewer;
};

inline std::optional<SurfacePoint> surface_at(const Mesh& mesh, const VisibilityBuffer& buffer,
                                              const Camera& camera, std::size_t pixel) {
  if (buffer.triangle[pixel] < 0) return std::nullopt;
  const auto [i0, i1, i2] = mesh.triangles[buffer.triangle[pixel]];
  const float b1 = buffer.b1[pixel], b2 = buffer.b2[pixel], b0 = 1 - b1 - b2;
  SurfacePoint s;
  s.position = b0 * mesh.position[i0] + b1 * mesh.position[i1] + b2 * mesh.position[i2];
  s.normal = normalize(b0 * mesh.normal[i0] + b1 * mesh.normal[i1] + b2 * mesh.normal[i2]);
  s.to_viewer = normalize(camera.eye - s.position);
  if (dot(s.normal, s.to_viewer) < 0) s.normal = -1.0f * s.normal;  // an inside seen from outside
  return s;
}

}  // namespace kutlog::examples
