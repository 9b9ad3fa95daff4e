#include "dymesh/core/results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "dymesh/core/atomic_file.h"
#include "dymesh/core/colour_map.h"
#include "dymesh/core/mesh_import.h"
#include "dymesh/core/report.h"
#include "dymesh/core/run_assessment.h"
#include "dymesh/core/svg_plot.h"
#include "dymesh/core/units.h"

namespace dymesh {

OutputUnits UnitsOf(UnitSystem system) {
  if (system == UnitSystem::kSI) return {1, 1, 1, 1, 1, 1, 1, "m", "m/s", "N", "N*m", "J", "kg*m/s", "kg"};
  return {1 / units::kInch, 1 / units::kMph, 1 / units::kPoundForce, 1 / (units::kPoundForce * units::kInch),
          1 / (units::kPoundForce * units::kFoot), 1 / (units::kPoundForce), 1 / units::kPoundMass,
          "in", "mph", "lbf", "lbf*in", "ft*lbf", "lbf*s", "lb"};
}

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

nlohmann::json Vector(const Vec3& v, double scale) { return {v.x() * scale, v.y() * scale, v.z() * scale}; }

// C1..C6 with the damage width and stations, in output lengths
nlohmann::json CrushProfileJson(const CrushProfile& p, double length) {
  nlohmann::json stations = nlohmann::json::array(), crush = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) {
    stations.push_back(p.station[i] * length);
    crush.push_back(p.crush[i] * length);
  }
  return {{"face", CrushFaceName(p.face)}, {"width", p.width * length}, {"centre", p.centre * length},
          {"stations", stations}, {"c", crush}, {"max_depth", p.max_depth * length}};
}

// integral of the body-frame collision force over the run [N s]
Vec3 BodyImpulse(const Simulation& sim, int body) {
  Vec3 impulse = Vec3::Zero();
  for (const Sample& s : sim.history()) impulse += s.bodies[body].loads.force_body * sim.scenario().time_step;
  return impulse;
}

BodySummary SummarizeBody(const Simulation& sim, int i) {
  const BodyModel& model = sim.engine().model(i);
  const BodyState& state = sim.engine().state(i);
  const RigidState& first = sim.history().front().bodies[i].rigid;
  BodySummary b;
  b.name = model.name;
  // delta-V of the CG, in the earth frame and in the body axes at t = 0
  b.delta_v_earth = state.rigid.velocity - first.velocity;
  b.delta_v_body = first.Rotation().transpose() * b.delta_v_earth;
  b.delta_v = b.delta_v_earth.norm();
  // PDOF: direction the collision force comes from, 0 deg frontal, +90 deg from the right (SAE)
  const Vec3 impulse = BodyImpulse(sim, i);
  b.pdof_deg = impulse.head<2>().norm() > 0.0 ? std::atan2(-impulse.y(), -impulse.x()) * kRadToDeg : 0.0;
  const int clock = static_cast<int>(std::lround((b.pdof_deg < 0 ? b.pdof_deg + 360.0 : b.pdof_deg) / 30.0)) % 12;
  b.pdof_clock = clock == 0 ? 12 : clock;
  // pulse: peak resultant acceleration, average over the contact duration
  for (const Sample& s : sim.history()) b.peak_accel = std::max(b.peak_accel, s.bodies[i].accel_body.norm());
  const double duration = sim.last_contact_time() - sim.first_contact_time();
  b.average_accel = duration > 0.0 ? b.delta_v / duration : 0.0;
  // crush: largest permanent and dynamic deformation, and where
  for (size_t v = 0; v < state.delta.size(); ++v) {
    const double crush = state.delta[v].norm();
    if (crush > b.max_crush) {
      b.max_crush = crush;
      b.max_crush_vertex = static_cast<int>(v);
      b.max_crush_location = model.mesh.vertices[v];
    }
    b.max_dynamic_crush = std::max(b.max_dynamic_crush, state.delta_max[v]);
  }
  b.crush_energy = state.crush_energy;
  b.law_energy = state.law_energy;
  b.friction_energy = state.friction_energy;
  b.final_velocity = state.rigid.velocity;
  b.final_yaw_rate = state.rigid.omega.z();
  b.crush_profile = MeasureCrushProfile(model, state);
  return b;
}

}  // namespace

Summary Summarize(const Simulation& sim) {
  Summary sum;
  const ContactEngine& engine = sim.engine();
  const Sample& first = sim.history().front();
  for (int i = 0; i < engine.body_count(); ++i) {
    sum.bodies.push_back(SummarizeBody(sim, i));
    // momentum and energy of the bodies that move (fixed barriers have no mass here)
    const BodyModel& model = engine.model(i);
    if (sim.scenario().bodies[i].motion == MotionModel::kFixed) continue;
    sum.momentum_before += model.mass * first.bodies[i].rigid.velocity;
    sum.momentum_after += model.mass * engine.state(i).rigid.velocity;
    sum.kinetic_before += KineticEnergy(model, first.bodies[i].rigid);
    sum.kinetic_after += KineticEnergy(model, engine.state(i).rigid);
  }
  for (const BodySummary& b : sum.bodies) {
    sum.crush_energy += b.crush_energy;
    sum.friction_energy += b.friction_energy;
    sum.law_energy += b.law_energy;
  }
  sum.energy_discontinuity = sum.crush_energy - sum.law_energy;
  const double lost = sum.kinetic_before - sum.kinetic_after;
  sum.energy_balance_error = lost != 0.0 ? (lost - sum.crush_energy - sum.friction_energy) / lost : 0.0;
  // closing and separation speed of the first pair along the impulse on body 0
  if (engine.body_count() >= 2) {
    const Vec3 impulse = first.bodies[0].rigid.Rotation() * BodyImpulse(sim, 0);
    if (impulse.norm() > 0.0) {
      const Vec3 n = impulse.normalized();
      const Vec3 before = first.bodies[0].rigid.velocity - first.bodies[1].rigid.velocity;
      const Vec3 after = engine.state(0).rigid.velocity - engine.state(1).rigid.velocity;
      sum.closing_speed = -before.dot(n);
      sum.separation_speed = after.dot(n);
    }
  }
  sum.contact_start = sim.first_contact_time();
  sum.contact_end = sim.last_contact_time();
  sum.steps = sim.steps();
  sum.end_time = sim.time();
  sum.diagnostics = sim.diagnostics();
  const RunAssessment assessment = AssessRun(sim, sum);
  sum.status = assessment.status;
  sum.warnings = assessment.warnings;
  return sum;
}

namespace {

// a failed run's overflowed values as JSON numbers (never null): +-inf as the largest finite
// magnitude, NaN as 0; the status says the values are not usable
void ReplaceNonFinite(nlohmann::json* j) {
  if (j->is_number_float()) {
    const double v = j->get<double>();
    if (std::isnan(v)) *j = 0.0;
    else if (std::isinf(v)) *j = v > 0 ? std::numeric_limits<double>::max() : std::numeric_limits<double>::lowest();
    return;
  }
  if (j->is_structured())
    for (auto& item : *j) ReplaceNonFinite(&item);
}

}  // namespace

nlohmann::json SummaryToJson(const Summary& s, UnitSystem system) {
  const OutputUnits u = UnitsOf(system);
  const double g = units::kStandardGravity;
  nlohmann::json j;
  j["units"] = {{"length", u.length_name}, {"speed", u.speed_name}, {"acceleration", "g"},
                {"energy", u.energy_name}, {"momentum", u.momentum_name}, {"time", "s"}, {"angle", "deg"}};
  for (const BodySummary& b : s.bodies) {
    j["bodies"].push_back({
        {"name", b.name},
        {"delta_v", b.delta_v * u.speed},
        {"delta_v_earth", Vector(b.delta_v_earth, u.speed)},
        {"delta_v_body", Vector(b.delta_v_body, u.speed)},
        {"pdof_deg", b.pdof_deg},
        {"pdof_clock", b.pdof_clock},
        {"peak_acceleration_g", b.peak_accel / g},
        {"average_acceleration_g", b.average_accel / g},
        {"max_crush", b.max_crush * u.length},
        {"max_crush_vertex", b.max_crush_vertex},
        {"max_crush_location_body", Vector(b.max_crush_location, u.length)},
        {"max_dynamic_crush", b.max_dynamic_crush * u.length},
        {"crush_energy", b.crush_energy * u.energy},
        {"friction_energy", b.friction_energy * u.energy},
        {"law_energy", b.law_energy * u.energy},
        {"final_velocity_earth", Vector(b.final_velocity, u.speed)},
        {"final_yaw_rate_deg_s", b.final_yaw_rate * kRadToDeg},
        {"crush_profile", CrushProfileJson(b.crush_profile, u.length)},
    });
  }
  const ContactDiagnostics& d = s.diagnostics;
  j["overall"] = {
      {"status", RunStatusName(s.status)},
      {"end_time_s", s.end_time},
      {"momentum_before", Vector(s.momentum_before, u.momentum)},
      {"momentum_after", Vector(s.momentum_after, u.momentum)},
      {"kinetic_energy_before", s.kinetic_before * u.energy},
      {"kinetic_energy_after", s.kinetic_after * u.energy},
      {"crush_energy", s.crush_energy * u.energy},
      {"friction_energy", s.friction_energy * u.energy},
      {"law_energy", s.law_energy * u.energy},
      {"energy_discontinuity", s.energy_discontinuity * u.energy},
      {"energy_balance_error", s.energy_balance_error},
      {"closing_speed", s.closing_speed * u.speed},
      {"separation_speed", s.separation_speed * u.speed},
      {"effective_restitution", s.closing_speed > 0 ? s.separation_speed / s.closing_speed : 0.0},
      {"contact_start_s", s.contact_start},
      {"contact_end_s", s.contact_end},
      {"steps", s.steps},
  };
  j["warnings"] = nlohmann::json::array();
  for (const RunWarning& w : s.warnings) j["warnings"].push_back({{"code", w.code}, {"field", w.field}, {"message", w.message}});
  j["diagnostics"] = {{"candidates", d.candidates}, {"located", d.located}, {"touching", d.touching},
                      {"too_far_limited", d.too_far_limited}, {"max_crush_limited", d.max_crush_limited},
                      {"growth_limited", d.growth_limited}, {"pushback_reduced", d.reduced},
                      {"non_finite", d.non_finite}, {"pair_steps_in_contact", d.pairs_in_contact}};
  ReplaceNonFinite(&j);
  return j;
}

namespace {

std::string HistoryCsv(const Simulation& sim) {
  const OutputUnits u = UnitsOf(sim.scenario().units);
  std::ostringstream csv;
  csv.precision(10);
  // header: one column per quantity, unit in brackets
  csv << "time[s]";
  for (int i = 0; i < sim.engine().body_count(); ++i) {
    const std::string n = sim.engine().model(i).name + ".";
    csv << ',' << n << "x[" << u.length_name << "]," << n << "y[" << u.length_name << "]," << n << "yaw[deg],"
        << n << "vx[" << u.speed_name << "]," << n << "vy[" << u.speed_name << "]," << n << "yaw_rate[deg/s],"
        << n << "ax_body[g]," << n << "ay_body[g]," << n << "az_body[g],"
        << n << "fx_body[" << u.force_name << "]," << n << "fy_body[" << u.force_name << "]," << n << "fz_body["
        << u.force_name << "]," << n << "mz_body[" << u.moment_name << "]," << n << "crush_energy["
        << u.energy_name << "]," << n << "friction_energy[" << u.energy_name << "]," << n << "kinetic_energy["
        << u.energy_name << "]";
  }
  csv << '\n';
  const double g = units::kStandardGravity;
  for (const Sample& s : sim.history()) {
    csv << s.time;
    for (int i = 0; i < sim.engine().body_count(); ++i) {
      const BodySample& b = s.bodies[i];
      csv << ',' << b.rigid.position.x() * u.length << ',' << b.rigid.position.y() * u.length << ','
          << b.rigid.yaw * kRadToDeg << ',' << b.rigid.velocity.x() * u.speed << ','
          << b.rigid.velocity.y() * u.speed << ',' << b.rigid.omega.z() * kRadToDeg << ','
          << b.accel_body.x() / g << ',' << b.accel_body.y() / g << ',' << b.accel_body.z() / g << ','
          << b.loads.force_body.x() * u.force << ',' << b.loads.force_body.y() * u.force << ','
          << b.loads.force_body.z() * u.force << ',' << b.loads.moment_body.z() * u.moment << ','
          << b.crush_energy * u.energy << ',' << b.friction_energy * u.energy << ','
          << KineticEnergy(sim.engine().model(i), b.rigid) * u.energy;
    }
    csv << '\n';
  }
  return csv.str();
}

}  // namespace

std::vector<double> VertexCrush(const Simulation& sim, int body) {
  const BodyState& state = sim.engine().state(body);
  std::vector<double> crush(state.delta.size());
  for (std::size_t v = 0; v < crush.size(); ++v) crush[v] = state.delta[v].norm();
  return crush;
}

namespace {

// writes each file unless asked to stop, recording which were written and which not
class OutputWriter {
 public:
  explicit OutputWriter(const std::function<bool()>& stop) : stop_(stop) {}
  void Emit(const std::string& path, const std::function<void()>& write) {
    if (stop_ && stop_()) {
      out_.not_written.push_back(path);
      return;
    }
    write();
    out_.written.push_back(path);
  }
  const WrittenOutputs& result() const { return out_; }

 private:
  const std::function<bool()>& stop_;
  WrittenOutputs out_;
};

// a body's meshes: OBJ, and PLY with the crush per vertex (scenario length unit, colours on a
// scale shared by every body of the run)
void WriteBodyMeshes(const Simulation& sim, int i, const std::string& dir, double crush_scale, OutputWriter* writer) {
  const OutputUnits u = UnitsOf(sim.scenario().units);
  const BodyModel& model = sim.engine().model(i);
  TriMesh deformed{sim.engine().state(i).vertices, model.mesh.triangles};
  TriMesh undeformed = model.mesh;
  for (Vec3& p : deformed.vertices) p *= u.length;
  for (Vec3& p : undeformed.vertices) p *= u.length;
  // crush scalar and colour per vertex
  std::vector<double> crush = VertexCrush(sim, i);
  std::vector<Rgb> colours;
  for (double& c : crush) {
    colours.push_back(CrushColour(crush_scale > 0.0 ? c / crush_scale : 0.0));
    c *= u.length;
  }
  const std::string base = (std::filesystem::path(dir) / model.name).string();
  const std::string scalar = std::string("crush: permanent crush |Delta| [") + u.length_name + "], colour scale 0 to " +
                             FormatFixed(crush_scale * u.length, 3) + " " + u.length_name;
  for (const auto& [suffix, mesh] : {std::pair{"_undeformed", &undeformed}, std::pair{"_deformed", &deformed}}) {
    const std::string what = model.name + suffix + ", body frame about the CG, " + u.length_name;
    const std::string obj = base + suffix + ".obj", ply = base + suffix + ".ply";
    writer->Emit(obj, [&] { WriteObj(*mesh, obj, what); });
    writer->Emit(ply, [&] { WritePly(*mesh, crush, colours, ply, what + "\n" + scalar); });
  }
}

}  // namespace

std::vector<std::string> OutputFileNames(const Scenario& scenario) {
  std::vector<std::string> names;
  for (const BodySpec& b : scenario.bodies)
    for (const char* suffix : {"_undeformed", "_deformed"})
      for (const char* ext : {".obj", ".ply"}) names.push_back(b.name + suffix + ext);
  for (const char* name : {"history.csv", "report.html", "summary.json"}) names.push_back(name);
  return names;
}

WrittenOutputs WriteOutputs(const Simulation& sim, const Summary& summary, const std::string& dir,
                            const std::function<bool()>& stop) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  // an earlier summary must not vouch for the files about to be replaced
  const std::string summary_path = (fs::path(dir) / "summary.json").string();
  std::error_code ec;
  fs::remove(summary_path, ec);
  // meshes (crush colours on the run's largest crush)
  OutputWriter writer(stop);
  double crush_scale = 0.0;
  for (const BodySummary& b : summary.bodies) crush_scale = std::max(crush_scale, b.max_crush);
  for (int i = 0; i < sim.engine().body_count(); ++i) WriteBodyMeshes(sim, i, dir, crush_scale, &writer);
  // time history and report, then the summary last: its presence means the outputs are complete
  const std::string history = (fs::path(dir) / "history.csv").string();
  writer.Emit(history, [&] { WriteFileAtomically(history, HistoryCsv(sim)); });
  const std::string report = (fs::path(dir) / "report.html").string();
  writer.Emit(report, [&] { WriteFileAtomically(report, ReportHtml(sim, summary)); });
  writer.Emit(summary_path, [&] {
    nlohmann::json j = SummaryToJson(summary, sim.scenario().units);
    j["scenario"] = {{"file", sim.scenario().file}, {"name", sim.scenario().name}};
    j["files"] = OutputFileNames(sim.scenario());
    WriteFileAtomically(summary_path, j.dump(2) + "\n");
  });
  return writer.result();
}

}  // namespace dymesh
