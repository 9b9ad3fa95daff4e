// The report's time-history plots and the top view of the trajectories.
#include <algorithm>
#include <cmath>
#include <limits>

#include "dymesh/core/outline.h"
#include "dymesh/report/svg_plot.h"
#include "dymesh/core/units.h"
#include "report_parts.h"

namespace dymesh::report {
namespace {

constexpr int kPlotWidth = 600, kPlotHeight = 320;

// a plot over the run's time with the contact duration shaded
LinePlot TimePlot(const Context& c, const std::string& id, const std::string& title, const std::string& y_label) {
  LinePlot p;
  p.id = id;
  p.title = title;
  p.x_label = "time [s]";
  p.y_label = y_label;
  p.width = kPlotWidth;
  p.height = kPlotHeight;
  if (c.summary.contact_start >= 0.0) p.band = PlotBand{c.summary.contact_start, c.summary.contact_end, "contact"};
  return p;
}

// CG acceleration of one body: longitudinal, lateral and resultant, with the peak marked
std::string AccelerationPlot(const Context& c, int i) {
  const std::string& name = c.sim.engine().model(i).name;
  const double g = units::kStandardGravity;
  LinePlot p = TimePlot(c, "plot-acceleration-" + IdPart(name), name + ": CG acceleration pulse", "acceleration [g]");
  const std::vector<double> t = Times(c.sim);
  p.series.push_back({"longitudinal (x)", t, BodySeries(c.sim, i, [&](const BodySample& b) { return b.accel_body.x() / g; }), "#1f5fbf"});
  p.series.push_back({"lateral (y)", t, BodySeries(c.sim, i, [&](const BodySample& b) { return b.accel_body.y() / g; }), "#2ca02c"});
  PlotSeries resultant{"resultant", t, BodySeries(c.sim, i, [&](const BodySample& b) { return b.accel_body.norm() / g; }), "#222222"};
  resultant.dashed = true;
  // the peak of the resultant
  const auto peak = std::max_element(resultant.y.begin(), resultant.y.end());
  if (peak != resultant.y.end() && *peak > 0.0)
    p.markers.push_back({t[peak - resultant.y.begin()], *peak, "peak " + FormatFixed(*peak, 1) + " g", "#222222"});
  p.series.push_back(std::move(resultant));
  return Figure(RenderLinePlot(p), "Acceleration of " + name +
                                       "'s CG from the collision loads, body axes (x forward, y right), in g.");
}

// delta-V magnitude of every moving body, final value and PDOF marked
std::string DeltaVPlot(const Context& c) {
  const OutputUnits& u = c.units;
  LinePlot p = TimePlot(c, "plot-delta-v", "Delta-V", std::string("delta-V [") + u.speed_name + "]");
  const std::vector<double> t = Times(c.sim);
  for (int i = 0; i < c.sim.engine().body_count(); ++i) {
    if (!Moves(c.sim, i)) continue;
    const Vec3 v0 = c.sim.history().front().bodies[i].rigid.velocity;
    const BodySummary& b = c.summary.bodies[i];
    p.series.push_back({b.name, t, BodySeries(c.sim, i, [&](const BodySample& s) { return (s.rigid.velocity - v0).norm() * u.speed; }),
                        BodyColour(i)});
    p.markers.push_back({t.back(), p.series.back().y.back(),
                         b.name + ": " + FormatFixed(b.delta_v * u.speed, 1) + " " + u.speed_name + ", PDOF " +
                             FormatFixed(b.pdof_deg, 0) + " deg (" + std::to_string(b.pdof_clock) + " o'clock)",
                         BodyColour(i)});
  }
  return Figure(RenderLinePlot(p), "Magnitude of each body's CG velocity change since t = 0. PDOF: direction the "
                                   "collision force comes from (0 deg frontal, +90 deg from the right).");
}

// collision force on every moving body, longitudinal and lateral (body axes)
std::string ForcePlot(const Context& c) {
  const OutputUnits& u = c.units;
  LinePlot p = TimePlot(c, "plot-force", "Contact force", std::string("force [") + u.force_name + "]");
  const std::vector<double> t = Times(c.sim);
  for (int i = 0; i < c.sim.engine().body_count(); ++i) {
    if (!Moves(c.sim, i)) continue;
    const std::string& name = c.sim.engine().model(i).name;
    p.series.push_back({name + " longitudinal", t,
                        BodySeries(c.sim, i, [&](const BodySample& b) { return b.loads.force_body.x() * u.force; }), BodyColour(i)});
    PlotSeries lateral{name + " lateral", t, BodySeries(c.sim, i, [&](const BodySample& b) { return b.loads.force_body.y() * u.force; }),
                       BodyColour(i)};
    lateral.dashed = true;
    p.series.push_back(std::move(lateral));
  }
  return Figure(RenderLinePlot(p), "Collision force on each body at its CG, body axes (x forward, y right).");
}

// collision yaw moment on every moving body
std::string MomentPlot(const Context& c) {
  const OutputUnits& u = c.units;
  LinePlot p = TimePlot(c, "plot-moment", "Contact yaw moment", std::string("moment [") + u.moment_name + "]");
  const std::vector<double> t = Times(c.sim);
  for (int i = 0; i < c.sim.engine().body_count(); ++i) {
    if (!Moves(c.sim, i)) continue;
    p.series.push_back({c.sim.engine().model(i).name, t,
                        BodySeries(c.sim, i, [&](const BodySample& b) { return b.loads.moment_body.z() * u.moment; }), BodyColour(i)});
  }
  return Figure(RenderLinePlot(p), "Collision moment about each body's CG, body z axis (positive turns the nose right).");
}

// kinetic, crush and friction energy of the moving bodies (and, with a `gravity` body, the work its
// weight and ground support took), and their sum (flat when balanced)
std::string EnergyPlot(const Context& c) {
  const OutputUnits& u = c.units;
  LinePlot p = TimePlot(c, "plot-energy", "Energy (balance error " + FormatFixed(100.0 * c.summary.energy_balance_error, 2) + " %)",
                        std::string("energy [") + u.energy_name + "]");
  std::vector<double> kinetic, crush, friction, support, total;
  for (const Sample& s : c.sim.history()) {
    double k = 0.0, cr = 0.0, fr = 0.0, su = 0.0;
    for (int i = 0; i < c.sim.engine().body_count(); ++i) {
      if (Moves(c.sim, i)) k += KineticEnergy(c.sim.engine().model(i), s.bodies[i].rigid);
      cr += s.bodies[i].crush_energy;
      fr += s.bodies[i].friction_energy;
      su -= s.bodies[i].support_work;
    }
    kinetic.push_back(k * u.energy), crush.push_back(cr * u.energy), friction.push_back(fr * u.energy);
    support.push_back(su * u.energy);
    total.push_back((k + cr + fr + su) * u.energy);
  }
  const std::vector<double> t = Times(c.sim);
  const bool supported = c.summary.support_work != 0.0;
  p.series.push_back({"kinetic", t, kinetic, "#1f5fbf"});
  p.series.push_back({"crush", t, crush, "#d62728"});
  p.series.push_back({"friction", t, friction, "#2ca02c"});
  if (supported) p.series.push_back({"taken by weight and ground support", t, support, "#9467bd"});
  PlotSeries sum{supported ? "kinetic + crush + friction + support" : "kinetic + crush + friction", t, total, "#222222"};
  sum.dashed = true;
  p.series.push_back(std::move(sum));
  return Figure(RenderLinePlot(p), "Kinetic energy of the moving bodies, work of the crush law and friction"
                                   " (and the work a gravity body's weight and ground support took). "
                                   "Their sum stays at the initial kinetic energy when the energy balances.");
}

// contact area of every deformable body's own nodes (a rigid body's nodes never carry force)
std::string ContactAreaPlot(const Context& c) {
  const OutputUnits& u = c.units;
  LinePlot p = TimePlot(c, "plot-contact-area", "Contact area", std::string("area [") + u.length_name + "^2]");
  const std::vector<double> t = Times(c.sim);
  for (int i = 0; i < c.sim.engine().body_count(); ++i) {
    if (c.sim.engine().model(i).rigid) continue;
    p.series.push_back({c.sim.engine().model(i).name, t,
                        BodySeries(c.sim, i, [&](const BodySample& b) { return b.contact_area * u.length * u.length; }),
                        BodyColour(i)});
  }
  return Figure(RenderLinePlot(p), "Area of each deformable body's own nodes carrying force (spec section 3 node areas), "
                                   "mean over the step's passes. Two bodies whose curves differ meet the interface "
                                   "differently with their meshes (README, Known limits).");
}

// the instants drawn in the top view: first contact, maximum engagement, separation
struct Instant {
  std::size_t sample;
  std::string label, dash;
  bool deformed;  // outline of the final (crushed) mesh rather than the undamaged one
};

// maximum engagement: the sample of the contact window where the main pair has approached most
// along its impulse (the common-velocity instant)
std::size_t MaxEngagement(const Context& c, std::size_t first, std::size_t last) {
  const std::vector<Sample>& h = c.sim.history();
  if (c.summary.main_pair < 0) return first;
  const PairSummary& p = c.summary.pairs[c.summary.main_pair];
  std::size_t best = first;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = first; k <= last; ++k) {
    const double d = (h[k].bodies[p.a].rigid.position - h[k].bodies[p.b].rigid.position).dot(p.direction);
    if (d < lowest) lowest = d, best = k;
  }
  return best;
}

std::vector<Instant> Instants(const Context& c) {
  const Summary& s = c.summary;
  const std::size_t end = c.sim.history().size() - 1;
  if (s.contact_start < 0.0) return {{0, "start", "2 3", false}, {end, "end", "", true}};
  const std::size_t first = SampleAt(c.sim, s.contact_start), last = SampleAt(c.sim, s.contact_end);
  const std::size_t engaged = MaxEngagement(c, first, last);
  auto at = [&](std::size_t k) { return " (t = " + FormatFixed(c.sim.history()[k].time, 4) + " s)"; };
  return {{first, "first contact" + at(first), "2 3", false},
          {engaged, "maximum engagement" + at(engaged), "8 4", false},
          {last, "separation" + at(last), "", true}};
}

// outline of body i at a sample, in output lengths
std::vector<std::pair<double, double>> OutlineAt(const Context& c, int i, const Instant& instant) {
  const std::vector<Vec3>& vertices = instant.deformed ? c.sim.engine().state(i).vertices : c.sim.engine().model(i).mesh.vertices;
  std::vector<std::pair<double, double>> points;
  for (const Vec2& p : PlanOutline(vertices, c.sim.history()[instant.sample].bodies[i].rigid))
    points.emplace_back(p.x() * c.units.length, p.y() * c.units.length);
  return points;
}

// CG path of body i over the whole run (at most about 2000 points), output lengths
std::vector<std::pair<double, double>> CgPath(const Context& c, int i) {
  const std::vector<Sample>& h = c.sim.history();
  const std::size_t stride = std::max<std::size_t>(1, h.size() / 2000);
  std::vector<std::pair<double, double>> path;
  for (std::size_t k = 0; k < h.size(); k += stride) {
    const Vec3& p = h[k].bodies[i].rigid.position;
    path.emplace_back(p.x() * c.units.length, p.y() * c.units.length);
  }
  const Vec3& p = h.back().bodies[i].rigid.position;
  path.emplace_back(p.x() * c.units.length, p.y() * c.units.length);
  return path;
}

}  // namespace

std::string TimeHistorySection(const Context& c) {
  std::string s = "<h2 id=\"pulse\">Pulse</h2>\n<div class=\"figures\">\n";
  for (int i = 0; i < c.sim.engine().body_count(); ++i)
    if (Moves(c.sim, i)) s += AccelerationPlot(c, i);
  s += DeltaVPlot(c) + ForcePlot(c) + MomentPlot(c) + ContactAreaPlot(c) + EnergyPlot(c);
  return s + "</div>\n";
}

std::string TrajectorySection(const Context& c) {
  // every outline and path; the view frames the moving bodies (a long barrier is cut off)
  const std::vector<Instant> instants = Instants(c);
  std::vector<std::vector<std::vector<std::pair<double, double>>>> outlines(c.sim.engine().body_count());
  std::vector<std::vector<std::pair<double, double>>> paths;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  auto grow = [&](const std::vector<std::pair<double, double>>& pts) {
    for (const auto& [x, y] : pts) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  bool any_moves = false;
  for (int i = 0; i < c.sim.engine().body_count(); ++i) any_moves = any_moves || Moves(c.sim, i);
  for (int i = 0; i < c.sim.engine().body_count(); ++i) {
    for (const Instant& instant : instants) outlines[i].push_back(OutlineAt(c, i, instant));
    paths.push_back(CgPath(c, i));
    if (any_moves && !Moves(c.sim, i)) continue;
    for (const auto& outline : outlines[i]) grow(outline);
    grow(paths.back());
  }
  const double pad = 0.15 * std::max(x1 - x0, y1 - y0);
  // outlines (dotted, dashed, solid), CG paths and CG dots; earth x right, y down (SAE top view)
  PlanView view(x0 - pad, x1 + pad, y0 - pad, y1 + pad, 1220, 520, false, "Top view: trajectories and outlines (earth frame)");
  for (int i = 0; i < c.sim.engine().body_count(); ++i) {
    const std::string colour = BodyColour(i);
    for (std::size_t k = 0; k < instants.size(); ++k) {
      // the last instant filled lightly, the others open
      std::string attributes = k + 1 == instants.size() ? "fill=\"" + colour + "\" fill-opacity=\"0.12\"" : "fill=\"none\"";
      attributes += " stroke=\"" + colour + "\" stroke-width=\"1.6\"";
      if (!instants[k].dash.empty()) attributes += " stroke-dasharray=\"" + instants[k].dash + "\"";
      view.Polygon(outlines[i][k], attributes);
    }
    view.Polyline(paths[i], "stroke=\"" + colour + "\" stroke-width=\"1.2\" stroke-opacity=\"0.8\"");
    for (const Instant& instant : instants) {
      const Vec3& p = c.sim.history()[instant.sample].bodies[i].rigid.position;
      view.Add("<circle cx=\"" + FormatFixed(view.Px(p.x() * c.units.length), 1) + "\" cy=\"" +
               FormatFixed(view.Py(p.y() * c.units.length), 1) + "\" r=\"2.5\" fill=\"" + colour + "\"/>\n");
    }
    view.Text(paths[i].back().first, paths[i].back().second, c.sim.engine().model(i).name, "middle",
              "fill=\"" + colour + "\" font-weight=\"bold\" dy=\"-6\"");
  }
  view.ScaleBar(1.0, c.units.length_name);
  std::string caption = "Earth frame seen from above (x right, y down: SAE, z down into the page). Lines: CG paths. "
                        "Outlines: convex hull of each mesh at ";
  for (std::size_t k = 0; k < instants.size(); ++k)
    caption += instants[k].label + (instants[k].dash.empty() ? " solid, filled" : instants[k].dash == "2 3" ? " dotted" : " dashed") +
               (k + 2 < instants.size() ? "; " : k + 1 < instants.size() ? " and " : ".");
  caption += " The first two use the undamaged mesh (their overlap is the crush to come), the last the crushed one.";
  return "<h2 id=\"trajectories\">Trajectories</h2>\n" + Figure(view.Render("plot-trajectories"), caption);
}

}  // namespace dymesh::report
