#include "common/pathtrace.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>

namespace kutlog::pathtrace {
namespace {

constexpr double kPi = ref::pi;

// The shading frame about a unit normal: the orthonormal basis of Duff et al. 2017.
struct Frame {
  Vec3 tangent, bitangent, normal;

  explicit Frame(const Vec3& n) : normal(n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1 / (sign + n.z), b = n.x * n.y * a;
    tangent = {1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    bitangent = {b, sign + n.y * n.y * a, -n.y};
  }
  Vec3 to_local(const Vec3& v) const {
    return {ref::dot(v, tangent), ref::dot(v, bitangent), ref::dot(v, normal)};
  }
  Vec3 to_world(const Vec3& v) const {
    return {v.x * tangent.x + v.y * bitangent.x + v.z * normal.x,
            v.x * tangent.y + v.y * bitangent.y + v.z * normal.y,
            v.x * tangent.z + v.y * bitangent.z + v.z * normal.z};
  }
};

// The sky: the sun up and to the left, in front of the sphere, so that its highlight faces
// the camera. Its angular radius, 0.15 rad, is twice the angle (0.074 rad) at which the
// n = 1000 lobe's reflected directions fall to half: a narrower disc leaves most of its
// highlight where the lobe overlaps it in part, where BRDF sampling, whichever, is a coin toss
// between 0 and the disc (light sampling's case); this one leaves a highlight that lobe
// sampling resolves and uniform sampling finds once in 89 draws at best. Its radiance makes
// it about four fifths of the light that reaches a surface facing it, as a clear day's sun is.
const Vec3 kToSun = unit({-0.45, 0.55, 0.7});
const double kSunCosRadius = 0x1.fa4033e5ee937p-1;  // cos(0.15), written out as libm's may vary
constexpr Rgb kSun{100, 94, 80};
constexpr Rgb kHorizon{0.85, 0.9, 1.0}, kZenith{0.2, 0.4, 0.9};
constexpr Rgb kGroundLight{0.4, 0.33, 0.25}, kGroundDark{0.08, 0.07, 0.06};
constexpr double kGroundDepth = 1.0;  // below the camera; the checker's squares are 1 wide

// The camera: a pinhole on +z looking at the unit sphere at the origin.
constexpr double kCameraDistance = 3.5;
// tan(19 pi / 180): 38 degrees vertically, written out as libm's may vary
const double kHalfFieldTangent = 0x1.60976af8c1612p-2;

// A reproducible random stream per pixel: SplitMix64's finalizer mixes (seed, pixel) into
// the seed of a std::mt19937_64.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A double uniform in [0, 1): the top 53 bits.
double uniform_double(std::mt19937_64& random) { return double(random() >> 11) * 0x1.0p-53; }

}  // namespace

Vec3 unit(const Vec3& v) {
  const double length = std::sqrt(ref::dot(v, v));
  return {v.x / length, v.y / length, v.z / length};
}

Environment Environment::sky() { return Environment(false); }
Environment Environment::white() { return Environment(true); }

Rgb Environment::radiance(const Vec3& direction) const {
  if (white_) return {1, 1, 1};
  if (ref::dot(direction, kToSun) > kSunCosRadius) return kSun;
  if (direction.y < 0) {
    // The ground plane seen from the sphere's height: a checker of unit squares.
    const double distance = kGroundDepth / -direction.y;
    const auto square = std::floor(direction.x * distance) + std::floor(direction.z * distance);
    return std::fmod(std::fabs(square), 2.0) < 1 ? kGroundLight : kGroundDark;
  }
  const double t = std::sqrt(direction.y);  // the gradient changes fastest near the horizon
  return {kHorizon.r + t * (kZenith.r - kHorizon.r), kHorizon.g + t * (kZenith.g - kHorizon.g),
          kHorizon.b + t * (kZenith.b - kHorizon.b)};
}

std::string_view sampler_name(Sampler sampler) {
  return sampler == Sampler::lobe ? "lobe" : "uniform";
}

std::string_view sampler_label(Sampler sampler) {
  return sampler == Sampler::lobe ? "F_kutlog lobe" : "uniform hemisphere";
}

std::optional<ref::DirectionSample> draw_direction(const Material& material, Sampler sampler,
                                                   const Vec3& wo, double u1, double u2) {
  if (sampler == Sampler::lobe) {
    const SampledDirection wm = material.sampler().sample(float(u1), float(u2), material.variant());
    return material.brdf().reflect(wo, {{wm.x, wm.y, wm.z}, wm.pdf});
  }
  const double cos_theta = u1, sin_theta = std::sqrt(std::max(0.0, 1 - u1 * u1));
  const double phi = 2 * kPi * u2;
  return ref::DirectionSample{{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta},
                              1 / (2 * kPi)};
}

Rgb estimate_reflected(const Material& material, Sampler sampler,
                       const Environment& environment, const Vec3& normal, const Vec3& wo,
                       double u1, double u2) {
  const Frame frame(normal);
  const Vec3 wo_local = frame.to_local(wo);
  const auto wi = draw_direction(material, sampler, wo_local, u1, u2);
  if (!wi || !(wi->pdf > 0)) return {};
  const double weight = material.eval(wo_local, wi->direction) * wi->direction.z / wi->pdf;
  if (weight == 0) return {};  // the environment lookup would only be multiplied by 0
  return weight * environment.radiance(frame.to_world(wi->direction));
}

double Material::eval(const Vec3& wo, const Vec3& wi) const {
  if (variant_ != Variant::deterministic) return brdf_.eval(wo, wi);
  // The reference's D G / (4 cos(theta_i) cos(theta_o)), D by the lobe's deterministic eval.
  if (!(wo.z > 0) || !(wi.z > 0)) return 0;
  const Vec3 wm = unit({wo.x + wi.x, wo.y + wi.y, wo.z + wi.z});
  const double D =
      double(lobe_.eval(float(wm.z), Variant::deterministic, Normalization::exact_coef));
  return D * ref::vcavity_shadowing(wm.z, wi.z, wo.z, ref::dot(wo, wm)) / (4 * wi.z * wo.z);
}

Image::Image(int width, int height)
    : width(width), height(height), pixels(std::size_t(width) * height),
      covered(std::size_t(width) * height) {}

std::vector<Image> render(const Scene& scene, Sampler sampler, std::uint64_t seed,
                          const std::vector<int>& spp_checkpoints, int threads) {
  if (scene.width < 1 || scene.height < 1)
    throw std::invalid_argument("image size: width and height must be >= 1");
  if (spp_checkpoints.empty() || spp_checkpoints.front() < 1 ||
      std::adjacent_find(spp_checkpoints.begin(), spp_checkpoints.end(), std::greater_equal<>()) !=
          spp_checkpoints.end())
    throw std::invalid_argument("samples per pixel: checkpoints must be >= 1 and increasing");
  if (threads < 1) throw std::invalid_argument("threads: must be >= 1");
  std::vector<Image> images(spp_checkpoints.size(), Image(scene.width, scene.height));
  const double aspect = double(scene.width) / scene.height;
  const Vec3 eye{0, 0, kCameraDistance};

  const auto render_pixel = [&](int column, int row) {
    const double x = ((2.0 * column + 1) / scene.width - 1) * kHalfFieldTangent * aspect;
    const double y = (1 - (2.0 * row + 1) / scene.height) * kHalfFieldTangent;
    const Vec3 direction = unit({x, y, -1});
    // |eye + s direction| = 1, the nearer root.
    const double half_b = ref::dot(eye, direction);
    const double discriminant = half_b * half_b - (ref::dot(eye, eye) - 1);
    if (discriminant <= 0) {
      for (Image& image : images) image.at(column, row) = scene.environment.radiance(direction);
      return;
    }
    const double distance = -half_b - std::sqrt(discriminant);
    const Vec3 normal = unit({eye.x + distance * direction.x, eye.y + distance * direction.y,
                              eye.z + distance * direction.z});
    const Vec3 wo{-direction.x, -direction.y, -direction.z};
    std::mt19937_64 random(mix(seed ^ mix(std::uint64_t(row) * scene.width + column + 1)));
    Rgb sum;
    std::size_t next = 0;
    for (int sample = 1; sample <= spp_checkpoints.back(); ++sample) {
      const double u1 = uniform_double(random), u2 = uniform_double(random);
      sum += estimate_reflected(scene.material, sampler, scene.environment, normal, wo, u1, u2);
      if (sample == spp_checkpoints[next]) {
        images[next].at(column, row) = (1.0 / sample) * sum;
        images[next].covered[std::size_t(row) * scene.width + column] = 1;
        ++next;
      }
    }
  };
  const auto render_rows = [&](int first_row) {
    for (int row = first_row; row < scene.height; row += threads)
      for (int column = 0; column < scene.width; ++column) render_pixel(column, row);
  };
  {
    std::vector<std::jthread> workers;  // joined at the end of this scope, before the return
    for (int first_row = 1; first_row < threads; ++first_row)
      workers.emplace_back(render_rows, first_row);
    render_rows(0);
  }
  return images;
}

double rmse(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height ||
      image.covered != reference.covered)
    throw std::invalid_argument("rmse: the images must have the same size and coverage");
  double sum_of_squares = 0;
  std::size_t values = 0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (!image.covered[i]) continue;
    const Rgb& a = image.pixels[i];
    const Rgb& b = reference.pixels[i];
    sum_of_squares += (a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) + (a.b - b.b) * (a.b - b.b);
    values += 3;
  }
  return values ? std::sqrt(sum_of_squares / values) : 0;
}

}  // namespace kutlog::pathtrace
