// The examples' mesh and visibility pass (examples/common), which kutlog-render and the
// example rasterizer share: the teapot is oriented outwards with exact unit normals, and the
// rasterizer covers what a triangle covers, with perspective-correct weights.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh.hpp"
#include "raster.hpp"

namespace kutlog::examples {
namespace {

TEST(UtahTeapot, HasTwoTrianglesPerQuadOfEveryPatch) {
  for (int subdivisions : {1, 4, 16}) {
    const Mesh mesh = utah_teapot(subdivisions);
    EXPECT_EQ(mesh.triangles.size(), std::size_t(32 * 2 * subdivisions * subdivisions));
    EXPECT_EQ(mesh.position.size(), std::size_t(32 * (subdivisions + 1) * (subdivisions + 1)));
    EXPECT_EQ(mesh.normal.size(), mesh.position.size());
  }
  EXPECT_THROW(utah_teapot(0), std::invalid_argument);
}

TEST(UtahTeapot, IsOneTallAndCentred) {
  const Mesh mesh = utah_teapot(16);
  float low = 1e9f, high = -1e9f, left = 1e9f, right = -1e9f;
  for (const Vec3& p : mesh.position) {
    low = std::min(low, p.y), high = std::max(high, p.y);
    left = std::min(left, p.x), right = std::max(right, p.x);
  }
  EXPECT_NEAR(low, -0.5f, 1e-6f);  // the bottom (z = 0) and the knob (z = 3.15)
  EXPECT_NEAR(high, 0.5f, 1e-6f);
  EXPECT_NEAR(left + right, 0.0f, 1e-3f);  // handle to spout, centred
}

// Orientation: the divergence theorem gives a positive volume only if the triangles face out;
// each triangle's own normal must agree with its vertices' exact normals.
TEST(UtahTeapot, FacesOutwardWithUnitNormalsThatAgreeWithTheTriangles) {
  const Mesh mesh = utah_teapot(32);
  double volume = 0;
  int disagreeing = 0;
  for (const auto& [i0, i1, i2] : mesh.triangles) {
    const Vec3 a = mesh.position[i0], b = mesh.position[i1], c = mesh.position[i2];
    volume += dot(a, cross(b, c)) / 6.0;
    const Vec3 face = cross(b - a, c - a);
    if (dot(face, face) < 1e-14f) continue;  // collapsed at the knob's and bottom's poles
    if (dot(face, mesh.normal[i0] + mesh.normal[i1] + mesh.normal[i2]) <= 0) ++disagreeing;
  }
  EXPECT_GT(volume, 0.1);  // a body of about 0.5 x 1 x 1.3 (the lid's gap keeps it open)
  EXPECT_EQ(disagreeing, 0);
  for (const Vec3& n : mesh.normal) ASSERT_NEAR(dot(n, n), 1.0f, 1e-5f);
}

// A square of side 1 facing the camera at distance 2, seen with a 90-degree field of view in a
// 200 x 200 frame, covers 50 x 50 pixels; its centre pixel shows its centre.
TEST(Rasterize, CoversTheProjectedAreaWithPerspectiveCorrectWeights) {
  Mesh square;
  square.position = {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
  square.normal.assign(4, Vec3{0, 0, 1});
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const float pi = 3.14159265f;
  const Camera camera({0, 0, 2}, {0, 0, 0}, pi / 2, 200, 200);
  VisibilityBuffer buffer(200, 200);
  rasterize(square, project(square, camera), buffer, 0, 200);
  int covered = 0;
  for (int t : buffer.triangle) covered += t >= 0;
  EXPECT_EQ(covered, 50 * 50);
  const auto center = surface_at(square, buffer, camera, 100 * 200 + 100);
  ASSERT_TRUE(center.has_value());
  // Pixel centre (100.5, 100.5): half a pixel right of the axis, a pixel being 2 / 100 wide.
  EXPECT_NEAR(center->position.x, 0.01f, 1e-5f);
  EXPECT_NEAR(center->position.y, -0.01f, 1e-5f);
  EXPECT_NEAR(center->normal.z, 1.0f, 1e-6f);
  EXPECT_FALSE(surface_at(square, buffer, camera, 0).has_value());
}

// Tilted away, the square's far half shrinks on screen: linear screen-space weights would put
// the surface point of a pixel in the wrong place; perspective-correct ones do not.
TEST(Rasterize, InterpolatesInPerspective) {
  Mesh plane;
  plane.position = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -3}, {-1, 0, -3}};
  plane.normal.assign(4, Vec3{0, 1, 0});
  plane.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Camera camera({0, 1, 2}, {0, 0, -1}, 1.2f, 160, 160);
  VisibilityBuffer buffer(160, 160);
  rasterize(plane, project(plane, camera), buffer, 0, 160);
  int checked = 0;
  for (std::size_t p = 0; p < buffer.triangle.size(); ++p) {
    const auto s = surface_at(plane, buffer, camera, p);
    if (!s) continue;
    // The surface point must lie on the ray through the pixel centre.
    const Vec3 projected = camera.project(s->position);
    EXPECT_NEAR(projected.x, float(p % 160) + 0.5f, 2e-3f);
    EXPECT_NEAR(projected.y, float(p / 160) + 0.5f, 2e-3f);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace kutlog::examples
