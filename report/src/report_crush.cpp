// The report's crush section: top and side views coloured by permanent crush, and C1..C6.
#include <algorithm>
#include <limits>
#include <numeric>

#include "dymesh/core/outline.h"
#include "dymesh/report/svg_plot.h"
#include "report_parts.h"

namespace dymesh::report {
namespace {

// a view of a body along one of its axes
struct Projection {
  int right, down;   // body axes drawn to the right (or left when mirrored) and downward
  int depth;         // body axis along the line of sight
  double toward;     // +1 or -1: the viewer sits on this side of the depth axis
  bool mirror;       // body `right` axis drawn to the left
  std::string name;  // "top", "side"
  std::string title;
};

// seen from above (SAE z down): x right, y down
Projection TopProjection(const std::string& body) { return {0, 1, 2, -1.0, false, "top", body + ": crush, top view"}; }

// seen from the damaged side (left: x to the left), otherwise from the right (x right), z down
Projection SideProjection(const std::string& body, CrushFace face) {
  if (face == CrushFace::kLeft) return {0, 2, 1, -1.0, true, "side", body + ": crush, side view from the left"};
  return {0, 2, 1, 1.0, false, "side", body + ": crush, side view from the right"};
}

// the undamaged mesh's silhouette in a projection (convex hull), output lengths
std::vector<std::pair<double, double>> Silhouette(const std::vector<Vec3>& vertices, const Projection& pr, double length) {
  std::vector<Vec2> points;
  for (const Vec3& p : vertices) points.emplace_back(p[pr.right] * length, p[pr.down] * length);
  std::vector<std::pair<double, double>> out;
  for (const Vec2& p : ConvexHull(std::move(points))) out.emplace_back(p.x(), p.y());
  return out;
}

// the six stations drawn in the top view, labelled outside the damaged face
void DrawStations(const CrushProfile& profile, double x0, double x1, double y0, double y1, double length, PlanView* view) {
  const bool across = profile.face == CrushFace::kFront || profile.face == CrushFace::kBack;
  for (int k = 0; k < 6; ++k) {
    const double s = profile.station[k] * length;
    const std::string label = std::string("C").append(std::to_string(k + 1));
    if (across) {
      view->Polyline({{x0, s}, {x1, s}}, "stroke=\"#333333\" stroke-width=\"0.8\" stroke-dasharray=\"3 3\"");
      const bool front = profile.face == CrushFace::kFront;
      view->Text(front ? x1 : x0, s, label, front ? "start" : "end", "fill=\"#111111\" dx=\"" + std::string(front ? "4" : "-4") + "\" dy=\"4\"");
    } else {
      view->Polyline({{s, y0}, {s, y1}}, "stroke=\"#333333\" stroke-width=\"0.8\" stroke-dasharray=\"3 3\"");
      const bool right = profile.face == CrushFace::kRight;
      view->Text(s, right ? y1 : y0, label, "middle", "fill=\"#111111\" dy=\"" + std::string(right ? "14" : "-5") + "\"");
    }
  }
}

// one view: visible triangles of the crushed mesh, far to near, coloured by crush; the undamaged
// silhouette dashed; in the top view the C1..C6 stations
std::string CrushView(const Context& c, int i, const Projection& pr, int width) {
  const BodyModel& model = c.sim.engine().model(i);
  const BodyState& state = c.sim.engine().state(i);
  const double length = c.units.length;
  // visible triangles (outward normal toward the viewer), far ones first
  std::vector<int> visible;
  for (int t = 0; t < static_cast<int>(state.tri_normal.size()); ++t)
    if (state.tri_normal[t][pr.depth] * pr.toward > 0.0) visible.push_back(t);
  std::vector<double> depth(state.tri_normal.size());  // each visible triangle's centre toward the viewer
  for (int t : visible) {
    const auto& tri = model.mesh.triangles[t];
    const Vec3 centre = (state.vertices[tri[0]] + state.vertices[tri[1]] + state.vertices[tri[2]]) / 3.0;
    depth[t] = centre[pr.depth] * pr.toward;
  }
  std::stable_sort(visible.begin(), visible.end(), [&](int a, int b) { return depth[a] < depth[b]; });
  // data box: the undamaged and crushed meshes, with room for the station labels
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto* vs : {&model.mesh.vertices, &state.vertices})
    for (const Vec3& p : *vs)
      x0 = std::min(x0, p[pr.right] * length), x1 = std::max(x1, p[pr.right] * length),
      y0 = std::min(y0, p[pr.down] * length), y1 = std::max(y1, p[pr.down] * length);
  const double pad = 0.06 * std::max(x1 - x0, y1 - y0);
  PlanView view(x0 - pad, x1 + pad, y0 - pad, y1 + pad, width, 420, pr.mirror, pr.title);
  // triangles
  const std::vector<double> crush = VertexCrush(c.sim, i);
  for (int t : visible) {
    const auto& tri = model.mesh.triangles[t];
    std::vector<std::pair<double, double>> pts;
    double sum = 0.0;
    for (int v : tri) {
      pts.emplace_back(state.vertices[v][pr.right] * length, state.vertices[v][pr.down] * length);
      sum += crush[v];
    }
    view.Polygon(pts, "class=\"" + CrushClass(c.crush_scale > 0.0 ? sum / 3.0 / c.crush_scale : 0.0) + "\"");
  }
  // the undamaged silhouette and, seen from above, the stations
  view.Polygon(Silhouette(model.mesh.vertices, pr, length), "fill=\"none\" stroke=\"#555555\" stroke-width=\"1\" stroke-dasharray=\"5 3\"");
  const CrushProfile& profile = c.summary.bodies[i].crush_profile;
  if (pr.name == "top" && profile.face != CrushFace::kNone) DrawStations(profile, x0, x1, y0, y1, length, &view);
  view.ScaleBar(1.0, c.units.length_name);
  return view.Render("plot-crush-" + pr.name + "-" + IdPart(model.name));
}

// C1..C6 against the station position, depth downward into the face
std::string ProfilePlot(const Context& c, int i) {
  const CrushProfile& p = c.summary.bodies[i].crush_profile;
  const std::string& name = c.sim.engine().model(i).name;
  const double l = c.units.length;
  const bool across = p.face == CrushFace::kFront || p.face == CrushFace::kBack;
  LinePlot plot;
  plot.id = "plot-crush-profile-" + IdPart(name);
  plot.title = name + ": crush profile C1..C6 (" + CrushFaceName(p.face) + ", width " + FormatFixed(p.width * l, 1) + " " +
               c.units.length_name + ")";
  plot.x_label = std::string(across ? "y" : "x") + ", body axes [" + c.units.length_name + "] (C1 at the " +
                 (across ? "left" : "front") + ")";
  plot.y_label = std::string("crush depth [") + c.units.length_name + "]";
  plot.invert_y = true;
  PlotSeries series{"C1..C6", {}, {}, "#b2182b"};
  series.points = true;
  for (int k = 0; k < 6; ++k) {
    series.x.push_back(p.station[k] * l);
    series.y.push_back(p.crush[k] * l);
    // labels alternate above and below the line so neighbours do not collide
    const std::string label = std::string("C").append(std::to_string(k + 1)).append(" ").append(FormatFixed(p.crush[k] * l, 1));
    plot.markers.push_back({p.station[k] * l, p.crush[k] * l, label,
                            "#333333", k % 2 == 1});
  }
  plot.series.push_back(std::move(series));
  return RenderLinePlot(plot);
}

// the six values with their stations, then the width, centre and largest depth
std::string ProfileTable(const Context& c, int i) {
  const CrushProfile& p = c.summary.bodies[i].crush_profile;
  const double l = c.units.length;
  const std::string unit = XmlEscape(c.units.length_name);
  const std::string axis = p.face == CrushFace::kFront || p.face == CrushFace::kBack ? "y" : "x";
  std::string s = "<table id=\"table-crush-" + XmlEscape(IdPart(c.sim.engine().model(i).name)) + "\">\n<thead><tr><th>" +
                  CrushFaceName(p.face) + "</th><th>station " + axis + " [" + unit + "]</th><th>crush [" + unit +
                  "]</th></tr></thead>\n<tbody>\n";
  for (int k = 0; k < 6; ++k)
    s += "<tr><td>C" + std::to_string(k + 1) + "</td><td>" + FormatFixed(p.station[k] * l, 2) + "</td><td>" +
         FormatFixed(p.crush[k] * l, 2) + "</td></tr>\n";
  s += "<tr><td>damage width L</td><td></td><td>" + FormatFixed(p.width * l, 2) + "</td></tr>\n";
  s += "<tr><td>centre of damage (" + axis + ")</td><td></td><td>" + FormatFixed(p.centre * l, 2) + "</td></tr>\n";
  s += "<tr><td>largest depth</td><td></td><td>" + FormatFixed(p.max_depth * l, 2) + "</td></tr>\n";
  return s + "</tbody></table>\n";
}

// one deformable body: views, colour scale, profile
std::string BodyCrush(const Context& c, int i) {
  const std::string& name = c.sim.engine().model(i).name;
  const CrushProfile& profile = c.summary.bodies[i].crush_profile;
  std::string s = "<h3>" + XmlEscape(name) + "</h3>\n<div class=\"figures\">\n";
  s += Figure(CrushView(c, i, TopProjection(name), 600), "Crushed mesh seen from above (x right, y down), coloured by permanent "
                                                         "crush |Delta|; dashed: undamaged outline; C1..C6 stations.");
  s += Figure(CrushView(c, i, SideProjection(name, profile.face), 600),
              "Crushed mesh seen from the side (z down), coloured by permanent crush; dashed: undamaged outline.");
  s += "</div>\n" + RenderCrushColourBar("crush-scale-" + IdPart(name), c.crush_scale * c.units.length,
                                         std::string("permanent crush [") + c.units.length_name + "]", 600);
  if (profile.face == CrushFace::kNone) return s + "<p class=\"note\">No measurable permanent crush (less than 1 mm).</p>\n";
  // the profile plot with its table beside it
  return s + "<div class=\"figures\">\n" +
         Figure(ProfilePlot(c, i), "Six-point crush (CRASH3 style) across the damage width of the damaged face; "
                                   "definition in the README.") +
         "<div>\n" + ProfileTable(c, i) + "</div>\n</div>\n";
}

}  // namespace

std::string CrushSection(const Context& c) {
  std::string s = "<h2 id=\"crush\">Crush</h2>\n";
  for (int i = 0; i < c.sim.engine().body_count(); ++i)
    if (!c.sim.engine().model(i).rigid) s += BodyCrush(c, i);
  return s;
}

}  // namespace dymesh::report
