#pragma once
#include <string>
#include <vector>

#include "dymesh/analysis/crush_profile.h"
#include "dymesh/analysis/output_units.h"
#include "dymesh/core/run_status.h"
#include "dymesh/core/simulation.h"

/// What a run reports: per-body delta-V, PDOF, pulse, crush and energy; overall balances.
namespace dymesh {

/// Fraction of a body's peak contact load above which its steps count as loaded (untaken_crush): the
/// crush sharing's state near maximum engagement, not a light touch's at the contact's first or last
/// nodes.
inline constexpr double kLoadedFraction = 0.5;

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
  double peak_contact_area = 0.0;    ///< [m^2] largest area of the body's own nodes in contact in a step
  /// [m] the crush the other bodies' nodes left for this body's own nodes to take (its equal-pressure
  /// share of their penetrations, BodySample::untaken_share), the largest while its load was at least
  /// half its peak (kLoadedFraction). Where its nodes meet the contact, a fraction of its own crush;
  /// where a face's corners lie outside the contact, the crush its mesh could not take
  double untaken_crush = 0.0;
  double crush_energy = 0.0;     ///< [J] ledger: share of the normal contact work
  double friction_energy = 0.0;  ///< [J] ledger: share of the friction work
  double law_energy = 0.0;       ///< [J] work of the node law on this body's nodes
  double support_work = 0.0;     ///< [J] work of its motion model's loads (`gravity`: weight and ground support)
  Vec3 final_velocity{0, 0, 0};  ///< [m/s] earth frame
  double final_yaw_rate = 0.0;   ///< [rad/s]
  CrushProfile crush_profile;    ///< CRASH3-style C1..C6 on the damaged face
};

/// One pair's collision, along the normal impulse the pair exchanged (horizontal when neither body
/// moves vertically: planar or fixed).
struct PairSummary {
  int a = 0, b = 1;                   ///< scenario body indices, a < b
  Vec3 direction{0, 0, 0};            ///< unit earth-frame normal impulse b gave a
  double closing_speed = 0.0;         ///< [m/s] of a toward b along `direction`'s reverse, when the contact began
  double separation_speed = 0.0;      ///< [m/s] of a away from b along `direction`, at the end of the run
  /// [m/s] the same at the impact point: the material points of a and b on the impulse's line of action
  /// (its moments about each CG give the line; any point on it gives the same normal speed)
  double point_closing_speed = 0.0, point_separation_speed = 0.0;
  double contact_start = 0.0;         ///< [s]
  /// the impulse's part across `direction` over its part along it: the collision's effective friction
  /// (the impulse ratio of planar impact mechanics), the pair's mu while it slid throughout, less where
  /// friction stopped the slide or its directions cancelled
  double impulse_ratio = 0.0;
  /// [rad/s] the yaw rate the pair's loads gave a and b (their moments about the vertical through each
  /// CG over its yaw inertia; 0 for a body that does not move), and the friction's part of it
  double yaw_rate_change[2] = {0.0, 0.0};
  double friction_yaw_rate_change[2] = {0.0, 0.0};

  /// separation over closing speed at the CGs, and at the impact point (0 when they did not close)
  double restitution() const { return closing_speed > 0.0 ? separation_speed / closing_speed : 0.0; }
  double point_restitution() const {
    return point_closing_speed > 0.0 ? point_separation_speed / point_closing_speed : 0.0;
  }
};

/// Results of a run.
struct Summary {
  std::vector<BodySummary> bodies;
  Vec3 momentum_before{0, 0, 0}, momentum_after{0, 0, 0};  ///< [kg m/s]
  double kinetic_before = 0.0, kinetic_after = 0.0;         ///< [J]
  double crush_energy = 0.0, friction_energy = 0.0;         ///< [J] ledger (work of the applied loads)
  double law_energy = 0.0;            ///< [J] node-law work, all bodies
  double energy_discontinuity = 0.0;  ///< [J] ledger crush work - node-law work
  double support_work = 0.0;          ///< [J] work of the motion models' loads, all bodies (Simulation::support_work)
  /// (KE lost + support work - crush - friction) / KE lost; -1 (+1) for work with none lost
  double energy_balance_error = 0.0;
  std::vector<PairSummary> pairs;     ///< every pair that carried a load, in the order their contact began
  /// the main collision: the pair with the largest impulse (-1 without contact); the two fields
  /// below repeat its speeds
  int main_pair = -1;
  double closing_speed = 0.0;         ///< [m/s] along the normal impulse direction (main pair)
  double separation_speed = 0.0;      ///< [m/s] along the normal impulse direction (main pair)
  double contact_start = -1.0, contact_end = -1.0;  ///< [s]
  int steps = 0;
  double end_time = 0.0;              ///< [s] time reached
  RunStatus status = RunStatus::kComplete;  ///< how the run ended (AssessRun)
  std::vector<RunWarning> warnings;         ///< what a user must read before trusting the result
  ContactDiagnostics diagnostics;
};

/// Computes the summary from a finished (or stopped) run.
Summary Summarize(const Simulation& sim);

/// The collision impulse on body `body` over the recorded history [N s], body frame (the body-frame
/// loads of each step summed: the PDOF's frame).
Vec3 BodyFrameImpulse(const Simulation& sim, int body);

/// Permanent crush |Delta| of every vertex of body i [m].
std::vector<double> VertexCrush(const Simulation& sim, int body);

}  // namespace dymesh
