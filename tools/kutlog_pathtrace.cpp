// kutlog-pathtrace: a glossy sphere (kutlog's normalized microfacet BRDF) under a sky with a
// small bright sun, path traced with the F_kutlog lobe's importance sampler and with uniform
// hemisphere sampling at the same samples per pixel. Writes the images side by side with a
// high-spp reference (PREFIX.png) and prints the RMSE of each against the reference for spp =
// 1, 2, 4, ..., --max-spp (the table, CSV for tools/plot/kutlog_figures.py --figure rmse).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "common/cli.hpp"
#include "common/label_font.hpp"
#include "common/pathtrace.hpp"
#include "common/table.hpp"

namespace {

namespace pt = kutlog::pathtrace;

// 1, 2, 4, ..., max_spp.
std::vector<int> powers_of_two_up_to(int max_spp) {
  std::vector<int> spp;
  for (int s = 1; s <= max_spp; s *= 2) spp.push_back(s);
  return spp;
}

// For viewing: a Reinhard curve x / (1 + x), then the display's gamma 2.2.
float display_value(double radiance) { return float(std::pow(radiance / (1 + radiance), 1 / 2.2)); }

// The panels side by side under their labels, tone mapped, as an 8-bit PNG.
void write_panels(const std::vector<const pt::Image*>& panels, const std::vector<std::string>& labels,
                  const std::string& path) {
  constexpr int kLabelHeight = 32;
  const int width = panels[0]->width, height = panels[0]->height;
  OIIO::ImageBuf out(OIIO::ImageSpec(int(panels.size()) * width, height + kLabelHeight, 3,
                                     OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::fill(out, {1.0f, 1.0f, 1.0f});
  for (std::size_t panel = 0; panel < panels.size(); ++panel) {
    for (int row = 0; row < height; ++row)
      for (int column = 0; column < width; ++column) {
        const pt::Rgb& c = panels[panel]->at(column, row);
        const float rgb[3] = {display_value(c.r), display_value(c.g), display_value(c.b)};
        out.setpixel(int(panel) * width + column, kLabelHeight + row, rgb);
      }
    OIIO::ImageBufAlgo::render_text(out, int(panel) * width + 8, 22, labels[panel], 14,
                                    kutlog::tools::label_font(), {0.0f, 0.0f, 0.0f});
  }
  if (!out.write(path, OIIO::TypeDesc::UINT8)) throw std::runtime_error(out.geterror());
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Path trace a glossy sphere (kutlog's normalized microfacet BRDF) under a sky with a small\n"
      "bright sun, sampling the reflected light with the F_kutlog lobe's sampler and uniformly\n"
      "over the hemisphere at the same samples per pixel. Writes PREFIX.png (the two side by\n"
      "side, and the reference) and prints the RMSE of each against a reference rendered with\n"
      "the lobe sampler at --reference-spp, for spp = 1, 2, 4, ..., --max-spp.",
      "kutlog-pathtrace");
  std::string prefix, format_name = "text";
  int width = 256, height = 192, k = 3, max_spp = 256, image_spp = 16, reference_spp = 4096;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  double n = 1000, Q = 0.5;
  std::uint64_t seed = 1;
  app.add_option("--output,-o", prefix, "Output path prefix (PREFIX.png)")->required();
  app.add_option("--width", width, "Image width in pixels")->check(CLI::Range(8, 4096))->capture_default_str();
  app.add_option("--height", height, "Image height in pixels")->check(CLI::Range(8, 4096))->capture_default_str();
  app.add_option("--n", n, "Exponent n (real > 0)")->capture_default_str();
  app.add_option("--k", k, "Power k (integer >= 1)")->capture_default_str();
  app.add_option("--q", Q, "Anchor Q in (0, 1)")->capture_default_str();
  app.add_option("--max-spp", max_spp, "Largest samples per pixel of the RMSE table, a power of two in [1, 65536]")->capture_default_str();
  app.add_option("--image-spp", image_spp, "Samples per pixel of the side-by-side images, a power of two <= --max-spp")->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "Samples per pixel of the reference (lobe sampling), >= --max-spp")->capture_default_str();
  app.add_option("--seed", seed, "Seed of the random streams")->capture_default_str();
  app.add_option("--threads", threads, "Threads rendering rows")->check(CLI::Range(1, 256))->capture_default_str();
  kutlog::tools::add_format_option(app, format_name);
  return kutlog::tools::run_tool(app, argc, argv, [&] {
    const pt::Material material(n, k, Q);  // validates n, k, Q
    if (max_spp < 1 || max_spp > 65536 || !std::has_single_bit(unsigned(max_spp)))
      throw std::invalid_argument("--max-spp: must be a power of two in [1, 65536], got " +
                                  std::to_string(max_spp));
    if (image_spp < 1 || image_spp > max_spp || !std::has_single_bit(unsigned(image_spp)))
      throw std::invalid_argument("--image-spp: must be a power of two in [1, --max-spp = " +
                                  std::to_string(max_spp) + "], got " + std::to_string(image_spp));
    if (reference_spp < max_spp)
      throw std::invalid_argument("--reference-spp: must be >= --max-spp = " +
                                  std::to_string(max_spp) + ", got " + std::to_string(reference_spp));
    const pt::Environment sky = pt::Environment::sky();
    const pt::Scene scene{material, sky, width, height};
    const std::vector<int> checkpoints = powers_of_two_up_to(max_spp);
    const auto start = std::chrono::steady_clock::now();
    // The reference draws other random numbers than the lobe image: its noise must not
    // correlate with the images' (render mixes the seed with the pixel, so any other seed will do).
    const std::uint64_t reference_seed = ~seed;
    const pt::Image reference =
        pt::render(scene, pt::Sampler::lobe, reference_seed, {reference_spp}, threads)[0];
    const double reference_seconds = seconds_since(start);

    std::vector<std::string> header{"spp"};
    for (pt::Sampler sampler : pt::kSamplers) header.push_back("rmse_" + std::string(pt::sampler_name(sampler)));
    for (const char* parameter : {"n", "k", "Q", "reference_spp"}) header.push_back(parameter);
    std::vector<std::vector<std::string>> rows(checkpoints.size());
    for (std::size_t i = 0; i < checkpoints.size(); ++i) rows[i].push_back(std::to_string(checkpoints[i]));
    std::vector<pt::Image> shown;
    std::vector<std::string> labels;
    for (pt::Sampler sampler : pt::kSamplers) {
      const std::vector<pt::Image> images = pt::render(scene, sampler, seed, checkpoints, threads);
      for (std::size_t i = 0; i < checkpoints.size(); ++i)
        rows[i].push_back(fmt::format("{:.6g}", pt::rmse(images[i], reference)));
      shown.push_back(images[std::countr_zero(unsigned(image_spp))]);
      labels.push_back(fmt::format("{}, {} spp", pt::sampler_label(sampler), image_spp));
    }
    kutlog::tools::Table table(header);
    for (auto& row : rows) {
      for (const std::string& value : {fmt::format("{:g}", n), std::to_string(k), fmt::format("{:g}", Q), std::to_string(reference_spp)})
        row.push_back(value);
      table.add_row(row);
    }
    table.print(kutlog::tools::parse_format(format_name));

    std::vector<const pt::Image*> panels;
    for (const pt::Image& image : shown) panels.push_back(&image);
    panels.push_back(&reference);
    labels.push_back(fmt::format("reference: lobe, {} spp", reference_spp));
    write_panels(panels, labels, prefix + ".png");
    fmt::print(stderr, "kutlog-pathtrace: wrote {}.png ({}x{} per panel); reference {:.1f} s, all {:.1f} s on {} threads\n",
               prefix, width, height, reference_seconds, seconds_since(start), threads);
    return 0;
  });
}
