#include "dymesh/report/report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "dymesh/report/colour_map.h"
#include "dymesh/report/svg_plot.h"
#include "dymesh/core/units.h"
#include "report_parts.h"

namespace dymesh {
namespace report {

namespace {

constexpr int kCrushClasses = 48;
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

// page style: plain, printable, no web fonts
constexpr const char* kPageCss = R"(
body { font-family: sans-serif; color: #222222; margin: 24px auto; max-width: 1260px; padding: 0 16px; }
h1 { font-size: 22px; margin-bottom: 4px; }
h2 { font-size: 18px; border-bottom: 1px solid #cccccc; padding-bottom: 4px; margin-top: 32px; }
h3 { font-size: 15px; margin: 18px 0 6px; }
p.meta { color: #555555; font-size: 13px; margin-top: 0; }
table { border-collapse: collapse; font-size: 13px; margin: 8px 0 16px; }
th, td { padding: 3px 12px; border-bottom: 1px solid #e6e6e6; text-align: right; }
th:first-child, td:first-child { text-align: left; color: #444444; }
thead th { border-bottom: 2px solid #bbbbbb; }
.figures { display: flex; flex-wrap: wrap; gap: 18px; }
figure { margin: 0; }
figcaption { font-size: 12px; color: #555555; max-width: 600px; margin-top: 2px; }
.status { border: 1px solid #9ac59a; background: #e6f4e6; padding: 4px 12px; font-size: 14px; }
.status-ended_in_contact, .status-interrupted, .status-failed_numerics { background: #fde2e1; border-color: #e0a0a0; }
.note { font-size: 12px; color: #555555; max-width: 900px; }
svg.plot { border: 1px solid #e6e6e6; }
)";

// a table row: label cell and value cells (values already escaped)
std::string Row(const std::string& label, const std::vector<std::string>& cells) {
  std::string s = "<tr><td>" + XmlEscape(label) + "</td>";
  for (const std::string& c : cells) s += "<td>" + c + "</td>";
  return s + "</tr>\n";
}

// one value per body
std::vector<std::string> PerBody(const Context& c, const std::function<std::string(int)>& f) {
  std::vector<std::string> cells;
  for (int i = 0; i < c.sim.engine().body_count(); ++i) cells.push_back(XmlEscape(f(i)));
  return cells;
}

// heading of the per-body table: one column per body, in its plot colour
std::string BodyTableHead(const Context& c) {
  std::string s = "<thead><tr><th></th>";
  for (int i = 0; i < c.sim.engine().body_count(); ++i)
    s += "<th style=\"color:" + BodyColour(i) + "\">" + XmlEscape(c.sim.engine().model(i).name) + "</th>";
  return s + "</tr></thead>\n";
}

// where a body's geometry came from, in a few words
std::string MeshSourceText(const Context& c, int i) {
  const MeshSource& m = c.sim.scenario().bodies[i].mesh;
  if (!m.box) return std::filesystem::path(m.file).filename().string();
  const double l = c.units.length;
  return "box " + FormatFixed(m.box_size.x() * l, 1) + " x " + FormatFixed(m.box_size.y() * l, 1) + " x " +
         FormatFixed(m.box_size.z() * l, 1) + " " + c.units.length_name;
}

const char* MotionName(MotionModel m) {
  switch (m) {
    case MotionModel::kFree6Dof: return "free";
    case MotionModel::kPlanar: return "planar";
    case MotionModel::kGravityGround: return "gravity";
    case MotionModel::kFixed: return "fixed";
  }
  return "?";
}

// inputs of each body as the scenario gave them (after unit conversion back)
std::string InputRows(const Context& c) {
  const OutputUnits& u = c.units;
  const Simulation& sim = c.sim;
  const bool us = sim.scenario().units == UnitSystem::kUS;
  const double inertia = us ? 1.0 / (units::kPoundForce * units::kInch) : 1.0;
  const char* inertia_name = us ? "lbf*in*s^2" : "kg*m^2";
  std::string s;
  s += Row("mesh", PerBody(c, [&](int i) { return MeshSourceText(c, i); }));
  s += Row("vertices / triangles", PerBody(c, [&](int i) {
             const TriMesh& m = sim.engine().model(i).mesh;
             return std::to_string(m.vertices.size()) + " / " + std::to_string(m.triangles.size());
           }));
  s += Row(std::string(us ? "weight [" : "mass [") + u.mass_name + "]",
           PerBody(c, [&](int i) { return Moves(sim, i) ? FormatFixed(sim.engine().model(i).mass * u.mass, 1) : "-"; }));
  s += Row(std::string("yaw inertia [") + inertia_name + "]", PerBody(c, [&](int i) {
             return Moves(sim, i) ? FormatFixed(sim.engine().model(i).inertia(2, 2) * inertia, 1) : "-";
           }));
  s += Row("restitution / friction", PerBody(c, [&](int i) {
             const BodyModel& m = sim.engine().model(i);
             return FormatFixed(m.restitution, 2) + " / " + FormatFixed(m.friction, 2);
           }));
  s += Row("rigid / motion", PerBody(c, [&](int i) {
             return std::string(sim.engine().model(i).rigid ? "rigid" : "deformable") + " / " +
                    MotionName(sim.scenario().bodies[i].motion);
           }));
  s += Row(std::string("initial speed [") + u.speed_name + "]", PerBody(c, [&](int i) {
             return FormatFixed(sim.history().front().bodies[i].rigid.velocity.norm() * u.speed, 2);
           }));
  s += Row("initial heading [deg]", PerBody(c, [&](int i) {
             return FormatFixed(sim.history().front().bodies[i].rigid.yaw * kRadToDeg, 1);
           }));
  return s;
}

// results of each body
std::string ResultRows(const Context& c) {
  const OutputUnits& u = c.units;
  const auto& b = c.summary.bodies;
  const double g = units::kStandardGravity;
  std::string s;
  s += Row(std::string("delta-V [") + u.speed_name + "]", PerBody(c, [&](int i) { return FormatFixed(b[i].delta_v * u.speed, 2); }));
  s += Row(std::string("delta-V longitudinal / lateral [") + u.speed_name + "]", PerBody(c, [&](int i) {
             return FormatFixed(b[i].delta_v_body.x() * u.speed, 2) + " / " + FormatFixed(b[i].delta_v_body.y() * u.speed, 2);
           }));
  s += Row("PDOF [deg] (clock)", PerBody(c, [&](int i) {
             return FormatFixed(b[i].pdof_deg, 1) + " (" + std::to_string(b[i].pdof_clock) + " o'clock)";
           }));
  s += Row("peak / average acceleration [g]", PerBody(c, [&](int i) {
             return FormatFixed(b[i].peak_accel / g, 1) + " / " + FormatFixed(b[i].average_accel / g, 1);
           }));
  s += Row(std::string("max permanent / dynamic crush [") + u.length_name + "]", PerBody(c, [&](int i) {
             return FormatFixed(b[i].max_crush * u.length, 2) + " / " + FormatFixed(b[i].max_dynamic_crush * u.length, 2);
           }));
  s += Row(std::string("crush left to its own nodes, untaken [") + u.length_name + "]", PerBody(c, [&](int i) {
             return FormatFixed(b[i].untaken_crush * u.length, 2);
           }));
  s += Row(std::string("crush / friction work [") + u.energy_name + "]", PerBody(c, [&](int i) {
             return FormatFixed(b[i].crush_energy * u.energy, 0) + " / " + FormatFixed(b[i].friction_energy * u.energy, 0);
           }));
  s += Row(std::string("final speed [") + u.speed_name + "] / yaw rate [deg/s]", PerBody(c, [&](int i) {
             return FormatFixed(b[i].final_velocity.norm() * u.speed, 2) + " / " + FormatFixed(b[i].final_yaw_rate * kRadToDeg, 1);
           }));
  return s;
}

// the run as a whole: energy and momentum balance, contact, diagnostics
std::string OverallTable(const Context& c) {
  const Summary& s = c.summary;
  const OutputUnits& u = c.units;
  auto one = [](const std::string& v) { return std::vector<std::string>{XmlEscape(v)}; };
  std::string t = "<table id=\"table-overall\">\n<thead><tr><th>run</th><th></th></tr></thead>\n";
  t += Row("status", one(RunStatusName(s.status)));
  t += Row("time step [s] / end time [s] / steps", one(FormatFixed(c.sim.scenario().time_step, 6) + " / " +
                                                      FormatFixed(s.end_time, 4) + " / " + std::to_string(s.steps)));
  t += Row("contact [s]", one(s.contact_start < 0 ? "none" : FormatFixed(s.contact_start, 4) + " to " + FormatFixed(s.contact_end, 4)));
  t += Row(std::string("kinetic energy before / after [") + u.energy_name + "]",
           one(FormatFixed(s.kinetic_before * u.energy, 0) + " / " + FormatFixed(s.kinetic_after * u.energy, 0)));
  t += Row(std::string("crush + friction energy [") + u.energy_name + "]",
           one(FormatFixed((s.crush_energy + s.friction_energy) * u.energy, 0)));
  if (s.support_work != 0.0)
    t += Row(std::string("work of weight and ground support (motion gravity) [") + u.energy_name + "]",
             one(FormatFixed(s.support_work * u.energy, 0)));
  t += Row("energy balance error (KE lost + support work - crush - friction) / KE lost",
           one(FormatFixed(100.0 * s.energy_balance_error, 3) + " %"));
  t += Row(std::string("node-law energy [") + u.energy_name + "] / discontinuity (crush work - node law)",
           one(FormatFixed(s.law_energy * u.energy, 0) + " / " +
               (s.crush_energy != 0.0 ? FormatFixed(100.0 * s.energy_discontinuity / s.crush_energy, 1) + " %" : "-")));
  t += Row(std::string("momentum before / after [") + u.momentum_name + "]",
           one(FormatFixed(s.momentum_before.norm() * u.momentum, 1) + " / " + FormatFixed(s.momentum_after.norm() * u.momentum, 1)));
  // per pair that touched (one row for a two-body run)
  for (const PairSummary& p : s.pairs) {
    const std::string names = "\"" + s.bodies[p.a].name + "\" / \"" + s.bodies[p.b].name + "\"";
    const std::string pair = s.pairs.size() > 1 ? " " + names : "";
    t += Row("closing / separation speed" + pair + " [" + u.speed_name + "]",
             one(FormatFixed(p.closing_speed * u.speed, 2) + " / " + FormatFixed(p.separation_speed * u.speed, 2)));
    t += Row("effective restitution at the CGs / at the impact point" + pair,
             one(FormatFixed(p.restitution(), 3) + " / " + FormatFixed(p.point_restitution(), 3)));
    t += Row("impulse ratio (tangential / normal impulse)" + pair, one(FormatFixed(p.impulse_ratio, 3)));
    // the turn the pair gave each of its bodies, and friction's part of it
    const auto turns = [](const double (&rate)[2]) {
      return FormatFixed(rate[0] * kRadToDeg, 1) + " / " + FormatFixed(rate[1] * kRadToDeg, 1);
    };
    t += Row("yaw rate change " + names + ", of it by friction [deg/s]",
             one(turns(p.yaw_rate_change) + ", " + turns(p.friction_yaw_rate_change)));
  }
  const ContactDiagnostics& d = s.diagnostics;
  t += Row("diagnostics: candidates / located / touching / faces pushed by rigid nodes",
           one(std::to_string(d.candidates) + " / " + std::to_string(d.located) + " / " + std::to_string(d.touching) +
               " / " + std::to_string(d.faces_pushed)));
  t += Row("limits: too far / max crush / growth / held unfound / pushback reduced / NaN guard",
           one(std::to_string(d.too_far_limited) + " / " + std::to_string(d.max_crush_limited) + " / " +
               std::to_string(d.growth_limited) + " / " + std::to_string(d.held_unfound) + " / " + std::to_string(d.reduced) +
               " / " + std::to_string(d.non_finite)));
  return t + "</table>\n";
}

// status and every warning, at the top: what to read before trusting anything below
std::string StatusBanner(const Summary& summary) {
  std::string s = "<div class=\"status status-" + std::string(RunStatusName(summary.status)) + "\" id=\"status\">";
  s += "<p><b>status: " + std::string(RunStatusName(summary.status)) + "</b>";
  if (summary.status == RunStatus::kInterrupted)
    s += " at t = " + FormatFixed(summary.end_time, 4) + " s: everything below covers the run up to then only";
  if (summary.status == RunStatus::kEndedInContact)
    s += ": the bodies were still pushing on each other at t = " + FormatFixed(summary.end_time, 4) + " s";
  if (summary.status == RunStatus::kFailedNumerics) s += ": the values below are not usable";
  s += "</p>\n";
  if (!summary.warnings.empty()) {
    s += "<ul id=\"warnings\">\n";
    for (const RunWarning& w : summary.warnings)
      s += "<li><code>" + XmlEscape(w.code) + "</code> " + (w.field.empty() ? "" : XmlEscape(w.field) + ": ") +
           XmlEscape(w.message) + "</li>\n";
    s += "</ul>\n";
  }
  return s + "</div>\n";
}

// the header and the summary tables
std::string SummarySection(const Context& c) {
  const Scenario& sc = c.sim.scenario();
  std::string s = "<h1>" + XmlEscape(sc.name.empty() ? "DyMESH run" : sc.name) + "</h1>\n";
  s += "<p class=\"meta\">scenario " + XmlEscape(sc.file) + "; units " + (sc.units == UnitSystem::kUS ? "US" : "SI") +
       "; accelerations in g; time in s</p>\n";
  s += StatusBanner(c.summary);
  s += "<h2 id=\"summary\">Summary</h2>\n<table id=\"table-summary\">\n" + BodyTableHead(c) + "<tbody>\n";
  s += "<tr><th colspan=\"" + std::to_string(c.sim.engine().body_count() + 1) + "\">inputs</th></tr>\n" + InputRows(c);
  s += "<tr><th colspan=\"" + std::to_string(c.sim.engine().body_count() + 1) + "\">results</th></tr>\n" + ResultRows(c);
  return s + "</tbody></table>\n" + OverallTable(c);
}

}  // namespace

std::string BodyColour(int i) {
  constexpr const char* kColours[] = {"#1f5fbf", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  return kColours[i % 7];
}

std::string IdPart(const std::string& name) {
  std::string id;
  for (char ch : name) id += std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' ? ch : '-';
  return id;
}

bool Moves(const Simulation& sim, int i) { return sim.scenario().bodies[i].motion != MotionModel::kFixed; }

std::size_t SampleAt(const Simulation& sim, double t) {
  const double k = std::round(t / sim.scenario().time_step);
  return std::min(static_cast<std::size_t>(std::max(k, 0.0)), sim.history().size() - 1);
}

std::vector<double> Times(const Simulation& sim) {
  std::vector<double> t;
  for (const Sample& s : sim.history()) t.push_back(s.time);
  return t;
}

std::vector<double> BodySeries(const Simulation& sim, int i, const std::function<double(const BodySample&)>& f) {
  std::vector<double> v;
  for (const Sample& s : sim.history()) v.push_back(f(s.bodies[i]));
  return v;
}

std::string Figure(const std::string& svg, const std::string& caption) {
  return "<figure>\n" + svg + "<figcaption>" + XmlEscape(caption) + "</figcaption>\n</figure>\n";
}

std::string CrushColourCss() {
  std::string css;
  for (int k = 0; k < kCrushClasses; ++k) {
    const std::string colour = CssColour(CrushColour(k == 0 ? 0.0 : static_cast<double>(k) / (kCrushClasses - 1)));
    css += "svg .c" + std::to_string(k) + " { fill: " + colour + "; stroke: " + colour + "; stroke-width: 0.4; }\n";
  }
  return css;
}

std::string CrushClass(double fraction) {
  // 0 (no crush) is its own class; any crush at all is at least class 1
  if (!(fraction > 0.0)) return "c0";
  const int k = std::clamp(static_cast<int>(std::ceil(fraction * (kCrushClasses - 1) - 0.5)), 1, kCrushClasses - 1);
  return std::string("c").append(std::to_string(k));
}

}  // namespace report

std::string ReportHtml(const Simulation& sim, const Summary& summary) {
  report::Context c{sim, summary, UnitsOf(sim.scenario().units)};
  for (const BodySummary& b : summary.bodies) c.crush_scale = std::max(c.crush_scale, b.max_crush);
  // polyglot page: valid HTML5 that also parses as XHTML (the tests load it as both)
  std::string page = "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n";
  page += "<meta charset=\"utf-8\"/>\n<title>" + XmlEscape(sim.scenario().name.empty() ? "DyMESH run" : sim.scenario().name) +
          " - DyMESH report</title>\n<style>" + std::string(report::kPageCss) + report::CrushColourCss() + "</style>\n</head>\n<body>\n";
  // summary, then the pulse, the trajectories and the crush
  page += report::SummarySection(c);
  page += report::TimeHistorySection(c);
  page += report::TrajectorySection(c);
  page += report::CrushSection(c);
  page += "<p class=\"note\">Written by dymesh. Accelerations are the CG accelerations from the collision loads "
          "(body axes: x forward, y right, z down). PDOF: direction the collision force comes from, 0 deg = "
          "frontal, +90 deg = from the right.</p>\n</body>\n</html>\n";
  return page;
}

}  // namespace dymesh
