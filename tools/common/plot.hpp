// 2-D line and scatter plots written as PNG, for the tools that chart errors and lobes. Drawn
// with OpenImageIO's ImageBufAlgo and labelled in DejaVu Sans (Debian package fonts-dejavu-core).
#pragma once

#include <array>
#include <optional>
#include <ranges>
#include <string>
#include <type_traits>
#include <vector>

namespace kutlog::tools {

// The DejaVu Sans file the tools label images with (Debian package fonts-dejavu-core);
// std::runtime_error naming the file and the package if it is missing.
const char* label_font();

// A color with components in [0, 1].
struct Rgb {
  float r, g, b;
};

// Series and reference lines given no color take these in turn (matplotlib's "tab10").
inline constexpr std::array<Rgb, 8> kPalette = {{
    {0.122f, 0.467f, 0.706f},  // blue
    {1.000f, 0.498f, 0.055f},  // orange
    {0.173f, 0.627f, 0.173f},  // green
    {0.839f, 0.153f, 0.157f},  // red
    {0.580f, 0.404f, 0.741f},  // purple
    {0.549f, 0.337f, 0.294f},  // brown
    {0.890f, 0.467f, 0.761f},  // pink
    {0.498f, 0.498f, 0.498f},  // gray
}};

// Coordinates of a series, copied from any range of numbers (std::vector<float>,
// std::vector<double>, std::span, ...).
class Values {
 public:
  template <std::ranges::input_range R>
    requires std::is_arithmetic_v<std::ranges::range_value_t<R>>
  Values(const R& values) : values_(std::ranges::begin(values), std::ranges::end(values)) {}

  const std::vector<double>& get() const { return values_; }

 private:
  std::vector<double> values_;
};

class Plot {
 public:
  // An empty plot of `width` x `height` pixels. Lines and spacing scale with the smaller of
  // width / 1200 and height / 800, text with its square root.
  explicit Plot(int width = 1200, int height = 800);

  // Text above the plot area, under the x axis, and along the y axis. Empty: none.
  Plot& title(std::string text);
  Plot& x_label(std::string text);
  Plot& y_label(std::string text);

  // Logarithmic axes (decade ticks). Points with a non-positive coordinate on a logarithmic
  // axis are not drawn.
  Plot& x_log(bool log);
  Plot& y_log(bool log);

  // Fixed axis limits, lo < hi (both > 0 on a logarithmic axis, checked by save()). Without
  // them the limits enclose the data and the reference lines, rounded outward to a tick, with
  // a small margin.
  Plot& x_range(double lo, double hi);
  Plot& y_range(double lo, double hi);

  // A polyline through (xs[i], ys[i]), broken at non-finite points. Throws
  // std::invalid_argument if xs and ys differ in size.
  Plot& line(std::string name, const Values& xs, const Values& ys,
             std::optional<Rgb> color = std::nullopt);
  // A dot at each finite (xs[i], ys[i]); cheap enough for 1e5 points and more. Throws
  // std::invalid_argument if xs and ys differ in size.
  Plot& points(std::string name, const Values& xs, const Values& ys,
               std::optional<Rgb> color = std::nullopt);
  // A dashed horizontal line across the plot at `y`, such as a bound; listed in the legend
  // unless `label` is empty.
  Plot& hline(double y, std::string label, std::optional<Rgb> color = std::nullopt);

  // Draws the plot and writes it as PNG to `path`. Throws std::runtime_error if the font is
  // missing or OpenImageIO cannot write the file, std::invalid_argument for a bad fixed range.
  void save(const std::string& path) const;

 private:
  enum class Style { line, points, dashed };
  struct Series {
    std::string name;
    std::vector<double> xs, ys;
    Rgb color;
    Style style;
  };
  struct AxisOptions {
    std::string label;
    bool log = false;
    std::optional<std::array<double, 2>> range;
  };

  class Renderer;  // lays out and draws the plot for save(), in plot.cpp

  Plot& add(std::string name, const Values& xs, const Values& ys, std::optional<Rgb> color,
            Style style);

  int width_, height_;
  std::string title_;
  AxisOptions x_, y_;
  std::vector<Series> series_;  // hlines included: dashed, no xs, ys = {y}
};

}  // namespace kutlog::tools
