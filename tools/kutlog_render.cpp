// kutlog-render: a lit sphere or Utah teapot with the lobes side by side, and a heatmap of where
// F_kutlog and Blinn-Phong differ. PNG for viewing, EXR for the linear values. The kutlog panels
// are shaded by the library's stream API (kutlog::shade), with the object's coverage as the
// lane mask.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/cli.hpp"
#include "common/label_font.hpp"
#include "kutlog/baselines.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/shade.hpp"
#include "mesh.hpp"    // examples/common: the teapot
#include "raster.hpp"  // examples/common: camera and visibility pass

namespace {

namespace iba = OIIO::ImageBufAlgo;
namespace ref = kutlog::ref;
namespace examples = kutlog::examples;

// One row of a panel's pixels, as the stream API's SoA vectors: unit normal, to the light and
// to the viewer; N.H in double for the pow and Schlick baselines; whether the object covers it.
struct PanelRow {
  std::vector<float> nx, ny, nz, lx, ly, lz, vx, vy, vz, n_dot_h;
  std::vector<std::uint8_t> covered;

  void push(const ref::Vec3& normal, const ref::Vec3& to_light, const ref::Vec3& to_viewer, bool inside) {
    nx.push_back(float(normal.x)), ny.push_back(float(normal.y)), nz.push_back(float(normal.z));
    lx.push_back(float(to_light.x)), ly.push_back(float(to_light.y)), lz.push_back(float(to_light.z));
    vx.push_back(float(to_viewer.x)), vy.push_back(float(to_viewer.y)), vz.push_back(float(to_viewer.z));
    n_dot_h.push_back(inside ? float(ref::blinn_cosine(normal, to_light, to_viewer)) : 0.0f);
    covered.push_back(inside);
  }
};

ref::Vec3 unit(const ref::Vec3& v) {
  const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / length, v.y / length, v.z / length};
}

// The unit sphere seen from +z, orthographic: the normal is the point itself.
PanelRow sphere_row(int row, int size, const ref::Vec3& to_light) {
  PanelRow r;
  for (int column = 0; column < size; ++column) {
    const double x = (2.0 * column + 1) / size - 1, y = 1 - (2.0 * row + 1) / size;
    const double rr = x * x + y * y;
    const bool inside = rr < 1;
    r.push({x, y, inside ? std::sqrt(1 - rr) : 0}, to_light, {0, 0, 1}, inside);
  }
  return r;
}

// A mesh seen through a perspective camera, from its visibility buffer.
struct MeshView {
  examples::Mesh mesh;
  examples::Camera camera;
  examples::VisibilityBuffer buffer;

  MeshView(int width, int height)
      : mesh(examples::utah_teapot(24)),
        camera({1.3f, 1.1f, 2.6f}, {0, -0.02f, 0}, 0.5f, width, height),
        buffer(width, height) {
    examples::rasterize(mesh, examples::project(mesh, camera), buffer, 0, height);
  }

  PanelRow row(int row, const ref::Vec3& to_light) const {
    PanelRow r;
    for (int column = 0; column < buffer.width; ++column) {
      const auto s = examples::surface_at(mesh, buffer, camera, std::size_t(row) * buffer.width + column);
      const auto as_ref = [](examples::Vec3 v) { return ref::Vec3{v.x, v.y, v.z}; };
      if (s) r.push(unit(as_ref(s->normal)), to_light, unit(as_ref(s->to_viewer)), true);
      else r.push({0, 0, 1}, to_light, {0, 0, 1}, false);
    }
    return r;
  }
};

// Radiance of a grey dielectric-ish material under a white light of irradiance 1:
// diffuse 0.5/pi N.L plus the specular term (already times N.L) scaled by `specular_scale`.
float radiance(float n_dot_l, float specular, float specular_scale) {
  return 0.5f / float(ref::pi) * std::max(n_dot_l, 0.0f) + specular_scale * specular;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Render a lit sphere or Utah teapot with the lobes side by side (Blinn-Phong, F_kutlog,\n"
      "coef * F_kutlog, Schlick), and a heatmap of |F_kutlog - Blinn-Phong|. Writes PREFIX.png,\n"
      "PREFIX.exr (linear) and PREFIX-heatmap.png.",
      "kutlog-render");
  std::string prefix;
  int size = 384, k = 3;
  double n = 100, Q = 0.5;
  std::vector<double> light{-0.5, 0.6, 0.8};
  std::string object = "sphere";
  app.add_option("--output,-o", prefix, "Output path prefix")->required();
  app.add_option("--size", size, "Panel width in pixels (the teapot's panels are 5/8 as tall)")->check(CLI::Range(16, 4096))->capture_default_str();
  app.add_option("--n", n, "Exponent n (real > 0)")->capture_default_str();
  app.add_option("--k", k, "Power k (integer >= 1)")->capture_default_str();
  app.add_option("--q", Q, "Anchor Q in (0, 1)")->capture_default_str();
  app.add_option("--object", object, "What to render")->check(CLI::IsMember({"sphere", "teapot"}))->capture_default_str();
  app.add_option("--light", light, "Direction to the light x,y,z (y up, z towards the viewer)")->delimiter(',')->expected(3)->capture_default_str();
  return kutlog::tools::run_tool(app, argc, argv, [&] {
    const kutlog::Lobe lobe(n, k, Q);  // validates n, k, Q
    if (!(light[2] > 0)) throw std::invalid_argument("--light: z must be > 0 (on the viewer's side)");
    const ref::Vec3 to_light = unit({light[0], light[1], light[2]});
    const int rows = object == "teapot" ? size * 5 / 8 : size;
    const std::optional<MeshView> teapot =
        object == "teapot" ? std::optional<MeshView>(std::in_place, size, rows) : std::nullopt;
    const char* font = kutlog::tools::label_font();
    constexpr int kPanels = 4, kLabelHeight = 40;
    const char* labels[kPanels] = {"Blinn-Phong cos^n", "F_kutlog", "coef * F_kutlog (0.04)", "Schlick"};
    const int width = kPanels * size, height = rows + kLabelHeight;
    OIIO::ImageBuf linear(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBuf heat(OIIO::ImageSpec(size + 160, rows + kLabelHeight, 3, OIIO::TypeDesc::FLOAT));
    iba::fill(linear, {1.0f, 1.0f, 1.0f});
    iba::fill(heat, {1.0f, 1.0f, 1.0f});
    std::vector<float> error(std::size_t(rows) * size, 0.0f);
    std::vector<float> power(size), kutlog_f(size), kutlog_normalized(size), schlick(size), n_dot_l(size);
    for (int row = 0; row < rows; ++row) {
      const PanelRow r = teapot ? teapot->row(row, to_light) : sphere_row(row, size, to_light);
      const kutlog::Vectors normal{r.nx.data(), r.ny.data(), r.nz.data()},
          to_l{r.lx.data(), r.ly.data(), r.lz.data()}, to_v{r.vx.data(), r.vy.data(), r.vz.data()};
      std::fill(kutlog_f.begin(), kutlog_f.end(), 0.0f);
      std::fill(kutlog_normalized.begin(), kutlog_normalized.end(), 0.0f);
      kutlog::ShadeOptions normalized;
      normalized.normalization = kutlog::Normalization::exact_coef;
      kutlog::shade(lobe, normal, to_l, to_v, kutlog_f.data(), size, r.covered.data());
      kutlog::shade(lobe, normal, to_l, to_v, kutlog_normalized.data(), size, r.covered.data(),
                    normalized);
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
    for (int row = 0; row < rows; ++row)
      for (int column = 0; column < size; ++column) {
        ramp(error[std::size_t(row) * size + column] / max_error, rgb);
        heat.setpixel(column, kLabelHeight + row, rgb);
      }
    for (int row = 0; row < rows; ++row) {
      ramp(1 - float(row) / float(rows - 1), rgb);
      for (int column = size + 20; column < size + 45; ++column) heat.setpixel(column, kLabelHeight + row, rgb);
    }
    char text[64];
    std::snprintf(text, sizeof text, "%.2g", max_error);
    iba::render_text(heat, size + 50, kLabelHeight + 14, text, 16, font, {0.0f, 0.0f, 0.0f});
    iba::render_text(heat, size + 50, kLabelHeight + rows, "0", 16, font, {0.0f, 0.0f, 0.0f});
    std::snprintf(text, sizeof text, "|F_kutlog - cos^n| (n=%g, k=%d, Q=%g)", n, k, Q);
    iba::render_text(heat, 10, 28, text, 18, font, {0.0f, 0.0f, 0.0f});
    if (!heat.write(prefix + "-heatmap.png", OIIO::TypeDesc::UINT8)) throw std::runtime_error(heat.geterror());
    std::fprintf(stderr, "kutlog-render: wrote %s.png, %s.exr, %s-heatmap.png\n", prefix.c_str(),
                 prefix.c_str(), prefix.c_str());
    return 0;
  });
}
