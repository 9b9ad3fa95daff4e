#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "dymesh/core/contact_step.h"
#include "dymesh/core/scenario.h"
#include "dymesh/core/placement.h"
#include "dymesh/core/run_start.h"
#include "dymesh/core/separation.h"
#include "dymesh/core/time_step_guide.h"

/// A self-contained run: bodies, contact engine, rigid-body host and recorded time history.
namespace dymesh {

/// One recorded instant for one body.
struct BodySample {
  RigidState rigid;
  CgLoads loads;              ///< collision loads over the step that ended here
  Vec3 accel_body{0, 0, 0};   ///< [m/s^2] CG acceleration from collision loads, body frame
  double law_energy = 0.0;      ///< [J] cumulative node-law work on the nodes
  double crush_energy = 0.0;    ///< [J] cumulative ledger crush (normal contact) work
  double friction_energy = 0.0; ///< [J] cumulative ledger friction work
  double support_work = 0.0;    ///< [J] cumulative work of the motion model's loads (Simulation::support_work)
  double contact_area = 0.0;    ///< [m^2] area of the body's own nodes in contact over the step (PairLoads)
  double untaken_share = 0.0;   ///< [m] its crush the other bodies' nodes left to its own (PairLoads, the largest pair's)
};

/// One recorded instant.
struct Sample {
  double time = 0.0;                ///< [s]
  double step = 0.0;                ///< [s] the step that ended here (the scenario's, or the host's dt); 0 at the start
  std::vector<BodySample> bodies;
};

/// One pair's contact over a run (bodies a < b, scenario order).
struct PairContact {
  int a = 0, b = 1;
  Vec3 impulse_on_a{0, 0, 0};  ///< [N s] earth frame, the collision impulse b gave a (normal and friction)
  Vec3 normal_impulse_on_a{0, 0, 0};  ///< [N s] earth frame, its normal part (along the master surfaces' normals)
  Vec3 angular_impulse_on_a{0, 0, 0};  ///< [N m s] earth frame, its moment about a's CG, summed over the steps
  Vec3 angular_impulse_on_b{0, 0, 0};  ///< [N m s] earth frame, the moment of a's on b about b's CG
  Vec3 friction_angular_impulse_on_a{0, 0, 0};  ///< [N m s] earth frame, the friction's part of angular_impulse_on_a
  Vec3 friction_angular_impulse_on_b{0, 0, 0};  ///< [N m s] earth frame, the friction's part of angular_impulse_on_b
  std::size_t first_sample = 0;  ///< history index of the state at which the pair's contact began
};

/// Bodies with no collision load for this long after contact have separated [s]; also the window
/// over which a run at rest in contact must show no growing force.
inline constexpr double kSeparationWindow = 0.02;

/// How far ahead [s] the stop at separation looks for bodies turning or moving back into each other
/// (a car turning off a wall slaps it with its tail). The forecast is free motion: no tyre or ground
/// forces, which over 0.2 s change a car's speed by at most about 1.4 m/s (0.7 g); a meeting later
/// than that is a secondary impact whose path the tyres decide, not this collision's.
inline constexpr double kSlapHorizon = 0.2;

/// Force-provider mode: a host step over which a body moved other than its velocities say.
struct HostMotionMismatch {
  int body = -1;           ///< -1: every step agreed
  double time = 0.0;       ///< [s] the step's start
  double moved = 0.0;      ///< [m] how far the host moved the body's farthest point: its CG's motion plus its turn times that point's distance from the CG
  double accounted = 0.0;  ///< [m] the same as its velocities and angular rates (the step's mean) move it
  double excess = 0.0;     ///< [m] the difference beyond what any integrator allows
};

/// Slack of the host-motion comparison: a host's positions may round off or lag by this much [m], and
/// by this part of the distance its velocities account for (an integrator's own error, e.g. RK4's).
inline constexpr double kHostMotionSlack = 1e-3;
inline constexpr double kHostMotionRelativeSlack = 0.01;

/// The largest roll, pitch or yaw a host may give [rad] (a spinning body's angle winds up; beyond
/// this its sine and cosine lose digits).
inline constexpr double kMaxHostAngle = 1e4;

/// A run of a scenario; owns everything it touches (no global state).
class Simulation {
 public:
  /// A run on body models already built (one per scenario body, in order: BuildBodyModels of
  /// dymesh/io/body_models.h, or the host's own), shared read-only between runs; the scenario's
  /// mesh sources are not read.
  /// Throws InputError for what a run refuses before its first step (CheckRunStart): a fixed body
  /// given motion, a deep initial overlap, a step beyond the stable limit of the stiffest pair.
  Simulation(const Scenario& scenario, std::vector<std::shared_ptr<const BodyModel>> models,
             const LocatorFactory& make_locator);

  /// Runs to the scenario's duration (or separation). `on_step(time)` is called after each step;
  /// returning false stops the run there. Returns true when the run reached its end. Throws
  /// std::logic_error for a finished or a host-driven run.
  bool Run(const std::function<bool(double)>& on_step = {});

  /// Advances one step; returns false once finished. Throws std::logic_error for a finished or a
  /// host-driven run.
  bool Advance();

  /// Force-provider mode (how DyMESH sits inside a host's own vehicle dynamics, as in HVE's SIMON):
  /// `states` are every body's pose and velocities now, as the host integrated them; returns the
  /// collision loads at each CG for the coming step of length `dt` and updates crush. The step
  /// before is recorded with these states (history, energy ledger), so the summary, the report and
  /// the outputs work from a host-driven run; the first call's states are where the run starts
  /// (delta-V, a pair's closing speed). Throws std::invalid_argument for a count that is not
  /// the body count, a non-finite state or dt <= 0, and std::logic_error once finished or after
  /// steps of the run's own integrator (Advance, Run).
  StepResult HostStep(const std::vector<RigidState>& states, double dt);

  /// Ends a host-driven run with the states the host reached after the last step (recorded, its
  /// contact work booked); the run is then finished.
  void FinishHostRun(const std::vector<RigidState>& states);

  const Scenario& scenario() const { return scenario_; }
  const ContactEngine& engine() const { return *engine_; }
  const std::vector<Sample>& history() const { return history_; }
  const ContactDiagnostics& diagnostics() const { return diagnostics_; }
  int steps() const { return steps_; }
  /// True once the run reached its duration or separation, or failed (false while running or when
  /// stopped early).
  bool finished() const { return finished_; }
  /// True when the run stopped because a pose or velocity went non-finite; the state and history
  /// are those of the last finite step.
  bool failed_numerics() const { return failed_numerics_; }
  /// True when the run ended on the separation rule: contact over for the separation window, and no
  /// two bodies able to meet again within kSlapHorizon in free motion (SoonestMeeting; a pair yet to
  /// touch, within the duration).
  bool separated() const { return separated_; }
  /// True when the last step carried a collision load.
  bool in_contact_at_end() const { return steps_ > 0 && last_contact_time_ == time_; }
  /// The longest step taken [s]: the scenario's, or the longest dt a host gave (the scenario's before any).
  double largest_step() const;
  /// Force-provider mode: the host step whose positions its velocities least account for (body -1: all agree).
  const HostMotionMismatch& host_motion_mismatch() const { return host_motion_; }
  /// The contact period and step limits of the scenario's stiffest pair.
  const TimeStepGuide& time_step_guide() const { return guide_; }
  /// Gap (or overlap) of every pair at t = 0, after place_at_contact.
  const std::vector<PairPlacement>& placements() const { return placements_; }
  double time() const { return time_; }
  double first_contact_time() const { return first_contact_time_; }
  /// When bodies stopped at separation may meet again in free motion before the duration [s] (a
  /// secondary impact beyond kSlapHorizon, not simulated); infinity when they cannot.
  double later_meeting_time() const { return later_meeting_; }
  double last_contact_time() const { return last_contact_time_; }
  /// Every pair that carried a collision load, in the order their contact began.
  const std::vector<PairContact>& pair_contacts() const { return pair_contacts_; }
  /// Whether bodies a < b carried a collision load between them at some step.
  bool PairTouched(int a, int b) const {
    return std::any_of(pair_contacts_.begin(), pair_contacts_.end(),
                       [&](const PairContact& c) { return c.a == a && c.b == b; });
  }
  /// [J] work of the motion model's own loads on a body so far (a `gravity` body's weight and ground
  /// support; 0 for the others and in force-provider mode, where the host applies its own), booked as
  /// the contact work is: force times the step's mean velocity
  double support_work(int body) const { return support_work_[body]; }

 private:
  void Record(const StepResult* step, double dt = 0.0);
  void RefuseImpossibleHostState(int body, const RigidState& r) const;
  void CompareHostMotion(const std::vector<RigidState>& states, double dt);
  bool Integrate(const StepResult& step, double dt);
  void AcceptHostStates(const std::vector<RigidState>& states);
  void NoteContact(const StepResult& step, double dt);
  std::vector<PlanMotion> PlanMotions(double horizon) const;
  double SoonestPairMeeting(const std::vector<PlanMotion>& plans, double touched_horizon, double remaining) const;

  Scenario scenario_;
  std::unique_ptr<ContactEngine> engine_;
  std::vector<double> rest_height_;
  std::vector<double> support_work_;     // [J] per body, the motion model's loads' work (support_work)
  std::vector<double> farthest_vertex_;  // [m] per body, its rest vertex farthest from the CG (the host-motion comparison)
  std::vector<Sample> history_;
  ContactDiagnostics diagnostics_;
  int steps_ = 0;
  double time_ = 0.0;
  double first_contact_time_ = -1.0, last_contact_time_ = -1.0;
  double recheck_separation_ = 0.0;  // [s] before this no two bodies can meet in free motion
  double later_meeting_ = INFINITY;  // [s] when stopped bodies may meet again before the duration
  bool finished_ = false, failed_numerics_ = false, separated_ = false;
  std::unique_ptr<StepResult> host_pending_;  // force-provider mode: the step the host is integrating
  double host_step_ = 0.0;                    // force-provider mode: the step length while it is uniform
  bool host_driven_ = false;                  // force-provider mode: HostStep has run (Advance refused)
  double host_pending_step_ = 0.0;            // force-provider mode: the length of the step the host is integrating
  HostMotionMismatch host_motion_;            // force-provider mode: the worst step of positions against velocities
  TimeStepGuide guide_;
  std::vector<PairPlacement> placements_;
  std::vector<PairContact> pair_contacts_;
};

}  // namespace dymesh
