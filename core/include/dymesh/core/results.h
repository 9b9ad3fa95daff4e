#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dymesh/core/simulation.h"

/// What a run reports: per-body delta-V, PDOF, pulse, crush and energy; overall balances.
namespace dymesh {

/// Results of one body.
struct BodySummary {
  std::string name;
  Vec3 delta_v_earth{0, 0, 0};   ///< [m/s]
  Vec3 delta_v_body{0, 0, 0};    ///< [m/s] in the body axes at first contact
  double delta_v = 0.0;          ///< [m/s] magnitude
  double pdof_deg = 0.0;         ///< principal direction of force, 0 = frontal, +90 = from the right
  int pdof_clock = 12;           ///< clock direction (12 = frontal)
  double peak_accel = 0.0;       ///< [m/s^2] peak resultant CG acceleration from collision loads
  double average_accel = 0.0;    ///< [m/s^2] delta-V over the contact duration
  double max_crush = 0.0;        ///< [m] largest permanent deformation |Delta|
  int max_crush_vertex = -1;
  Vec3 max_crush_location{0, 0, 0};  ///< [m] body frame (undamaged position)
  double max_dynamic_crush = 0.0;    ///< [m] largest DeltaMaxTotal
  double crush_energy = 0.0;     ///< [J]
  double friction_energy = 0.0;  ///< [J]
  Vec3 final_velocity{0, 0, 0};  ///< [m/s] earth frame
  double final_yaw_rate = 0.0;   ///< [rad/s]
};

/// Results of a run.
struct Summary {
  std::vector<BodySummary> bodies;
  Vec3 momentum_before{0, 0, 0}, momentum_after{0, 0, 0};  ///< [kg m/s]
  double kinetic_before = 0.0, kinetic_after = 0.0;         ///< [J]
  double crush_energy = 0.0, friction_energy = 0.0;         ///< [J]
  double energy_balance_error = 0.0;  ///< (KE lost - crush - friction) / KE lost
  double closing_speed = 0.0;         ///< [m/s] along the impulse direction (first pair)
  double separation_speed = 0.0;      ///< [m/s] along the impulse direction (first pair)
  double contact_start = -1.0, contact_end = -1.0;  ///< [s]
  int steps = 0;
  ContactDiagnostics diagnostics;
};

/// Computes the summary from a finished run.
Summary Summarize(const Simulation& sim);

/// Summary as JSON in the scenario's unit system.
nlohmann::json SummaryToJson(const Summary& summary, UnitSystem units);

/// Writes summary.json, history.csv and the deformed and undeformed meshes (OBJ) into `dir`,
/// each through a temporary name renamed into place. Returns the paths written.
std::vector<std::string> WriteOutputs(const Simulation& sim, const Summary& summary, const std::string& dir);

/// Writes `text` to `path` atomically (temporary file, then rename).
void WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace dymesh
