#include "common/plot.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <utility>

namespace kutlog::tools {
namespace {

namespace iba = OIIO::ImageBufAlgo;

// A full path: OIIO 2.4 opens it directly instead of searching its font directories.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kWhite{1, 1, 1};
constexpr Rgb kGrid{0.82f, 0.82f, 0.82f};
constexpr Rgb kMinorGrid{0.93f, 0.93f, 0.93f};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Aim for about this many tick intervals on a linear axis.
constexpr int kTargetTicks = 8;
// Fraction of the axis span added outside automatic limits, so that data on a rounded limit
// does not hide under the frame.
constexpr double kMargin = 0.03;

// The 1, 2 or 5 times a power of ten nearest to the positive `v` at or above it (`up`), or
// at or below it. The slack absorbs the rounding of the power of ten.
double round_125(double v, bool up) {
  const double decade = std::pow(10.0, std::floor(std::log10(v)));
  const double mantissa = v / decade;
  if (up) {
    for (double c : {1.0, 2.0, 5.0})
      if (c >= mantissa * (1 - 1e-9)) return c * decade;
    return 10 * decade;
  }
  for (double c : {5.0, 2.0})
    if (c <= mantissa * (1 + 1e-9)) return c * decade;
  return decade;
}

struct Tick {
  double at;     // in axis units
  double value;  // what the label shows
  bool major;    // labelled; a minor tick is only a faint grid line
  std::string label = {};
};

// 0.25, 1000 or, in `exponential` form, 2.5e-4 (printf's "2.50000e-04" without the padding).
std::string format_number(double v, bool exponential) {
  if (v == 0) return "0";  // not -0, nor 0e0
  char text[32];
  std::snprintf(text, sizeof text, exponential ? "%.5e" : "%.6g", v);
  if (!exponential) return text;
  std::string mantissa = text;
  const auto e = mantissa.find('e');
  const int exponent = std::stoi(mantissa.substr(e + 1));
  mantissa.erase(mantissa.find_last_not_of('0', e - 1) + 1);
  if (mantissa.back() == '.') mantissa.pop_back();
  return mantissa + "e" + std::to_string(exponent);
}

// Labels in plain form unless one of them is tiny or huge: then all exponential, so that an
// axis reads in one notation.
void label(std::vector<Tick>& ticks) {
  const bool exponential = std::ranges::any_of(ticks, [](const Tick& t) {
    const double size = std::abs(t.value);
    return t.major && size != 0 && (size < 1e-3 || size >= 1e6);
  });
  for (Tick& t : ticks)
    if (t.major) t.label = format_number(t.value, exponential);
}

// One axis in "axis units", the value on a linear axis and its log10 on a logarithmic one,
// so that the mapping to pixels is linear on both.
struct Axis {
  bool log;
  double lo, hi;
  double step;  // spacing of the linear ticks, in axis units

  // NaN or infinite when `v` cannot be drawn on this axis.
  double unit(double v) const { return log ? std::log10(v) : v; }
  double fraction(double u) const { return (u - lo) / (hi - lo); }
};

std::vector<Tick> linear_ticks(double lo, double hi, double step) {
  std::vector<Tick> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k <= std::floor(hi / step + 1e-9); ++k)
    ticks.push_back({k * step, k * step, true});
  return ticks;
}

// Decades, thinned to about ten labels; 2 and 5 labelled too when few decades are shown, the
// other mantissas as minor ticks unless their grid would be a blur of lines.
std::vector<Tick> log_ticks(double lo, double hi) {
  const double span = hi - lo;
  const int stride = std::max(1, int(std::ceil(span / 10)));
  std::vector<Tick> ticks;
  int labelled = 0;
  for (double k = std::floor(lo); k <= std::ceil(hi); ++k) {
    for (int m = 1; m <= 9; ++m) {
      const double at = k + std::log10(double(m));
      if (at < lo - 1e-9 || at > hi + 1e-9) continue;
      const bool major = m == 1 ? std::fmod(k, stride) == 0 : span <= 3 && (m == 2 || m == 5);
      if (major || span <= 6) ticks.push_back({at, m * std::pow(10.0, k), major});
      labelled += major;
    }
  }
  if (labelled >= 3) return ticks;
  // A factor of about 2 shown: plain ticks on the values say more than its two ends.
  ticks = linear_ticks(std::pow(10.0, lo), std::pow(10.0, hi),
                       round_125((std::pow(10.0, hi) - std::pow(10.0, lo)) / kTargetTicks, true));
  for (Tick& tick : ticks) tick.at = std::log10(tick.value);
  return ticks;
}

std::vector<Tick> labelled_ticks(const Axis& axis) {
  std::vector<Tick> ticks =
      axis.log ? log_ticks(axis.lo, axis.hi) : linear_ticks(axis.lo, axis.hi, axis.step);
  label(ticks);
  return ticks;
}

// The axis through `fixed` exactly, or else around the data extent [lo, hi] (axis units,
// NaN if there is no data): rounded outward to a tick, plus the margin.
Axis make_axis(bool log, const std::optional<std::array<double, 2>>& fixed, double lo,
               double hi, const char* name) {
  Axis axis{log, lo, hi, 0};
  if (fixed) {
    const auto [flo, fhi] = *fixed;
    if (!(flo < fhi) || (log && !(flo > 0)))
      throw std::invalid_argument(std::string("plot: bad ") + name + " range");
    axis.lo = axis.unit(flo);
    axis.hi = axis.unit(fhi);
    axis.step = round_125((axis.hi - axis.lo) / kTargetTicks, true);
    return axis;
  }
  if (std::isnan(lo)) {  // no data: [0, 1] on a linear axis, [1, 10] on a logarithmic one
    axis.lo = 0;
    axis.hi = 1;
  } else if (lo == hi) {
    const double widen = log ? 0.5 : (lo != 0 ? std::abs(lo) * 0.1 : 1.0);
    axis.lo -= widen;
    axis.hi += widen;
  }
  if (log) {
    axis.lo = std::log10(round_125(std::pow(10.0, axis.lo), false));
    axis.hi = std::log10(round_125(std::pow(10.0, axis.hi), true));
  } else {
    axis.step = round_125((axis.hi - axis.lo) / kTargetTicks, true);
    axis.lo = std::floor(axis.lo / axis.step + 1e-9) * axis.step;
    axis.hi = std::ceil(axis.hi / axis.step - 1e-9) * axis.step;
  }
  const double margin = kMargin * (axis.hi - axis.lo);
  axis.lo -= margin;
  axis.hi += margin;
  return axis;
}

struct Rect {
  double left, top, right, bottom;
};

// Liang-Barsky: shortens the segment to its part inside `r`; false if none is.
bool clip_segment(double& x0, double& y0, double& x1, double& y1, const Rect& r) {
  double t0 = 0, t1 = 1;
  const double dx = x1 - x0, dy = y1 - y0;
  const std::pair<double, double> sides[] = {
      {-dx, x0 - r.left}, {dx, r.right - x0}, {-dy, y0 - r.top}, {dy, r.bottom - y0}};
  for (const auto& [p, q] : sides) {
    if (p == 0) {
      if (q < 0) return false;
    } else if (p < 0) {
      t0 = std::max(t0, q / p);
    } else {
      t1 = std::min(t1, q / p);
    }
  }
  if (t0 > t1) return false;
  x1 = x0 + t1 * dx;
  y1 = y0 + t1 * dy;
  x0 += t0 * dx;
  y0 += t0 * dy;
  return true;
}

bool inside(double x, double y, const Rect& r) {
  return x >= r.left && x <= r.right && y >= r.top && y <= r.bottom;
}

int px(double v) { return int(std::lround(v)); }

std::array<float, 3> channels(Rgb c) { return {c.r, c.g, c.b}; }

// The image and the primitives of a plot; coordinates in pixels, y down.
class Canvas {
 public:
  Canvas(int width, int height, double scale)
      : image_(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)), scale_(scale) {
    iba::fill(image_, channels(kWhite));
  }

  int scaled(double pixels) const { return std::max(1, px(pixels * scale_)); }

  // A line of `thickness` pixels, cut to `clip`.
  void line(double x0, double y0, double x1, double y1, Rgb color, const Rect& clip,
            int thickness = 1) {
    if (!clip_segment(x0, y0, x1, y1, clip)) return;
    // Offset copies, right and down, thicken the line whatever its direction.
    for (int dx = 0; dx < thickness; ++dx)
      for (int dy = 0; dy < thickness; ++dy)
        if (dx == 0 || dy == 0)
          iba::render_line(image_, px(x0) + dx, px(y0) + dy, px(x1) + dx, px(y1) + dy,
                           channels(color), false, pixels(clip));
  }

  void dashed_hline(double x0, double x1, double y, Rgb color, const Rect& clip) {
    const double dash = scaled(10), gap = scaled(6);
    for (double x = x0; x < x1; x += dash + gap)
      line(x, y, std::min(x + dash, x1), y, color, clip, scaled(2));
  }

  // A filled square of side 2 r + 1; one ImageBufAlgo call, fast enough for 1e5 dots.
  void dot(double x, double y, int r, Rgb color, const Rect& clip) {
    if (!inside(x, y, clip)) return;
    iba::render_box(image_, px(x) - r, px(y) - r, px(x) + r, px(y) + r, channels(color), true,
                    pixels(clip));
  }

  void box(const Rect& r, Rgb color, bool fill) {
    iba::render_box(image_, px(r.left), px(r.top), px(r.right), px(r.bottom), channels(color),
                    fill);
  }

  // Font size in pixels for a nominal size at scale 1. Text shrinks and grows slower than the
  // image, so that it stays readable on small plots.
  int font(double size) const { return std::max(9, px(size * std::sqrt(scale_))); }
  // Height of a digit above the baseline: what centres numbers on ticks.
  static int ascent(int size) { return -iba::text_size("0", size, kFontPath).ybegin; }
  static int width(const std::string& text, int size) {
    return iba::text_size(text, size, kFontPath).width();
  }

  // Black text with its baseline at `y`.
  void text(int x, int y, const std::string& text, int size,
            iba::TextAlignX align = iba::TextAlignX::Left) {
    render_text(image_, x, y, text, size, align);
  }

  // Text reading upwards, its left edge at x and centred on `y`: drawn horizontally into its
  // own image, then rotated and pasted.
  void vertical_text(int x, int y, const std::string& text, int size) {
    const OIIO::ROI extent = iba::text_size(text, size, kFontPath);
    OIIO::ImageBuf strip(OIIO::ImageSpec(extent.width(), extent.height(), 3,
                                         OIIO::TypeDesc::UINT8));
    iba::fill(strip, channels(kWhite));
    render_text(strip, -extent.xbegin, -extent.ybegin, text, size, iba::TextAlignX::Left);
    iba::paste(image_, x, y - extent.width() / 2, 0, 0, iba::rotate270(strip));
  }

  void write(const std::string& path) {
    if (!image_.write(path, OIIO::TypeUnknown, "png")) {
      // A file that cannot be opened is reported by the ImageBuf, a missing PNG plugin by OIIO.
      std::string error = image_.geterror();
      if (error.empty()) error = OIIO::geterror();
      throw std::runtime_error("plot: cannot write " + path + ": " + error);
    }
  }

 private:
  // Layout works from the baseline: OIIO 2.4's other vertical alignments (Top, Center,
  // Bottom) place text inconsistently.
  static void render_text(OIIO::ImageBuf& image, int x, int y, const std::string& text,
                          int size, iba::TextAlignX align) {
    if (!iba::render_text(image, x, y, text, size, kFontPath, channels(kBlack), align))
      throw std::runtime_error("plot: cannot draw text: " + image.geterror());
  }

  static OIIO::ROI pixels(const Rect& r) {
    return {px(r.left), px(r.right) + 1, px(r.top), px(r.bottom) + 1};
  }

  OIIO::ImageBuf image_;
  double scale_;
};

}  // namespace

Plot::Plot(int width, int height) : width_(width), height_(height) {}

Plot& Plot::title(std::string text) {
  title_ = std::move(text);
  return *this;
}
Plot& Plot::x_label(std::string text) {
  x_.label = std::move(text);
  return *this;
}
Plot& Plot::y_label(std::string text) {
  y_.label = std::move(text);
  return *this;
}
Plot& Plot::x_log(bool log) {
  x_.log = log;
  return *this;
}
Plot& Plot::y_log(bool log) {
  y_.log = log;
  return *this;
}
Plot& Plot::x_range(double lo, double hi) {
  x_.range = {lo, hi};
  return *this;
}
Plot& Plot::y_range(double lo, double hi) {
  y_.range = {lo, hi};
  return *this;
}

Plot& Plot::line(std::string name, const Values& xs, const Values& ys, std::optional<Rgb> color) {
  return add(std::move(name), xs, ys, color, Style::line);
}
Plot& Plot::points(std::string name, const Values& xs, const Values& ys,
                   std::optional<Rgb> color) {
  return add(std::move(name), xs, ys, color, Style::points);
}
Plot& Plot::hline(double y, std::string label, std::optional<Rgb> color) {
  return add(std::move(label), std::vector<double>{}, std::vector<double>{y}, color,
             Style::dashed);
}

Plot& Plot::add(std::string name, const Values& xs, const Values& ys, std::optional<Rgb> color,
                Style style) {
  if (style != Style::dashed && xs.get().size() != ys.get().size())
    throw std::invalid_argument("plot: series '" + name + "' has " +
                                std::to_string(xs.get().size()) + " x but " +
                                std::to_string(ys.get().size()) + " y values");
  const Rgb chosen = color.value_or(kPalette[series_.size() % kPalette.size()]);
  series_.push_back({std::move(name), xs.get(), ys.get(), chosen, style});
  return *this;
}

// One save(): the axes resolved from the data, the layout, and the drawing.
class Plot::Renderer {
 public:
  explicit Renderer(const Plot& plot)
      : plot_(plot),
        canvas_(plot.width_, plot.height_,
                std::min(plot.width_ / 1200.0, plot.height_ / 800.0)) {
    resolve_axes();
    lay_out();
    for (const Series& s : plot.series_) pixels_.push_back(series_pixels(s));
  }

  void draw(const std::string& path) {
    draw_grid();
    // Reference lines last, so that dense data does not bury a bound.
    for (const bool dashed : {false, true})
      for (std::size_t k = 0; k < plot_.series_.size(); ++k)
        if ((plot_.series_[k].style == Style::dashed) == dashed) draw_series(k);
    draw_axes();
    draw_legend();
    canvas_.write(path);
  }

 private:
  using Pixel = std::array<double, 2>;  // NaN where a point cannot be drawn

  // A reference line becomes a segment across the plot area.
  std::vector<Pixel> series_pixels(const Series& s) const {
    if (s.style == Style::dashed) {
      const double y = to_y(y_.unit(s.ys[0]));
      return {{area_.left, y}, {area_.right, y}};
    }
    std::vector<Pixel> pixels;
    for (std::size_t i = 0; i < s.xs.size(); ++i) {
      const double u = x_.unit(s.xs[i]), v = y_.unit(s.ys[i]);
      const bool drawable = std::isfinite(u) && std::isfinite(v);
      pixels.push_back({drawable ? to_x(u) : kNaN, drawable ? to_y(v) : kNaN});
    }
    return pixels;
  }

  // Calls `visit(from, to)` on each drawable piece of series k: the segments of a line, each
  // point of a scatter (from == to).
  template <class Visit>
  void for_each_piece(std::size_t k, Visit visit) const {
    const std::vector<Pixel>& p = pixels_[k];
    const bool joined = plot_.series_[k].style != Style::points;
    for (std::size_t i = joined ? 1 : 0; i < p.size(); ++i) {
      const Pixel& from = joined ? p[i - 1] : p[i];
      if (std::isfinite(from[1]) && std::isfinite(p[i][1])) visit(from, p[i]);
    }
  }

  // The axes around the data extent (axis units) of the points that can be drawn.
  void resolve_axes() {
    x_.log = plot_.x_.log;
    y_.log = plot_.y_.log;
    double x_lo = kNaN, x_hi = kNaN, y_lo = kNaN, y_hi = kNaN;
    const auto extend = [](double u, double& lo, double& hi) {
      lo = std::isnan(lo) ? u : std::min(lo, u);
      hi = std::isnan(hi) ? u : std::max(hi, u);
    };
    for (const Series& s : plot_.series_) {
      if (s.style == Style::dashed && std::isfinite(y_.unit(s.ys[0])))
        extend(y_.unit(s.ys[0]), y_lo, y_hi);
      for (std::size_t i = 0; i < s.xs.size(); ++i) {
        const double u = x_.unit(s.xs[i]), v = y_.unit(s.ys[i]);
        if (!std::isfinite(u) || !std::isfinite(v)) continue;
        extend(u, x_lo, x_hi);
        extend(v, y_lo, y_hi);
      }
    }
    x_ = make_axis(x_.log, plot_.x_.range, x_lo, x_hi, "x");
    y_ = make_axis(y_.log, plot_.y_.range, y_lo, y_hi, "y");
    x_ticks_ = labelled_ticks(x_);
    y_ticks_ = labelled_ticks(y_);
  }

  // From the outside in: the title above the plot area; the y label and the tick numbers
  // left of it; the tick numbers and the x label below it.
  void lay_out() {
    title_size_ = canvas_.font(26);
    label_size_ = canvas_.font(20);
    tick_size_ = canvas_.font(16);
    legend_size_ = canvas_.font(16);
    pad_ = canvas_.scaled(14);
    tick_length_ = canvas_.scaled(7);
    gap_ = canvas_.scaled(5);
    tick_ascent_ = Canvas::ascent(tick_size_);
    const int y_numbers = widest_label(y_ticks_), x_numbers = widest_label(x_ticks_);
    const bool title = !plot_.title_.empty(), x_label = !plot_.x_.label.empty(),
               y_label = !plot_.y_.label.empty();
    area_.left = pad_ + (y_label ? line_height(label_size_) + pad_ : 0) + y_numbers + gap_ +
                 tick_length_;
    // Without a title, room for half of the top y number; right, for half of the last x one.
    area_.top = pad_ + (title ? line_height(title_size_) + pad_ : tick_ascent_);
    area_.right = plot_.width_ - std::max(2 * pad_, x_numbers / 2 + pad_);
    area_.bottom = plot_.height_ - pad_ - (x_label ? line_height(label_size_) + pad_ : 0) -
                   tick_ascent_ - gap_ - tick_length_;
  }

  int widest_label(const std::vector<Tick>& ticks) const {
    int widest = 0;
    for (const Tick& t : ticks)
      if (t.major) widest = std::max(widest, Canvas::width(t.label, tick_size_));
    return widest;
  }

  // A line of text about 1.2 of its size high, descenders included.
  static int line_height(int size) { return size * 6 / 5; }

  double to_x(double u) const { return area_.left + x_.fraction(u) * (area_.right - area_.left); }
  double to_y(double v) const { return area_.bottom - y_.fraction(v) * (area_.bottom - area_.top); }

  void draw_grid() {
    for (const Tick& t : x_ticks_)
      canvas_.line(to_x(t.at), area_.top, to_x(t.at), area_.bottom, grid_color(t), area_);
    for (const Tick& t : y_ticks_)
      canvas_.line(area_.left, to_y(t.at), area_.right, to_y(t.at), grid_color(t), area_);
  }
  static Rgb grid_color(const Tick& t) { return t.major ? kGrid : kMinorGrid; }

  void draw_series(std::size_t k) {
    const Rgb color = plot_.series_[k].color;
    const Style style = plot_.series_[k].style;
    for_each_piece(k, [&](const Pixel& from, const Pixel& to) {
      switch (style) {
        case Style::dashed:
          canvas_.dashed_hline(from[0], to[0], from[1], color, area_);
          break;
        case Style::points:
          canvas_.dot(to[0], to[1], canvas_.scaled(1), color, area_);
          break;
        case Style::line:
          canvas_.line(from[0], from[1], to[0], to[1], color, area_, canvas_.scaled(2));
          break;
      }
    });
  }

  // Frame, ticks with their numbers, axis labels and title.
  void draw_axes() {
    const Rect image{0, 0, double(plot_.width_ - 1), double(plot_.height_ - 1)};
    canvas_.box(area_, kBlack, false);
    for (const Tick& t : x_ticks_) {
      if (!t.major) continue;
      const double x = to_x(t.at);
      canvas_.line(x, area_.bottom, x, area_.bottom + tick_length_, kBlack, image);
      canvas_.text(px(x), px(area_.bottom) + tick_length_ + gap_ + tick_ascent_, t.label,
                   tick_size_, iba::TextAlignX::Center);
    }
    for (const Tick& t : y_ticks_) {
      if (!t.major) continue;
      const double y = to_y(t.at);
      canvas_.line(area_.left - tick_length_, y, area_.left, y, kBlack, image);
      canvas_.text(px(area_.left) - tick_length_ - gap_, px(y) + tick_ascent_ / 2, t.label,
                   tick_size_, iba::TextAlignX::Right);
    }
    const int centre_x = px((area_.left + area_.right) / 2);
    if (!plot_.x_.label.empty())
      canvas_.text(centre_x, plot_.height_ - pad_ - line_height(label_size_) / 5,
                   plot_.x_.label, label_size_, iba::TextAlignX::Center);
    if (!plot_.y_.label.empty())
      canvas_.vertical_text(pad_, px((area_.top + area_.bottom) / 2), plot_.y_.label,
                            label_size_);
    if (!plot_.title_.empty())
      canvas_.text(centre_x, pad_ + Canvas::ascent(title_size_), plot_.title_, title_size_,
                   iba::TextAlignX::Center);
  }

  // A box listing the named series, in the corner of the plot area that hides the least data.
  void draw_legend() {
    std::vector<const Series*> listed;
    int name_width = 0;
    for (const Series& s : plot_.series_) {
      if (s.name.empty()) continue;
      listed.push_back(&s);
      name_width = std::max(name_width, Canvas::width(s.name, legend_size_));
    }
    if (listed.empty()) return;
    const int row = line_height(legend_size_) + gap_, sample = canvas_.scaled(36);
    const Rect box = least_hiding_corner(pad_ + sample + 2 * gap_ + name_width + pad_,
                                         2 * pad_ + row * double(listed.size()) - gap_);
    canvas_.box(box, kWhite, true);
    canvas_.box(box, kBlack, false);
    const int ascent = Canvas::ascent(legend_size_);
    for (std::size_t i = 0; i < listed.size(); ++i) {
      const Series& s = *listed[i];
      const double baseline = box.top + pad_ + row * double(i) + ascent;
      const double mid = baseline - ascent / 2.0, x0 = box.left + pad_, x1 = x0 + sample;
      switch (s.style) {
        case Style::dashed: canvas_.dashed_hline(x0, x1, mid, s.color, box); break;
        case Style::points: canvas_.dot((x0 + x1) / 2, mid, canvas_.scaled(3), s.color, box); break;
        case Style::line: canvas_.line(x0, mid, x1, mid, s.color, box, canvas_.scaled(2)); break;
      }
      canvas_.text(px(x1) + 2 * gap_, px(baseline), s.name, legend_size_);
    }
  }

  Rect least_hiding_corner(double width, double height) const {
    Rect best{};
    std::size_t least = std::numeric_limits<std::size_t>::max();
    for (const bool right : {true, false}) {
      for (const bool top : {true, false}) {
        Rect r;
        r.left = right ? area_.right - pad_ - width : area_.left + pad_;
        r.top = top ? area_.top + pad_ : area_.bottom - pad_ - height;
        r.right = r.left + width;
        r.bottom = r.top + height;
        if (const std::size_t hidden = count_hidden(r); hidden < least) {
          least = hidden;
          best = r;
        }
      }
    }
    return best;
  }

  // Points, line segments and reference lines that cross `r`.
  std::size_t count_hidden(const Rect& r) const {
    std::size_t hidden = 0;
    for (std::size_t k = 0; k < plot_.series_.size(); ++k)
      for_each_piece(k, [&](Pixel from, Pixel to) {
        hidden += clip_segment(from[0], from[1], to[0], to[1], r);
      });
    return hidden;
  }

  const Plot& plot_;
  Canvas canvas_;
  Axis x_{}, y_{};
  std::vector<Tick> x_ticks_, y_ticks_;
  Rect area_{};  // the plot area, inside the frame
  int title_size_ = 0, label_size_ = 0, tick_size_ = 0, legend_size_ = 0;
  int pad_ = 0, tick_length_ = 0, gap_ = 0, tick_ascent_ = 0;
  std::vector<std::vector<Pixel>> pixels_;  // per series
};

void Plot::save(const std::string& path) const {
  label_font();  // throws if the font is missing
  Renderer(*this).draw(path);
}

const char* label_font() {
  if (!std::filesystem::exists(kFontPath))
    throw std::runtime_error(std::string("font ") + kFontPath +
                             " is missing (Debian package fonts-dejavu-core)");
  return kFontPath;
}

}  // namespace kutlog::tools
