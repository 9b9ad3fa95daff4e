#include "dymesh/ensemble/sample_run.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/run_assessment.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/units.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/mesh_import.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh::ensemble {
namespace {

using Json = nlohmann::json;

Json Vector(const Vec3& v, double scale) { return {v.x() * scale, v.y() * scale, v.z() * scale}; }

// the record's body entry (scenario units); the statistics track its kOutputQuantities
Json BodyJson(const BodySummary& b, const RigidState& final_state, const OutputUnits& u) {
  Json c = Json::array();
  for (double x : b.crush_profile.crush) c.push_back(x * u.length);
  return {{"name", b.name}, {"delta_v", b.delta_v * u.speed}, {"delta_v_earth", Vector(b.delta_v_earth, u.speed)},
          {"pdof_deg", b.pdof_deg}, {"peak_acceleration_g", b.peak_accel / units::kStandardGravity},
          {"average_acceleration_g", b.average_accel / units::kStandardGravity}, {"max_crush", b.max_crush * u.length},
          {"crush_energy", b.crush_energy * u.energy}, {"c", c},
          {"final_position", Vector(final_state.position, u.length)},
          {"final_heading_deg", final_state.yaw * kRadToDeg}, {"final_velocity", Vector(final_state.velocity, u.speed)},
          {"final_yaw_rate_deg_s", b.final_yaw_rate * kRadToDeg},
          {"peak_contact_area", b.peak_contact_area * u.length * u.length},
          {"support_work", b.support_work * u.energy}};
}

// the fields every record has, whatever became of the sample
Json RecordHead(const Spec& spec, int index, const std::vector<double>& values) {
  Json inputs = Json::object();
  for (std::size_t k = 0; k < spec.inputs.size(); ++k) inputs[spec.inputs[k].name] = values[k];
  return {{"index", index}, {"spec_hash", HashText(spec.hash)}, {"engine_version", kEngineVersion}, {"inputs", inputs}};
}

// a run that ended: its status, warnings, energy balance and bodies; its outputs when complete
void RecordRun(const Simulation& sim, const Scenario& scenario, Json* record) {
  const Summary s = Summarize(sim);
  const OutputUnits u = UnitsOf(scenario.units);
  Json warnings = Json::array();
  for (const RunWarning& w : s.warnings) warnings.push_back(w.code);
  (*record)["status"] = RunStatusName(s.status);
  (*record)["warnings"] = warnings;
  (*record)["energy_balance_error"] = std::isfinite(s.energy_balance_error) ? s.energy_balance_error : 0.0;
  (*record)["support_work"] = s.support_work * u.energy;
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    (*record)["bodies"].push_back(BodyJson(s.bodies[i], sim.engine().state(static_cast<int>(i)).rigid, u));
}

// a sample that has no results: its status and why
void RecordNotRun(const std::string& status, const std::string& why, Json* record) {
  (*record)["status"] = status;
  (*record)["message"] = why;
}

}  // namespace

bool SampleRecord::in_statistics() const {
  if (status != RunStatusName(RunStatus::kComplete)) return false;
  for (const std::string& code : warnings)
    if (WarningVoidsResults(code)) return false;
  return true;
}

SharedAssets::SharedAssets() : device_(std::make_shared<const accel::EmbreeDevice>()) {}

TriMesh MeshCache::Get(const MeshSource& source, const std::string& scenario_file, const std::string& field) {
  // the key: everything BuildBodyMesh reads
  const std::string key = source.file + "|" + std::to_string(source.scale) + "|" + source.axes[0] + source.axes[1] +
                          source.axes[2] + "|" + std::to_string(source.fit_length.value_or(0)) + "|" +
                          std::to_string(source.box) + std::to_string(source.box_size.x()) +
                          std::to_string(source.box_size.y()) + std::to_string(source.box_size.z()) + "|" +
                          std::to_string(source.box_segments[0]) + "," + std::to_string(source.box_segments[1]) + "," +
                          std::to_string(source.box_segments[2]) + "|" + std::to_string(source.cylinder) +
                          std::to_string(source.cylinder_radius) + std::to_string(source.cylinder_height) +
                          std::to_string(source.cylinder_segments) + "|" + std::to_string(source.subdivisions);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = meshes_.find(key); it != meshes_.end()) return *it->second;
  }
  auto mesh = std::make_shared<const TriMesh>(BuildBodyMesh(source, scenario_file, field));
  std::lock_guard<std::mutex> lock(mutex_);
  return *meshes_.emplace(key, mesh).first->second;
}

Crash3Stiffness Crash3ToAB(const Crash3Preset& p, double b0, double b1) {
  // in US units the speeds go to in/s (17.6 per mph) and the mass is W / g in lb s^2 / in
  const double speed = p.us ? 17.6 : 1.0;
  const double mass = p.us ? p.mass / units::kPoundMass / (units::kStandardGravity / units::kInch) : p.mass;
  const double v0 = b0 * speed, slope = b1 * speed;
  return {mass * v0 * slope / p.width, mass * slope * slope / p.width};
}

Scenario SampleScenario(const Spec& spec, const std::vector<double>& values) {
  Json j = Json::parse(spec.scenario_text);
  for (std::size_t k = 0; k < spec.inputs.size(); ++k) {
    const Input& in = spec.inputs[k];
    if (values[k] < in.low || values[k] > in.high)
      throw InputError(spec.file, "inputs[" + std::to_string(k) + "].bounds",
                       "sample value " + std::to_string(values[k]) + " of \"" + in.name + "\" is outside its bounds");
    if (!in.pointer.empty()) j[Json::json_pointer(in.pointer)] = values[k];
  }
  // CRASH3 presets: the surface's A and B from the sampled b0 and b1, together
  for (const Crash3Preset& p : spec.crash3) {
    const Crash3Stiffness k = Crash3ToAB(p, values[p.b0_input], values[p.b1_input]);
    j[Json::json_pointer(p.pointer)] = {{"A", k.a}, {"B", k.b}};
  }
  return ParseScenario(j.dump(), spec.scenario_file);
}

std::vector<std::shared_ptr<const BodyModel>> SampleModels(const Scenario& scenario, MeshCache* meshes) {
  return BuildBodyModels(scenario, [&](const MeshSource& source, const std::string& field) {
    return meshes->Get(source, scenario.file, field);
  });
}

SampleRecord RunSample(const Spec& spec, int index, const std::vector<double>& values, SharedAssets* meshes,
                       double time_limit) {
  const auto start = std::chrono::steady_clock::now();
  Json record = RecordHead(spec, index, values);
  try {
    const Scenario scenario = SampleScenario(spec, values);
    Simulation sim(scenario, SampleModels(scenario, meshes), accel::MakeEmbreeLocatorFactory(meshes->device()));
    // the wall-clock limit, checked between steps
    auto within_limit = [&](double) {
      return !(time_limit > 0.0) ||
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <= time_limit;
    };
    if (sim.Run(within_limit)) {
      RecordRun(sim, scenario, &record);
    } else {
      RecordNotRun(kTimedOut, "ran over the sample time limit of " + Json(time_limit).dump() + " s (wall clock) at " +
                                  Json(sim.time()).dump() + " s simulated", &record);
    }
  } catch (const std::exception& e) {
    // a refused sample is a record with its reason, never the end of the ensemble
    RecordNotRun(kFailedInput, e.what(), &record);
  }
  // status, outputs and observables read from the line, as a resumed sample's are
  return ParseOwnRecord(spec, record.dump());
}

namespace {

// a record field missing or of the wrong type, named by its JSON path
struct RecordFieldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// j[key] as a number (j[key][index] with an index), or RecordFieldError naming `path`
double RecordNumber(const Json& j, const std::string& key, const std::string& path, int index = -1) {
  const Json* v = j.is_object() && j.contains(key) ? &j[key] : nullptr;
  if (v && index >= 0) v = v->is_array() && static_cast<int>(v->size()) > index ? &(*v)[index] : nullptr;
  if (!v || !v->is_number())
    throw RecordFieldError(path + (index >= 0 ? "[" + std::to_string(index) + "]" : "") + ": expected a number");
  return v->get<double>();
}

// the warning codes, the inputs and, for a sample in the statistics, each body's figures
void ReadRecordFields(const Spec& spec, const Json& j, SampleRecord* out) {
  const Json& warnings = j.contains("warnings") ? j["warnings"] : Json::array();
  if (!warnings.is_array()) throw RecordFieldError("warnings: expected an array of warning codes");
  for (const Json& w : warnings) {
    if (!w.is_string()) throw RecordFieldError("warnings: expected an array of warning codes");
    out->warnings.push_back(w.get<std::string>());
  }
  if (j.contains("inputs"))
    for (const Input& in : spec.inputs) out->inputs.push_back(RecordNumber(j["inputs"], in.name, "inputs." + in.name));
  if (!out->in_statistics() || !j.contains("bodies")) return;
  if (!j["bodies"].is_array()) throw RecordFieldError("bodies: expected an array");
  for (std::size_t i = 0; i < j["bodies"].size(); ++i) {
    const Json& b = j["bodies"][i];
    const std::string path = "bodies[" + std::to_string(i) + "].";
    if (!b.is_object() || !b.contains("name") || !b["name"].is_string()) throw RecordFieldError(path + "name: expected a string");
    const std::string name = b["name"].get<std::string>();
    for (const char* q : kOutputQuantities) out->outputs[name + "." + q] = out->observables[name + "." + q] = RecordNumber(b, q, path + q);
    // what evidence may be measured on besides (kMeasuredQuantities): the crush profile and the rest position
    for (int c = 0; c < 6; ++c) out->observables[name + ".c" + std::to_string(c + 1)] = RecordNumber(b, "c", path + "c", c);
    out->observables[name + ".rest_x"] = RecordNumber(b, "final_position", path + "final_position", 0);
    out->observables[name + ".rest_y"] = RecordNumber(b, "final_position", path + "final_position", 1);
    out->observables[name + ".rest_heading"] = RecordNumber(b, "final_heading_deg", path + "final_heading_deg");
  }
}

}  // namespace

bool ParseRecord(const Spec& spec, const std::string& line, SampleRecord* out, std::string* problem) {
  std::string ignored;
  std::string& why = problem ? *problem : ignored;
  const Json j = Json::parse(line, nullptr, false);
  why = "expected a JSON object with \"index\" and \"status\"";
  if (j.is_discarded() || !j.is_object() || !j.contains("index") || !j.contains("status")) return false;
  why = "spec_hash: expected " + HashText(spec.hash);
  if (!j.contains("spec_hash") || j["spec_hash"] != HashText(spec.hash)) return false;
  // a status this engine writes (a record edited by hand, or from another engine, is not one)
  const Json& status = j["status"];
  bool known = status == kFailedInput || status == kTimedOut;
  for (RunStatus s : {RunStatus::kComplete, RunStatus::kEndedInContact, RunStatus::kInterrupted, RunStatus::kFailedNumerics})
    known = known || status == RunStatusName(s);
  why = known ? "index: expected a whole number" : "status: expected a status this engine writes";
  if (!known || !j["index"].is_number_integer()) return false;
  out->index = j["index"].get<int>();
  out->status = j["status"].get<std::string>();
  out->line = line;
  out->outputs.clear();
  out->observables.clear();
  out->inputs.clear();
  out->warnings.clear();
  try {
    ReadRecordFields(spec, j, out);
  } catch (const RecordFieldError& e) {
    why = e.what();
    return false;
  }
  why.clear();
  return true;
}

SampleRecord ParseOwnRecord(const Spec& spec, const std::string& line) {
  SampleRecord r;
  if (!ParseRecord(spec, line, &r))
    throw std::logic_error("ensemble: a record this engine wrote does not read back: " + line.substr(0, 200));
  return r;
}

}  // namespace dymesh::ensemble
