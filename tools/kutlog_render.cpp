// kutlog-render: lit spheres with the lobes side by side, and a heatmap of where F_kutlog and
// Blinn-Phong differ. PNG for viewing, EXR for the linear values. The kutlog panels are shaded
// by the library's stream API (kutlog::shade), with the sphere's coverage as the lane mask.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "common/cli.hpp"
#include "common/plot.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/shade.hpp"

namespace {

namespace iba = OIIO::ImageBufAlgo;

// One row of the sphere seen from +z (orthographic), as the stream API's SoA vectors.
struct SphereRow {
  std::vector<float> nx, ny, nz, lx, ly, lz, vx, vy, vz, n_dot_h;
  std::vector<std::uint8_t> covered;
};

SphereRow sphere_row(int row, int size, const kutlog::ref::Vec3& light) {
  SphereRow r;
  const double length = std::sqrt(light.x * light.x + light.y * light.y + light.z * light.z);
  for (int column = 0; column < size; ++column) {
    const double x = (2.0 * column + 1) / size - 1, y = 1 - (2.0 * row + 1) / size;
    const double rr = x * x + y * y;
    const bool inside = rr < 1;
    const double z = inside ? std::sqrt(1 - rr) : 0;
    r.nx.push_back(float(x)), r.ny.push_back(float(y)), r.nz.push_back(float(z));
    r.lx.push_back(float(light.x / length)), r.ly.push_back(float(light.y / length));
    r.lz.push_back(float(light.z / length));
    r.vx.push_back(0), r.vy.push_back(0), r.vz.push_back(1);
    r.n_dot_h.push_back(float(kutlog::ref::blinn_cosine({x, y, z}, {light.x / length, light.y / length, light.z / length}, {0, 0, 1})));
    r.covered.push_back(inside);
  }
  return r;
}

// Radiance of a grey dielectric-ish material under a white light of irradiance 1:
// diffuse 0.5/pi N.L plus the specular term (already times N.L) scaled by `specular_scale`.
float radiance(float n_dot_l, float specular, float specular_scale) {
  return 0.5f / float(kutlog::ref::pi) * std::max(n_dot_l, 0.0f) + specular_scale * specular;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Render lit spheres with the lobes side by side (Blinn-Phong, F_kutlog, coef * F_kutlog,\n"
      "Schlick), and a heatmap of |F_kutlog - Blinn-Phong|. Writes PREFIX.png, PREFIX.exr\n"
      "(linear) and PREFIX-heatmap.png.",
      "kutlog-render");
  std::string prefix;
  int size = 384, k = 3;
  double n = 100, Q = 0.5;
  std::vector<double> light{-0.5, 0.6, 0.8};
  app.add_option("--output,-o", prefix, "Output path prefix")->required();
  app.add_option("--size", size, "Panel size in pixels")->check(CLI::Range(16, 4096))->capture_default_str();
  app.add_option("--n", n, "Exponent n (real > 0)")->capture_default_str();
  app.add_option("--k", k, "Power k (integer >= 1)")->capture_default_str();
  app.add_option("--q", Q, "Anchor Q in (0, 1)")->capture_default_str();
  app.add_option("--light", light, "Direction to the light x,y,z")->delimiter(',')->expected(3)->capture_default_str();
  return kutlog::tools::run_tool(app, argc, argv, [&] {
    const kutlog::Lobe lobe(n, k, Q);  // validates n, k, Q
    const kutlog::ref::Vec3 to_light{light[0], light[1], light[2]};
    if (!(light[2] > 0)) throw std::invalid_argument("--light: z must be > 0 (above the sphere's rim)");
    const char* font = kutlog::tools::label_font();
    constexpr int kPanels = 4, kLabelHeight = 40;
    const char* labels[kPanels] = {"Blinn-Phong cos^n", "F_kutlog", "coef * F_kutlog (0.04)", "Schlick"};
    const int width = kPanels * size, height = size + kLabelHeight;
    OIIO::ImageBuf linear(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBuf heat(OIIO::ImageSpec(size + 160, size + kLabelHeight, 3, OIIO::TypeDesc::FLOAT));
    iba::fill(linear, {1.0f, 1.0f, 1.0f});
    iba::fill(heat, {1.0f, 1.0f, 1.0f});
    std::vector<float> error(std::size_t(size) * size, 0.0f);
    std::vector<float> power(size), kutlog_f(size), kutlog_normalized(size), schlick(size), n_dot_l(size);
    for (int row = 0; row < size; ++row) {
      const SphereRow r = sphere_row(row, size, to_light);
      const kutlog::Vectors normal{r.nx.data(), r.ny.data(), r.nz.data()},
          to_l{r.lx.data(), r.ly.data(), r.lz.data()}, to_v{r.vx.data(), r.vy.data(), r.vz.data()};
      std::fill(kutlog_f.begin(), kutlog_f.end(), 0.0f);
      std::fill(kutlog_normalized.begin(), kutlog_normalized.end(), 0.0f);
      kutlog::ShadeOptions plain;
      plain.normalization = kutlog::Normalization::none;
      kutlog::shade(lobe, normal, to_l, to_v, kutlog_f.data(), size, r.covered.data(), plain);
      kutlog::shade(lobe, normal, to_l, to_v, kutlog_normalized.data(), size, r.covered.data());
      kutlog::blinn_phong_u10(r.n_dot_h.data(), power.data(), size, float(n));
      kutlog::schlick(r.n_dot_h.data(), schlick.data(), size, float(n));
      for (int column = 0; column < size; ++column) {
        if (!r.covered[column]) continue;
        n_dot_l[column] = r.nx[column] * r.lx[column] + r.ny[column] * r.ly[column] + r.nz[column] * r.lz[column];
        const float nl = std::max(n_dot_l[column], 0.0f);
        const float values[kPanels] = {radiance(nl, power[column] * nl, 0.8f),
                                       radiance(nl, kutlog_f[column], 0.8f),
                                       radiance(nl, kutlog_normalized[column], 0.04f),
                                       radiance(nl, schlick[column] * nl, 0.8f)};
        for (int panel = 0; panel < kPanels; ++panel) {
          const float v[3] = {values[panel], values[panel], values[panel]};
          linear.setpixel(panel * size + column, kLabelHeight + row, v);
        }
        error[std::size_t(row) * size + column] = std::fabs(kutlog_f[column] - power[column] * nl);
      }
    }
    for (int panel = 0; panel < kPanels; ++panel)
      iba::render_text(linear, panel * size + 10, 28, labels[panel], 20, font, {0.0f, 0.0f, 0.0f});
    if (!linear.write(prefix + ".exr")) throw std::runtime_error(linear.geterror());
    // For viewing: 2x / (1 + x), a Reinhard curve reaching white at radiance 1 (the labels'
    // white background stays white), clipped above.
    OIIO::ImageBuf display = linear;
    for (OIIO::ImageBuf::Iterator<float> it(display); !it.done(); ++it)
      for (int c = 0; c < 3; ++c) it[c] = std::min(1.0f, 2 * it[c] / (1 + it[c]));
    if (!display.write(prefix + ".png", OIIO::TypeDesc::UINT8)) throw std::runtime_error(display.geterror());

    // Heatmap: |F_kutlog - cos^n| (specular times N.L), black -> red -> yellow, with a bar.
    const float max_error = std::max(*std::max_element(error.begin(), error.end()), 1e-6f);
    const auto ramp = [](float u, float rgb[3]) {
      rgb[0] = std::min(1.0f, 2 * u), rgb[1] = std::clamp(2 * u - 1, 0.0f, 1.0f), rgb[2] = 0.15f * (1 - u);
    };
    float rgb[3];
    for (int row = 0; row < size; ++row)
      for (int column = 0; column < size; ++column) {
        ramp(error[std::size_t(row) * size + column] / max_error, rgb);
        heat.setpixel(column, kLabelHeight + row, rgb);
      }
    for (int row = 0; row < size; ++row) {
      ramp(1 - float(row) / float(size - 1), rgb);
      for (int column = size + 20; column < size + 45; ++column) heat.setpixel(column, kLabelHeight + row, rgb);
    }
    char text[64];
    std::snprintf(text, sizeof text, "%.2g", max_error);
    iba::render_text(heat, size + 50, kLabelHeight + 14, text, 16, font, {0.0f, 0.0f, 0.0f});
    iba::render_text(heat, size + 50, kLabelHeight + size, "0", 16, font, {0.0f, 0.0f, 0.0f});
    std::snprintf(text, sizeof text, "|F_kutlog - cos^n| (n=%g, k=%d, Q=%g)", n, k, Q);
    iba::render_text(heat, 10, 28, text, 18, font, {0.0f, 0.0f, 0.0f});
    if (!heat.write(prefix + "-heatmap.png", OIIO::TypeDesc::UINT8)) throw std::runtime_error(heat.geterror());
    std::fprintf(stderr, "kutlog-render: wrote %s.png, %s.exr, %s-heatmap.png\n", prefix.c_str(),
                 prefix.c_str(), prefix.c_str());
    return 0;
  });
}
