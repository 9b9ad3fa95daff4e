#pragma once
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/run_status.h"
#include "dymesh/core/simulation.h"
#include "dymesh/ensemble/spec.h"

/// One sample: its scenario (the base with the sample's values written at the inputs' paths), its
/// run and its record (one line of samples.jsonl).
namespace dymesh::ensemble {

/// Body meshes built once per mesh source and shared read-only (thread-safe).
class MeshCache {
 public:
  TriMesh Get(const MeshSource& source, const std::string& scenario_file, const std::string& field);

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const TriMesh>> meshes_;
};

/// What every sample shares read-only (thread-safe): the meshes, and one Embree device (each
/// sample still builds its own scenes on it).
class SharedAssets : public MeshCache {
 public:
  SharedAssets();
  const std::shared_ptr<const accel::EmbreeDevice>& device() const { return device_; }

 private:
  std::shared_ptr<const accel::EmbreeDevice> device_;
};

/// A sample's result: the record line and the outputs the statistics use (empty unless in them).
struct SampleRecord {
  int index = -1;
  std::string line;                        ///< JSON, no newline
  std::string status;                      ///< run status, or "failed_input" when refused
  std::map<std::string, double> outputs{}; ///< "BODY.QUANTITY" -> value (scenario units)
  std::vector<double> inputs{};            ///< the sample's input values, in spec order
  std::map<std::string, double> observables{};  ///< outputs plus BODY.c1..c6, rest_x, rest_y, rest_heading
  std::vector<std::string> warnings{};     ///< the run's warning codes

  /// The run parted (status complete) and no warning voids its results (WarningVoidsResults): its
  /// outputs enter the statistics; any other sample is counted as failed.
  bool in_statistics() const;

  /// Its warning codes, each once (a code two bodies carry counts once for the sample).
  std::set<std::string> warning_codes() const { return {warnings.begin(), warnings.end()}; }
};

/// CRASH3 2-D coefficients of a preset from b0 and b1 (the preset's units): A = m b0 b1 / L,
/// B = m b1^2 / L; US: A [lb/in], B [lb/in^2] from b0 [mph], b1 [mph/in], weight [lb], L [in].
struct Crash3Stiffness {
  double a, b;
};
Crash3Stiffness Crash3ToAB(const Crash3Preset& preset, double b0, double b1);

/// The sample's scenario: the base with `values` at the inputs' paths (InputError when refused).
Scenario SampleScenario(const Spec& spec, const std::vector<double>& values);

/// The sample's body models, from the meshes of `meshes` (InputError when a mesh is refused).
std::vector<std::shared_ptr<const BodyModel>> SampleModels(const Scenario& scenario, MeshCache* meshes);

/// Status of a sample that ran over its wall-clock time limit: the one record that depends on the
/// machine, so a resumed ensemble runs it again.
inline constexpr const char* kTimedOut = "timed_out";
/// Status of a sample whose scenario was refused.
inline constexpr const char* kFailedInput = "failed_input";

/// Per-body outputs of a complete sample (statistics, thresholds): "BODY.QUANTITY".
inline constexpr std::array<const char*, 7> kOutputQuantities = {
    "delta_v", "pdof_deg", "peak_acceleration_g", "max_crush", "crush_energy", "final_yaw_rate_deg_s", "peak_contact_area"};
/// What evidence may be measured on besides the outputs: the crush profile and the rest position.
inline constexpr std::array<const char*, 9> kMeasuredQuantities = {"c1", "c2", "c3", "c4", "c5", "c6",
                                                                   "rest_x", "rest_y", "rest_heading"};

/// Runs sample `index` with `values` and makes its record; never throws for a bad sample (the
/// record says why). `engine_version` is written into the record. With `time_limit` > 0 [s, wall
/// clock], a sample still running after it stops between steps and is recorded as kTimedOut.
SampleRecord RunSample(const Spec& spec, int index, const std::vector<double>& values, SharedAssets* meshes,
                       double time_limit = 0.0);

/// Reads a record line back (status, outputs); false when it is not a valid record of `spec`, with
/// `problem` (when given) naming the field and what was expected.
bool ParseRecord(const Spec& spec, const std::string& line, SampleRecord* out, std::string* problem = nullptr);

/// Reads back a record line this engine just wrote for `spec` (here or on a worker rank); one that
/// does not parse is a bug, not bad input: std::logic_error naming the line's start.
SampleRecord ParseOwnRecord(const Spec& spec, const std::string& line);

/// The engine version written into records.
inline constexpr const char* kEngineVersion = "0.1.0";

}  // namespace dymesh::ensemble
