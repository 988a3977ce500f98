// A small path tracer that shows what importance sampling the F_kutlog lobe buys: a glossy
// sphere (kutlog's normalized microfacet BRDF, white) lit by an environment, its reflected
// light estimated by BRDF sampling two ways, the lobe's own sampler or uniform hemisphere
// directions, each an unbiased estimate of the same image.
//
// The object is a sphere because it is convex: no reflected ray meets it again, so direct
// lighting from the environment is the whole light transport and no ray-object test is needed
// beyond the camera's. kutlog and the standard library only (the images are the tool's).
// Directions come from kutlog's SIMD LobeSampler, as a renderer would draw them; the
// reference BRDF (the spec) weighs them.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "kutlog/sampling.hpp"
#include "kutlog/sampling_reference.hpp"

namespace kutlog::pathtrace {

using ref::Vec3;

struct Rgb {
  double r = 0, g = 0, b = 0;

  Rgb& operator+=(const Rgb& other) {
    r += other.r, g += other.g, b += other.b;
    return *this;
  }
  friend Rgb operator*(double scale, const Rgb& c) { return {scale * c.r, scale * c.g, scale * c.b}; }
};

// v / |v|.
Vec3 unit(const Vec3& v);

// Radiance arriving from infinitely far away, by direction (world frame: y up, the camera on
// +z looking down -z).
class Environment {
 public:
  // A sky gradient, a checkered ground below the horizon and a small, very bright sun: the
  // sun and the checker edges are the high-frequency features that make sampling matter.
  static Environment sky();
  // Radiance 1 from everywhere: the white furnace, where the reflected radiance is the BRDF's
  // directional albedo.
  static Environment white();

  Rgb radiance(const Vec3& direction) const;

 private:
  explicit Environment(bool white) : white_(white) {}
  bool white_;
};

// The sphere's material: the reference BRDF and a LobeSampler of the same n, k, Q. With
// Variant::deterministic, the sampler's deterministic mode and D by Lobe::eval's: with the
// rest in double IEEE operations compiled unfused, the image has the same bits on every CPU.
class Material {
 public:
  // std::invalid_argument naming the parameter, as the reference's.
  Material(double n, int k, double Q, Variant variant = Variant::precise)
      : brdf_(n, k, Q), sampler_(n, k, Q, LobeUse::microfacet), lobe_(n, k, Q),
        variant_(variant) {}
  const ref::KutlogMicrofacet& brdf() const { return brdf_; }
  const LobeSampler& sampler() const { return sampler_; }
  Variant variant() const { return variant_; }
  // f(wo, wi) in the local frame: the reference's, or with D from the deterministic lobe.
  double eval(const Vec3& wo, const Vec3& wi) const;

 private:
  ref::KutlogMicrofacet brdf_;
  LobeSampler sampler_;
  Lobe lobe_;
  Variant variant_;
};

// How the direction of each sample is drawn. kSamplers drives the tool's images, CSV columns
// and labels.
enum class Sampler { lobe, uniform };
inline constexpr Sampler kSamplers[] = {Sampler::lobe, Sampler::uniform};
// "lobe" or "uniform": the CSV column suffix.
std::string_view sampler_name(Sampler sampler);
// How the images' labels name it: "F_kutlog lobe", "uniform hemisphere".
std::string_view sampler_label(Sampler sampler);

// One direction wi for the outgoing direction wo, both in the local shading frame (z the
// normal), from the uniform numbers u1, u2 in [0, 1): the material's LobeSampler, its half
// vector reflected by the reference (no direction where the reflection falls below the
// horizon, which the estimate weighs 0), or uniform over the hemisphere (pdf 1 / (2 pi)).
std::optional<ref::DirectionSample> draw_direction(const Material& material, Sampler sampler,
                                                   const Vec3& wo, double u1, double u2);

// One sample's estimate f(wo, wi) L(wi) cos(theta_i) / pdf(wi) of the radiance reflected
// towards wo (a unit vector, world frame) at a point of unit normal `normal`.
Rgb estimate_reflected(const Material& material, Sampler sampler,
                       const Environment& environment, const Vec3& normal, const Vec3& wo,
                       double u1, double u2);

struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;              // row-major, top row first
  std::vector<std::uint8_t> covered;    // 1 where the sphere is, 0 on the background

  Image(int width, int height);
  Rgb& at(int column, int row) { return pixels[std::size_t(row) * width + column]; }
  const Rgb& at(int column, int row) const { return pixels[std::size_t(row) * width + column]; }
};

struct Scene {
  const Material& material;
  const Environment& environment;
  int width, height;
};

// Renders the scene with `sampler`, one camera ray through each pixel's centre (so that the
// images differ only by the sampling of reflected light) and spp_checkpoints.back() samples per
// pixel; returns the running mean at each number of samples in spp_checkpoints (strictly
// increasing, >= 1). Pixels draw from their own random streams, seeded by (seed, pixel): the
// images do not depend on `threads` (rows are shared out among that many std::threads).
// std::invalid_argument for a size below 1, empty or not strictly increasing checkpoints,
// threads < 1.
std::vector<Image> render(const Scene& scene, Sampler sampler, std::uint64_t seed,
                          const std::vector<int>& spp_checkpoints, int threads);

// The root-mean-square difference over the covered pixels' three channels (the background is
// the environment itself, the same in every image). std::invalid_argument for images of
// different sizes or coverage.
double rmse(const Image& image, const Image& reference);

}  // namespace kutlog::pathtrace
