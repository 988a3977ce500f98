// kutlog-rasterizer: renders the Utah teapot with a z-buffer, perspective-correct normals and
// coef * F_kutlog shading per 16x16 tile through kutlog's stream API (kutlog::shade, coverage
// as the lane mask), on every core, and times that shading against pow-based Blinn-Phong
// (kutlog::blinn_phong_xsimd, xsimd::pow) from the same cosines. It also times the shape most
// software rasterizers have, a fragment function per pixel: kutlog's scalar Lobe::eval, and the
// same in C through kutlog/kutlog.h (fragment_shader.c), against powf. SHADING picks the path
// whose highlight the image shows: the C and C++ fragment paths give the same bits.
#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <kutlog/baselines.hpp>
#include <kutlog/kutlog.h>
#include <kutlog/lobe.hpp>
#include <kutlog/shade.hpp>
#include <optional>
#include <string_view>
#include <thread>
#include <vector>

#include "fragment_shader.h"  // the fragment function in C
#include "mesh.hpp"    // examples/common: the teapot
#include "raster.hpp"  // examples/common: camera and visibility pass

namespace {

using kutlog::examples::Camera;
using kutlog::examples::Mesh;
using kutlog::examples::Vec3;
using kutlog::examples::VisibilityBuffer;

constexpr int kTile = 16;
constexpr const char* kUsage =
    "usage: kutlog-rasterizer [WIDTH HEIGHT [FRAMES [OUTPUT [SHADING]]]]  (defaults 1920 1080 5 "
    "rasterizer.png stream; WIDTH, HEIGHT in [16, 16384], FRAMES in [1, 1000]; OUTPUT .png: "
    "8 bits, else (.exr, .tif) 32-bit float; SHADING stream, fragment or c: the highlight of "
    "kutlog::shade, of Lobe::eval per pixel, or of kutlog_eval per pixel in C)";

enum class Shading { stream, fragment, c };
std::optional<Shading> parse_shading(std::string_view text) {
  if (text == "stream") return Shading::stream;
  if (text == "fragment") return Shading::fragment;
  if (text == "c") return Shading::c;
  return std::nullopt;
}

struct TileInputs {
  std::array<float, kTile * kTile> t, n_dot_l;
  std::array<std::uint8_t, kTile * kTile> covered;
};

// The cosines N.H and N.L of a tile's pixels; covered[lane] says whether the pixel shows the
// mesh (and is inside the frame). Uncovered lanes get harmless values the mask skips anyway.
void gather_tile(const Mesh& mesh, const VisibilityBuffer& buffer, const Camera& camera,
                 Vec3 to_light, int tx, int ty, TileInputs& in) {
  for (int j = 0; j < kTile; ++j)
    for (int i = 0; i < kTile; ++i) {
      const int x = tx * kTile + i, y = ty * kTile + j, lane = j * kTile + i;
      const bool inside = x < buffer.width && y < buffer.height;
      const auto surface =
          inside ? kutlog::examples::surface_at(mesh, buffer, camera, std::size_t(y) * buffer.width + x)
                 : std::nullopt;
      in.covered[lane] = surface.has_value();
      in.t[lane] = in.n_dot_l[lane] = 0;
      if (!surface) continue;
      const Vec3 half = kutlog::examples::normalize(to_light + surface->to_viewer);
      in.t[lane] = dot(surface->normal, half);
      in.n_dot_l[lane] = dot(surface->normal, to_light);
    }
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// A whole decimal integer in [low, high], or nothing.
std::optional<int> parse_int(std::string_view text, int low, int high) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low || value > high)
    return std::nullopt;
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))) {
    std::printf("%s\n", kUsage);
    return 0;
  }
  const auto width = argc > 1 ? parse_int(argv[1], kTile, 16384) : 1920;
  const auto height = argc > 2 ? parse_int(argv[2], kTile, 16384) : 1080;
  const auto frames = argc > 3 ? parse_int(argv[3], 1, 1000) : 5;
  const auto shading = argc > 5 ? parse_shading(argv[5]) : Shading::stream;
  if (!width || !height || !frames || !shading || argc == 2 || argc > 6) {
    std::fprintf(stderr, "kutlog-rasterizer: error: %s\n", kUsage);
    return 2;
  }
  const char* output = argc > 4 ? argv[4] : "rasterizer.png";
  const float n = 1000;
  const kutlog::Lobe lobe(n, 3, 0.5);
  // The same lobe for the C path: its fragment handle, 32 bytes, evaluated inline in C.
  kutlog_lobe* c_lobe = nullptr;
  kutlog_fragment c_fragment;
  kutlog_error error;
  if (kutlog_lobe_create(n, 3, 0.5, &c_lobe, &error) != KUTLOG_OK ||
      kutlog_lobe_fragment(c_lobe, KUTLOG_EXACT_COEF, &c_fragment, &error) != KUTLOG_OK) {
    std::fprintf(stderr, "kutlog-rasterizer: error: %s\n", error.message);
    return 1;
  }
  const Mesh mesh = kutlog::examples::utah_teapot(64);  // 32 patches x 64 x 64 quads
  const Camera camera({0.75f, 0.6f, 1.75f}, {0, -0.04f, 0}, 0.7f, *width, *height);
  const Vec3 to_light = kutlog::examples::normalize({-0.5f, 1.0f, 0.7f});
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  const int tiles_x = (*width + kTile - 1) / kTile, tiles_y = (*height + kTile - 1) / kTile;

  const std::vector<Vec3> screen = kutlog::examples::project(mesh, camera);
  VisibilityBuffer buffer(*width, *height);
  std::vector<float> image(std::size_t(*width) * *height);
  std::vector<double> kutlog_ms, pow_ms, fragment_kutlog_ms, fragment_c_ms, fragment_powf_ms;
  // The fragment functions: the specular term of one pixel, coef F(N.H) max(N.L, 0) by the
  // scalar eval, against the normalized (N.H)^n max(N.L, 0) of pow-based Blinn-Phong.
  const float blinn_phong_coef = (n + 8) / (8 * 3.14159265f);
  kutlog::ShadeOptions normalized;
  normalized.normalization = kutlog::Normalization::exact_coef;
  // Most pixels lie past the lobe's cut, in runs along each scanline: a branch the CPU
  // predicts skips eval there (eval itself selects, for fragments in random order).
  const auto fragment_kutlog = [&lobe, t_cut = lobe.t_cut()](float t, float n_dot_l) {
    if (t <= t_cut) return 0.0f;
    return lobe.eval(t, kutlog::Variant::precise, kutlog::Normalization::exact_coef) *
           std::max(n_dot_l, 0.0f);
  };
  const auto fragment_powf = [n, blinn_phong_coef](float t, float n_dot_l) {
    return blinn_phong_coef * powf(std::max(t, 0.0f), n) * std::max(n_dot_l, 0.0f);
  };
  for (int f = 0; f < *frames; ++f) {
    buffer.clear();
    std::vector<std::thread> workers;
    const int rows = (*height + int(threads) - 1) / int(threads);
    for (unsigned w = 0; w < threads; ++w)
      workers.emplace_back([&, w] {
        kutlog::examples::rasterize(mesh, screen, buffer, int(w) * rows,
                                    std::min(*height, int(w + 1) * rows));
      });
    for (std::thread& worker : workers) worker.join();
    workers.clear();
    // Shading, tiles spread over the threads; each thread times its kernel calls only.
    std::vector<double> kutlog_seconds(threads), pow_seconds(threads),
        fragment_kutlog_seconds(threads), fragment_c_seconds(threads), fragment_powf_seconds(threads);
    for (unsigned w = 0; w < threads; ++w)
      workers.emplace_back([&, w] {
        TileInputs in;
        std::array<float, kTile * kTile> specular{}, baseline{}, fragment{}, fragment_c{},
            fragment_baseline{};
        for (int tile = int(w); tile < tiles_x * tiles_y; tile += int(threads)) {
          const int tx = tile % tiles_x, ty = tile / tiles_x;
          gather_tile(mesh, buffer, camera, to_light, tx, ty, in);
          const auto start = std::chrono::steady_clock::now();
          // Both from the same cosines: coef F(N.H) max(N.L, 0) against (N.H)^n max(N.L, 0).
          kutlog::shade(lobe, in.t.data(), in.n_dot_l.data(), specular.data(), specular.size(),
                        in.covered.data(), normalized);
          const auto middle = std::chrono::steady_clock::now();
          kutlog::blinn_phong_xsimd(in.t.data(), baseline.data(), baseline.size(), n);
          for (int lane = 0; lane < kTile * kTile; ++lane) baseline[lane] *= std::max(in.n_dot_l[lane], 0.0f);
          const auto end = std::chrono::steady_clock::now();
          kutlog_seconds[w] += std::chrono::duration<double>(middle - start).count();
          pow_seconds[w] += std::chrono::duration<double>(end - middle).count();
          // The shape most software rasterizers have: a fragment function per covered pixel,
          // kutlog's scalar eval against the powf it replaces.
          const auto fragment_start = std::chrono::steady_clock::now();
          for (int lane = 0; lane < kTile * kTile; ++lane)
            if (in.covered[lane]) fragment[lane] = fragment_kutlog(in.t[lane], in.n_dot_l[lane]);
          const auto fragment_c_start = std::chrono::steady_clock::now();
          shade_fragments_c(&c_fragment, in.t.data(), in.n_dot_l.data(), in.covered.data(),
                            fragment_c.data(), kTile * kTile);
          const auto fragment_middle = std::chrono::steady_clock::now();
          for (int lane = 0; lane < kTile * kTile; ++lane)
            if (in.covered[lane]) fragment_baseline[lane] = fragment_powf(in.t[lane], in.n_dot_l[lane]);
          const auto fragment_end = std::chrono::steady_clock::now();
          fragment_kutlog_seconds[w] +=
              std::chrono::duration<double>(fragment_c_start - fragment_start).count();
          fragment_c_seconds[w] +=
              std::chrono::duration<double>(fragment_middle - fragment_c_start).count();
          const std::array<float, kTile * kTile>& shown =
              *shading == Shading::stream ? specular
                                          : *shading == Shading::fragment ? fragment : fragment_c;
          fragment_powf_seconds[w] +=
              std::chrono::duration<double>(fragment_end - fragment_middle).count();
          for (int j = 0; j < kTile; ++j)
            for (int i = 0; i < kTile; ++i) {
              const int x = tx * kTile + i, y = ty * kTile + j, lane = j * kTile + i;
              if (x >= *width || y >= *height) continue;
              // A dark glossy glaze: diffuse 0.25 N.L plus the normalized highlight.
              image[std::size_t(y) * *width + x] =
                  in.covered[lane] ? 0.25f * std::max(in.n_dot_l[lane], 0.0f) + 0.04f * shown[lane] : 1.0f;
            }
        }
      });
    for (std::thread& worker : workers) worker.join();
    // Wall time of the shading kernels: the threads run them in parallel.
    kutlog_ms.push_back(1e3 * *std::max_element(kutlog_seconds.begin(), kutlog_seconds.end()));
    pow_ms.push_back(1e3 * *std::max_element(pow_seconds.begin(), pow_seconds.end()));
    fragment_kutlog_ms.push_back(
        1e3 * *std::max_element(fragment_kutlog_seconds.begin(), fragment_kutlog_seconds.end()));
    fragment_c_ms.push_back(
        1e3 * *std::max_element(fragment_c_seconds.begin(), fragment_c_seconds.end()));
    fragment_powf_ms.push_back(
        1e3 * *std::max_element(fragment_powf_seconds.begin(), fragment_powf_seconds.end()));
  }
  // The frame's bits, FNV-1a over every pixel's float: the C and C++ fragment paths print the
  // same digest (tests/CMakeLists.txt).
  std::uint64_t digest = 0xcbf29ce484222325u;
  for (const float pixel : image) {
    std::uint32_t bits;
    std::memcpy(&bits, &pixel, sizeof bits);
    for (int byte = 0; byte < 4; ++byte)
      digest = (digest ^ ((bits >> (8 * byte)) & 0xffu)) * 0x100000001b3u;
  }
  OIIO::ImageBuf out(OIIO::ImageSpec(*width, *height, 1, OIIO::TypeDesc::FLOAT), image.data());
  // For viewing: 2x / (1 + x), white at radiance 1.
  for (OIIO::ImageBuf::Iterator<float> it(out); !it.done(); ++it) it[0] = std::min(1.0f, 2 * it[0] / (1 + it[0]));
  const std::string_view name(output);
  const bool eight_bits = name.size() >= 4 && name.substr(name.size() - 4) == ".png";
  if (!out.write(output, eight_bits ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT)) {
    std::fprintf(stderr, "kutlog-rasterizer: error: %s\n", out.geterror().c_str());
    return 1;
  }
  std::printf("image digest: %016llx\n", static_cast<unsigned long long>(digest));
  const double k_ms = median(kutlog_ms), p_ms = median(pow_ms);
  std::printf("frame %dx%d, Utah teapot %zu triangles, %u threads, median of %d frames, wrote %s\n",
              *width, *height, mesh.triangles.size(), threads, *frames, output);
  std::printf("shading ms/frame: kutlog=%.3f pow_xsimd=%.3f ratio=%.2f\n", k_ms, p_ms, p_ms / k_ms);
  const double fk_ms = median(fragment_kutlog_ms), fc_ms = median(fragment_c_ms),
               fp_ms = median(fragment_powf_ms);
  std::printf("per-fragment shading ms/frame: kutlog=%.3f kutlog_c=%.3f powf=%.3f ratio=%.2f\n",
              fk_ms, fc_ms, fp_ms, fp_ms / fk_ms);
  kutlog_lobe_destroy(c_lobe);
  return 0;
}
