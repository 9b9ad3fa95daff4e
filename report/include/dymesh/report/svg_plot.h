#pragma once
#include <optional>
#include <string>
#include <vector>

/// Inline SVG drawn by the engine for the HTML report: line plots against time, and plan views
/// (equal scale on both axes) for trajectories and crush. Output is well-formed XML (XHTML-safe),
/// with no scripts, fonts or external references.
namespace dymesh {

/// Text made safe for XML content and attribute values (&, <, >, "; a control character XML does not
/// allow is written as its escape, \x01).
std::string XmlEscape(const std::string& text);

/// A number with `decimals` digits after the point ("-0" printed as "0").
std::string FormatFixed(double value, int decimals);

/// "Nice" tick positions (1, 2 or 5 times a power of ten) covering [lo, hi] with about `target` ticks.
std::vector<double> NiceTicks(double lo, double hi, int target);

/// Keeps at most about `max_points` points of a series, preserving each bucket's minimum and
/// maximum of y (peaks survive); x must be ascending. Short series are returned unchanged.
void DecimateMinMax(const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points,
                    std::vector<double>* out_x, std::vector<double>* out_y);

/// One line of a plot.
struct PlotSeries {
  std::string label;
  std::vector<double> x{}, y{};
  std::string colour = "#1f77b4";  ///< CSS colour
  bool dashed = false;
  bool points = false;             ///< also draw a dot at every point
  bool line = true;                ///< draw the line (false with points: a scatter plot)
};

/// A labelled point (e.g. the final delta-V).
struct PlotMarker {
  double x = 0.0, y = 0.0;
  std::string label;
  std::string colour = "#000000";
  bool below = false;  ///< label under the point rather than above
};

/// A shaded interval of x (e.g. the contact duration).
struct PlotBand {
  double x0 = 0.0, x1 = 0.0;
  std::string label;
};

/// A line plot: axes with nice ticks and grid, a legend row, optional band and markers.
struct LinePlot {
  std::string id;                  ///< element id of the <svg>
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series{};
  std::vector<PlotMarker> markers{};
  std::optional<PlotBand> band{};
  bool invert_y = false;           ///< y grows downward (crush depth into a face)
  bool include_zero = true;        ///< y range always contains 0
  int width = 600, height = 320;   ///< [px]
};

/// The plot as an <svg> element.
std::string RenderLinePlot(const LinePlot& plot);

/// A plan view: data coordinates mapped to pixels with one scale on both axes (x right, y down,
/// or x to the left when `mirror_x`), fitted into `width` pixels and at most `max_height`.
class PlanView {
 public:
  /// Frames the data box [x0, x1] x [y0, y1]; `title` above, `margin` pixels around the data.
  PlanView(double x0, double x1, double y0, double y1, int width, int max_height, bool mirror_x,
           const std::string& title, int margin = 24);

  /// Pixel coordinates of a data point.
  double Px(double x) const;
  double Py(double y) const;
  /// "x,y" of a data point in pixels (for points lists).
  std::string Point(double x, double y) const;

  /// Appends raw SVG markup (already escaped) drawn in order.
  void Add(const std::string& markup) { body_ += markup; }
  /// A closed polygon through data points with the given attributes (e.g. fill="..." class="...").
  void Polygon(const std::vector<std::pair<double, double>>& points, const std::string& attributes);
  /// An open polyline through data points.
  void Polyline(const std::vector<std::pair<double, double>>& points, const std::string& attributes);
  /// Text at a data point; `anchor` is start, middle or end.
  void Text(double x, double y, const std::string& text, const std::string& anchor, const std::string& attributes = "");

  /// A scale bar (drawn over everything) of a round length, labelled in `unit` (data units times `length_factor`).
  void ScaleBar(double length_factor, const std::string& unit);

  /// The view as an <svg> element with `id` and an optional `style` block of CSS classes.
  std::string Render(const std::string& id, const std::string& css = "") const;

  int width() const { return width_; }
  int height() const { return height_; }
  double scale() const { return scale_; }  ///< [px per data unit]

 private:
  double x0_, x1_, y0_, y1_;
  int width_, height_, margin_, top_;
  double scale_;
  bool mirror_x_;
  std::string title_, body_, overlay_;
};

/// A horizontal colour bar legend (crush colour map) from 0 to `max_value`, labelled with `unit`.
std::string RenderCrushColourBar(const std::string& id, double max_value, const std::string& unit, int width);

}  // namespace dymesh
