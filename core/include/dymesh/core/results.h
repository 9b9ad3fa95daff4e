#pragma once
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dymesh/core/crush_profile.h"
#include "dymesh/core/run_status.h"
#include "dymesh/core/simulation.h"

/// What a run reports: per-body delta-V, PDOF, pulse, crush and energy; overall balances.
namespace dymesh {

/// Output units of a unit system: the factor from SI and the label of each quantity
/// (US: in, mph, lbf, lbf*in, ft*lbf, lbf*s, lb; SI: m, m/s, N, N*m, J, kg*m/s, kg).
struct OutputUnits {
  double length, speed, force, moment, energy, momentum, mass;
  const char *length_name, *speed_name, *force_name, *moment_name, *energy_name, *momentum_name, *mass_name;
};

/// The output units of `system`.
OutputUnits UnitsOf(UnitSystem system);

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
  double crush_energy = 0.0;     ///< [J] ledger: share of the normal contact work
  double friction_energy = 0.0;  ///< [J] ledger: share of the friction work
  double law_energy = 0.0;       ///< [J] work of the node law on this body's nodes
  Vec3 final_velocity{0, 0, 0};  ///< [m/s] earth frame
  double final_yaw_rate = 0.0;   ///< [rad/s]
  CrushProfile crush_profile;    ///< CRASH3-style C1..C6 on the damaged face
};

/// Results of a run.
struct Summary {
  std::vector<BodySummary> bodies;
  Vec3 momentum_before{0, 0, 0}, momentum_after{0, 0, 0};  ///< [kg m/s]
  double kinetic_before = 0.0, kinetic_after = 0.0;         ///< [J]
  double crush_energy = 0.0, friction_energy = 0.0;         ///< [J] ledger (work of the applied loads)
  double law_energy = 0.0;            ///< [J] node-law work, all bodies
  double energy_discontinuity = 0.0;  ///< [J] ledger crush work - node-law work
  double energy_balance_error = 0.0;  ///< (KE lost - crush - friction) / KE lost
  double closing_speed = 0.0;         ///< [m/s] along the impulse direction (first pair)
  double separation_speed = 0.0;      ///< [m/s] along the impulse direction (first pair)
  double contact_start = -1.0, contact_end = -1.0;  ///< [s]
  int steps = 0;
  double end_time = 0.0;              ///< [s] time reached
  RunStatus status = RunStatus::kComplete;  ///< how the run ended (AssessRun)
  std::vector<RunWarning> warnings;         ///< what a user must read before trusting the result
  ContactDiagnostics diagnostics;
};

/// Computes the summary from a finished run.
Summary Summarize(const Simulation& sim);

/// Summary as JSON in the scenario's unit system.
nlohmann::json SummaryToJson(const Summary& summary, UnitSystem units);

/// The plain names of the files WriteOutputs writes for `scenario`, in writing order: per body
/// NAME_undeformed.obj/.ply and NAME_deformed.obj/.ply, then history.csv, report.html, summary.json.
std::vector<std::string> OutputFileNames(const Scenario& scenario);

/// Which output files were written and which were not (when writing was stopped).
struct WrittenOutputs {
  std::vector<std::string> written, not_written;  ///< paths
};

/// Writes into `dir`: each body's deformed and undeformed mesh (OBJ, and PLY with the permanent
/// crush per vertex), history.csv, report.html and, last, summary.json; each through a temporary
/// name renamed into place. An earlier summary.json is removed first, so its presence always means
/// that the files beside it belong to it. `stop`, when given, is asked before each file: once it
/// returns true the remaining files are skipped (listed in `not_written`).
WrittenOutputs WriteOutputs(const Simulation& sim, const Summary& summary, const std::string& dir,
                            const std::function<bool()>& stop = {});

/// Permanent crush |Delta| of every vertex of body i [m].
std::vector<double> VertexCrush(const Simulation& sim, int body);

}  // namespace dymesh
