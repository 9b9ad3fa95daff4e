#pragma once
#include <memory>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/scenario.h"

/// How long a contact lasts for the scenario's stiffness and masses, and the time step that follows.
namespace dymesh {

/// Fewest steps per contact period before a run is warned that its step is coarse: the half period
/// of the stiffest pair is resolved to ~1 % in delta-V at 50 steps (README validation table).
inline constexpr int kMinStepsPerContact = 50;

/// Stiffest pair's contact period and the step limits it sets.
struct TimeStepGuide {
  bool bounded = false;           ///< false when no pair has a linear stiffness (A-only laws, all rigid)
  int body_a = -1, body_b = -1;   ///< the stiffest pair (shortest period)
  double stiffness = 0.0;         ///< [N/m] its contact stiffness (series of both sides)
  double reduced_mass = 0.0;      ///< [kg] its reduced mass (a fixed body counts as infinite)
  double contact_period = 0.0;    ///< [s] pi / omega: loading and unloading of a linear contact
  double recommended_step = 0.0;  ///< [s] contact_period / kMinStepsPerContact
  double stable_limit = 0.0;      ///< [s] 2 / omega: the semi-implicit host diverges beyond it
  /// The fastest pair (largest initial relative speed of the CGs; -1 when none moves) and the longest
  /// step [s] over which it closes no farther than the contact search reaches (TOOFAR_MAXIMUM): past
  /// it, a node can cross a surface in one step unseen and the contact be missed.
  int fastest_a = -1, fastest_b = -1;
  double relative_speed = 0.0;    ///< [m/s] of the fastest pair
  double reach_step = 0.0;        ///< [s] contact.toofar_maximum / relative_speed
  /// The `gravity` model's ground support, a critically damped spring of natural frequency
  /// omega = sqrt(g / kGroundStaticDeflection), the same for every such body: the first body with
  /// motion "gravity" (-1 when none has it) and the step beyond which the semi-implicit host diverges
  /// on it, 2 (sqrt 2 - 1) / omega. No finer step is asked for: the support only holds the body up (its
  /// transient moves no planar result: a car at 5 mph into the barrier, delta-V within 0.06 % from
  /// 0.25 ms to 8 ms, 2026-11-28).
  int ground_body = -1;
  double ground_omega = 0.0;         ///< [rad/s]
  double ground_stable_limit = 0.0;  ///< [s]
};

/// Estimates, for every pair of bodies that can meet, a linear contact stiffness (the stiffest of the
/// loading slope B, the unloading slope Kv and, with quadratic or cubic terms C3, D3, the loading law's
/// slope up to the crush at which that surface alone takes the pair's relative kinetic energy, over a
/// body's surfaces, times the smaller projected bounds area across the closing direction, the two
/// bodies in series) and the pair's reduced mass, and returns the shortest period. An upper bound on
/// the stiffness: real contact areas are smaller.
/// Also the step the search reach allows the fastest pair (pairs of two rigid bodies left out), and
/// the limits of a `gravity` body's ground support.
TimeStepGuide GuideTimeStep(const Scenario& scenario, const std::vector<std::shared_ptr<const BodyModel>>& models);

/// Throws InputError at time.step when the scenario's step is beyond the guide's stable limit,
/// naming the pair, the limit and the recommended step, or beyond the ground support's, naming the
/// gravity body.
void RefuseUnstableStep(const Scenario& scenario, const TimeStepGuide& guide);

}  // namespace dymesh
