#include "dymesh/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "dymesh/io/printable.h"
#include "dymesh/report/colour_map.h"

namespace dymesh {
namespace {

// layout of a line plot [px]
constexpr int kMinLeft = 56, kRight = 18, kTop = 52, kBottom = 44;
constexpr const char* kFont = "font-family=\"sans-serif\"";
// a span under this fraction of its values' magnitude is flat: ticks counted in its steps from the
// values stay far below 2^53, where adding one to the count would no longer move it
constexpr double kFlatSpan = 1e-9;

// the data range of a plot: x and y limits with their ticks
struct Axes {
  double x0, x1, y0, y1;
  std::vector<double> x_ticks, y_ticks;
  int left = kMinLeft;  // [px] left margin: room for the longest y tick label and the axis label
};

// digits after the point that tell ticks `step` apart
int DecimalsFor(double step) {
  if (!(step > 0.0)) return 0;
  return std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 9);
}

// smallest and largest finite value of every series (and markers); y range includes 0 if asked
void DataRange(const LinePlot& plot, double* x0, double* x1, double* y0, double* y1) {
  const double inf = std::numeric_limits<double>::infinity();
  *x0 = inf, *x1 = -inf, *y0 = inf, *y1 = -inf;
  auto take = [&](double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    *x0 = std::min(*x0, x), *x1 = std::max(*x1, x), *y0 = std::min(*y0, y), *y1 = std::max(*y1, y);
  };
  for (const PlotSeries& s : plot.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) take(s.x[i], s.y[i]);
  for (const PlotMarker& m : plot.markers) take(m.x, m.y);
  if (!(*x0 <= *x1)) *x0 = 0.0, *x1 = 1.0, *y0 = 0.0, *y1 = 1.0;
  if (plot.include_zero) *y0 = std::min(*y0, 0.0), *y1 = std::max(*y1, 0.0);
}

// a span no wider than the round-off of its values (an output constant to its last digits)
bool Flat(double lo, double hi) { return !(hi - lo > kFlatSpan * std::max(std::abs(lo), std::abs(hi))); }

// limits widened to whole ticks (y) or kept as the data (x); an empty or flat span gets a unit span
Axes MakeAxes(const LinePlot& plot) {
  Axes a;
  DataRange(plot, &a.x0, &a.x1, &a.y0, &a.y1);
  if (Flat(a.x0, a.x1)) a.x0 -= 0.5, a.x1 += 0.5;
  if (Flat(a.y0, a.y1)) a.y0 -= 1.0, a.y1 += 1.0;
  a.y_ticks = NiceTicks(a.y0, a.y1, 5);
  const double step = a.y_ticks.size() > 1 ? a.y_ticks[1] - a.y_ticks[0] : a.y1 - a.y0;
  a.y0 = std::min(a.y0, std::floor(a.y0 / step + 1e-9) * step);
  a.y1 = std::max(a.y1, std::ceil(a.y1 / step - 1e-9) * step);
  a.y_ticks = NiceTicks(a.y0, a.y1, 5);
  a.x_ticks = NiceTicks(a.x0, a.x1, 6);
  // left margin from the longest y tick label (about 6.5 px per character at 11 px)
  const int decimals = DecimalsFor(a.y_ticks.size() > 1 ? a.y_ticks[1] - a.y_ticks[0] : 1.0);
  std::size_t longest = 0;
  for (double t : a.y_ticks) longest = std::max(longest, FormatFixed(t, decimals).size());
  a.left = std::max(kMinLeft, static_cast<int>(30 + 6.5 * longest));
  return a;
}

// maps data to the plot area [px]
struct Frame {
  const Axes& a;
  int width, height;
  bool invert_y;
  double Px(double x) const { return a.left + (x - a.x0) / (a.x1 - a.x0) * (width - a.left - kRight); }
  double Py(double y) const {
    const double f = (y - a.y0) / (a.y1 - a.y0);
    return invert_y ? kTop + f * (height - kTop - kBottom) : height - kBottom - f * (height - kTop - kBottom);
  }
};

std::string Px(double v) { return FormatFixed(v, 1); }

// svg open tag with size, id and accessible title
std::string SvgOpen(const std::string& id, int width, int height, const std::string& title) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" id=\"" + XmlEscape(id) + "\" width=\"" +
         std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " +
         std::to_string(width) + " " + std::to_string(height) + "\" role=\"img\" aria-label=\"" + XmlEscape(title) +
         "\">\n<title>" + XmlEscape(title) + "</title>\n";
}

// grid lines, tick labels, axis labels and the title
std::string AxesMarkup(const LinePlot& plot, const Axes& a, const Frame& f) {
  std::string s = "<g class=\"axes\" " + std::string(kFont) + " font-size=\"11\" fill=\"#333333\">\n";
  const int x_decimals = DecimalsFor(a.x_ticks.size() > 1 ? a.x_ticks[1] - a.x_ticks[0] : 1.0);
  const int y_decimals = DecimalsFor(a.y_ticks.size() > 1 ? a.y_ticks[1] - a.y_ticks[0] : 1.0);
  for (double t : a.x_ticks) {
    s += "<line x1=\"" + Px(f.Px(t)) + "\" y1=\"" + Px(kTop) + "\" x2=\"" + Px(f.Px(t)) + "\" y2=\"" +
         Px(plot.height - kBottom) + "\" stroke=\"#e4e4e4\"/>";
    s += "<text x=\"" + Px(f.Px(t)) + "\" y=\"" + Px(plot.height - kBottom + 15) + "\" text-anchor=\"middle\">" +
         FormatFixed(t, x_decimals) + "</text>\n";
  }
  for (double t : a.y_ticks) {
    s += "<line x1=\"" + Px(a.left) + "\" y1=\"" + Px(f.Py(t)) + "\" x2=\"" + Px(plot.width - kRight) + "\" y2=\"" +
         Px(f.Py(t)) + "\" stroke=\"" + (t == 0.0 ? "#9a9a9a" : "#e4e4e4") + "\"/>";
    s += "<text x=\"" + Px(a.left - 6) + "\" y=\"" + Px(f.Py(t) + 4) + "\" text-anchor=\"end\">" +
         FormatFixed(t, y_decimals) + "</text>\n";
  }
  // frame, axis labels, title
  s += "<rect x=\"" + Px(a.left) + "\" y=\"" + Px(kTop) + "\" width=\"" + Px(plot.width - a.left - kRight) +
       "\" height=\"" + Px(plot.height - kTop - kBottom) + "\" fill=\"none\" stroke=\"#9a9a9a\"/>\n";
  s += "<text x=\"" + Px(a.left + 0.5 * (plot.width - a.left - kRight)) + "\" y=\"" + Px(plot.height - 8) +
       "\" text-anchor=\"middle\">" + XmlEscape(plot.x_label) + "</text>\n";
  s += "<text transform=\"translate(14," + Px(kTop + 0.5 * (plot.height - kTop - kBottom)) +
       ") rotate(-90)\" text-anchor=\"middle\">" + XmlEscape(plot.y_label) + "</text>\n";
  s += "<text x=\"" + Px(a.left) + "\" y=\"18\" font-size=\"14\" font-weight=\"bold\" fill=\"#111111\">" +
       XmlEscape(plot.title) + "</text>\n</g>\n";
  return s;
}

// the legend: one row of swatches under the title, wrapping when it is full
std::string LegendMarkup(const LinePlot& plot, int left) {
  std::string s = "<g class=\"legend\" " + std::string(kFont) + " font-size=\"11\" fill=\"#333333\">\n";
  double x = left, y = 36;
  for (const PlotSeries& series : plot.series) {
    const double w = 30 + 6.2 * series.label.size();
    if (x + w > plot.width - kRight && x > left) x = left, y += 14;
    s += "<line x1=\"" + Px(x) + "\" y1=\"" + Px(y - 4) + "\" x2=\"" + Px(x + 20) + "\" y2=\"" + Px(y - 4) +
         "\" stroke=\"" + series.colour + "\" stroke-width=\"2.5\"" +
         (series.dashed ? " stroke-dasharray=\"5 3\"" : "") + "/>";
    s += "<text x=\"" + Px(x + 24) + "\" y=\"" + Px(y) + "\">" + XmlEscape(series.label) + "</text>\n";
    x += w + 10;
  }
  return s + "</g>\n";
}

// one series as a polyline clipped to the plot area (decimated to the pixel width)
std::string SeriesMarkup(const PlotSeries& series, const Frame& f, const std::string& clip) {
  std::vector<double> x, y;
  DecimateMinMax(series.x, series.y, 4 * static_cast<std::size_t>(f.width), &x, &y);
  std::string points, dots;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
    points += (points.empty() ? "" : " ") + Px(f.Px(x[i])) + "," + Px(f.Py(y[i]));
    if (series.points)
      dots += "<circle cx=\"" + Px(f.Px(x[i])) + "\" cy=\"" + Px(f.Py(y[i])) + "\" r=\"3\" fill=\"" + series.colour + "\"/>";
  }
  std::string s = !series.line ? std::string()
                                : "<polyline clip-path=\"url(#" + clip + ")\" fill=\"none\" stroke=\"" + series.colour +
                                      "\" stroke-width=\"1.8\" stroke-linejoin=\"round\"" +
                                      (series.dashed ? " stroke-dasharray=\"6 4\"" : "") + " points=\"" + points + "\"/>\n";
  return s + dots + (dots.empty() ? "" : "\n");
}

// a marker dot with its label, kept inside the plot (label left of points in the right part)
std::string MarkerMarkup(const PlotMarker& m, const Frame& f, const LinePlot& plot) {
  const double x = f.Px(m.x), y = f.Py(m.y);
  const bool right_part = x > f.a.left + 0.55 * (plot.width - f.a.left - kRight);
  const double ty = std::clamp(m.below ? y + 18 : y - 8, static_cast<double>(kTop) + 12,
                              static_cast<double>(plot.height - kBottom) - 4);
  return "<circle cx=\"" + Px(x) + "\" cy=\"" + Px(y) + "\" r=\"4.5\" fill=\"" + m.colour +
         "\" stroke=\"#ffffff\" stroke-width=\"1.5\"/><text x=\"" + Px(right_part ? x - 8 : x + 8) + "\" y=\"" +
         Px(ty) + "\" text-anchor=\"" + (right_part ? "end" : "start") + "\" " + kFont +
         " font-size=\"12\" font-weight=\"bold\" fill=\"" + m.colour + "\">" + XmlEscape(m.label) + "</text>\n";
}

// the shaded interval with its label at the top
std::string BandMarkup(const PlotBand& band, const Frame& f, const LinePlot& plot) {
  const double x0 = std::max<double>(f.Px(band.x0), f.a.left);
  const double x1 = std::min<double>(f.Px(band.x1), plot.width - kRight);
  if (!(x1 > x0)) return {};
  return "<rect class=\"band\" x=\"" + Px(x0) + "\" y=\"" + Px(kTop) + "\" width=\"" + Px(x1 - x0) + "\" height=\"" +
         Px(plot.height - kTop - kBottom) + "\" fill=\"#f2efe4\"/><text x=\"" + Px(x0 + 4) + "\" y=\"" +
         Px(kTop + 12) + "\" " + kFont + " font-size=\"10\" fill=\"#8a7f5a\">" + XmlEscape(band.label) + "</text>\n";
}

}  // namespace

std::string XmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\t': case '\n': case '\r': out += c; break;
      // XML allows no other C0 control character, even as a reference: shown as its escape
      default: out += static_cast<unsigned char>(c) < 0x20 ? Printable(std::string(1, c)) : std::string(1, c);
    }
  }
  return out;
}

std::string FormatFixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  std::string s = text;
  // "-0", "-0.00": no sign on a zero
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::vector<double> NiceTicks(double lo, double hi, int target) {
  // a flat span has no step the values can resolve (counting ticks up from lo would never reach hi)
  if (Flat(lo, hi) || !std::isfinite(lo) || !std::isfinite(hi) || target < 1) return {lo};
  // step: 1, 2, 5 or 10 times a power of ten, the nearest (by ratio) to span / target
  const double raw = (hi - lo) / target;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {2.0, 5.0, 10.0})
    if (std::abs(std::log(m * power / raw)) < std::abs(std::log(step / raw))) step = m * power;
  // every multiple of the step inside [lo, hi] (a hair of tolerance at the ends)
  std::vector<double> ticks;
  const double eps = 1e-9 * step;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps; k += 1.0) ticks.push_back(k * step + 0.0);
  return ticks;
}

void DecimateMinMax(const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points,
                    std::vector<double>* out_x, std::vector<double>* out_y) {
  const std::size_t n = std::min(x.size(), y.size());
  out_x->clear();
  out_y->clear();
  if (n <= max_points || max_points < 4) {
    out_x->assign(x.begin(), x.begin() + n);
    out_y->assign(y.begin(), y.begin() + n);
    return;
  }
  // buckets of consecutive points; each keeps its minimum and maximum, in x order; the ends stay
  const std::size_t buckets = max_points / 2 - 1;
  auto keep = [&](std::size_t i) {
    out_x->push_back(x[i]);
    out_y->push_back(y[i]);
  };
  keep(0);
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t begin = 1 + b * (n - 2) / buckets, end = 1 + (b + 1) * (n - 2) / buckets;
    if (begin >= end) continue;
    std::size_t lo = begin, hi = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    keep(std::min(lo, hi));
    if (lo != hi) keep(std::max(lo, hi));
  }
  keep(n - 1);
}

std::string RenderLinePlot(const LinePlot& plot) {
  const Axes a = MakeAxes(plot);
  const Frame f{a, plot.width, plot.height, plot.invert_y};
  const std::string clip = plot.id + "-clip";
  std::string s = SvgOpen(plot.id, plot.width, plot.height, plot.title);
  // background, clip region of the data area
  s += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n<defs><clipPath id=\"" + XmlEscape(clip) +
       "\"><rect x=\"" + Px(a.left) + "\" y=\"" + Px(kTop) + "\" width=\"" + Px(plot.width - a.left - kRight) +
       "\" height=\"" + Px(plot.height - kTop - kBottom) + "\"/></clipPath></defs>\n";
  // band under the grid, then axes, series, markers, legend
  if (plot.band) s += BandMarkup(*plot.band, f, plot);
  s += AxesMarkup(plot, a, f);
  for (const PlotSeries& series : plot.series) s += SeriesMarkup(series, f, XmlEscape(clip));
  for (const PlotMarker& m : plot.markers) s += MarkerMarkup(m, f, plot);
  s += LegendMarkup(plot, a.left);
  return s + "</svg>\n";
}

PlanView::PlanView(double x0, double x1, double y0, double y1, int width, int max_height, bool mirror_x,
                   const std::string& title, int margin)
    : x0_(x0), x1_(x1), y0_(y0), y1_(y1), width_(width), margin_(margin), top_(title.empty() ? 0 : 26),
      mirror_x_(mirror_x), title_(title) {
  // one scale for both axes: the tighter of the width and the height limits
  const double dx = std::max(x1 - x0, 1e-9), dy = std::max(y1 - y0, 1e-9);
  scale_ = std::min((width - 2.0 * margin) / dx, (max_height - 2.0 * margin - top_) / dy);
  height_ = static_cast<int>(std::ceil(dy * scale_ + 2.0 * margin + top_));
}

double PlanView::Px(double x) const {
  const double used = (x1_ - x0_) * scale_, left = 0.5 * (width_ - used);
  return mirror_x_ ? left + (x1_ - x) * scale_ : left + (x - x0_) * scale_;
}

double PlanView::Py(double y) const { return top_ + margin_ + (y - y0_) * scale_; }

std::string PlanView::Point(double x, double y) const { return FormatFixed(Px(x), 1) + "," + FormatFixed(Py(y), 1); }

void PlanView::Polygon(const std::vector<std::pair<double, double>>& points, const std::string& attributes) {
  std::string p;
  for (const auto& [x, y] : points) p.append(p.empty() ? "" : " ").append(Point(x, y));
  body_ += "<polygon points=\"" + p + "\" " + attributes + "/>\n";
}

void PlanView::Polyline(const std::vector<std::pair<double, double>>& points, const std::string& attributes) {
  std::string p;
  for (const auto& [x, y] : points) p.append(p.empty() ? "" : " ").append(Point(x, y));
  body_ += "<polyline points=\"" + p + "\" fill=\"none\" " + attributes + "/>\n";
}

void PlanView::Text(double x, double y, const std::string& text, const std::string& anchor,
                    const std::string& attributes) {
  body_ += "<text x=\"" + FormatFixed(Px(x), 1) + "\" y=\"" + FormatFixed(Py(y), 1) + "\" text-anchor=\"" + anchor +
           "\" " + kFont + " font-size=\"11\" " + attributes + ">" + XmlEscape(text) + "</text>\n";
}

void PlanView::ScaleBar(double length_factor, const std::string& unit) {
  // a round length near a fifth of the view's width, in output units
  const double target = 0.2 * (width_ - 2.0 * margin_) / scale_ * length_factor;
  const double power = std::pow(10.0, std::floor(std::log10(target)));
  double length = power;
  for (double m : {2.0, 5.0})
    if (m * power <= target) length = m * power;
  const double px = length / length_factor * scale_;
  const double x = margin_, y = height_ - 8.0;
  overlay_ += "<g class=\"scale-bar\"><line x1=\"" + FormatFixed(x, 1) + "\" y1=\"" + FormatFixed(y, 1) + "\" x2=\"" +
           FormatFixed(x + px, 1) + "\" y2=\"" + FormatFixed(y, 1) +
           "\" stroke=\"#333333\" stroke-width=\"2\"/><text x=\"" + FormatFixed(x + px + 6, 1) + "\" y=\"" +
           FormatFixed(y + 4, 1) + "\" " + kFont + " font-size=\"11\" fill=\"#333333\">" +
           XmlEscape(FormatFixed(length, DecimalsFor(length)) + " " + unit) + "</text></g>\n";
}

std::string PlanView::Render(const std::string& id, const std::string& css) const {
  std::string s = SvgOpen(id, width_, height_, title_);
  if (!css.empty()) s += "<style>" + css + "</style>\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  if (!title_.empty())
    s += "<text x=\"8\" y=\"18\" " + std::string(kFont) + " font-size=\"14\" font-weight=\"bold\" fill=\"#111111\">" +
         XmlEscape(title_) + "</text>\n";
  // the drawing clipped below the title, then the overlay (scale bar)
  s += "<defs><clipPath id=\"" + XmlEscape(id) + "-clip\"><rect x=\"0\" y=\"" + std::to_string(top_) + "\" width=\"" +
       std::to_string(width_) + "\" height=\"" + std::to_string(height_ - top_) + "\"/></clipPath></defs>\n";
  s += "<g clip-path=\"url(#" + XmlEscape(id) + "-clip)\">\n" + body_ + "</g>\n";
  return s + overlay_ + "</svg>\n";
}

std::string RenderCrushColourBar(const std::string& id, double max_value, const std::string& unit, int width) {
  const int height = 46, left = 12, bar = width - 2 * left;
  std::string s = SvgOpen(id, width, height, "crush colour scale");
  // the ramp as a gradient, the no-crush swatch at its left
  s += "<defs><linearGradient id=\"" + XmlEscape(id) + "-ramp\">";
  for (int i = 0; i <= 10; ++i)
    s += "<stop offset=\"" + FormatFixed(i / 10.0, 1) + "\" stop-color=\"" + CssColour(CrushColour(i == 0 ? 1e-9 : i / 10.0)) +
         "\"/>";
  s += "</linearGradient></defs>\n<rect x=\"" + std::to_string(left) + "\" y=\"4\" width=\"" + std::to_string(bar) +
       "\" height=\"14\" fill=\"url(#" + XmlEscape(id) + "-ramp)\" stroke=\"#999999\"/>\n";
  // labels: 0, half and the maximum
  s += "<g " + std::string(kFont) + " font-size=\"11\" fill=\"#333333\">";
  const int decimals = max_value >= 10 ? 1 : 2;
  s += "<text x=\"" + std::to_string(left) + "\" y=\"32\">0 (grey: none)</text>";
  s += "<text x=\"" + std::to_string(left + bar / 2) + "\" y=\"32\" text-anchor=\"middle\">" +
       FormatFixed(0.5 * max_value, decimals) + "</text>";
  s += "<text x=\"" + std::to_string(left + bar) + "\" y=\"32\" text-anchor=\"end\">" + FormatFixed(max_value, decimals) +
       " " + XmlEscape(unit) + "</text></g>\n";
  return s + "</svg>\n";
}

}  // namespace dymesh
