#pragma once
#include <string_view>
#include <vector>

#include "dymesh/core/run_status.h"

/// Judges a finished (or stopped) run: its status and the warnings a user must read.
namespace dymesh {

class Simulation;
struct Summary;

/// |energy balance error| beyond which a run is warned: the ledger closes to round-off on every
/// validation case, so 1 % is far above numerical noise and far below a physically wrong run.
inline constexpr double kEnergyBalanceTolerance = 0.01;

/// Net contact work (crush + friction, the ledger) below -1 % of the relative kinetic energy before the
/// collision means the contact created energy: with restitution at most 1 the crush work is never
/// negative, and friction work never is; 1 % is far above the ledger's round-off, like the balance's.
inline constexpr double kEnergyCreatedTolerance = 0.01;

/// The crush work the contact gives back (its steps of negative normal work, summed) beyond which it
/// returned more than restitution allows: the scaled rebound law gives back exactly e^2 of a node's
/// loading work (spec §6), so the contact at most e^2 of what it absorbed, e the largest of the
/// deformable bodies'. The demos and validation runs give back 0.0003-0.0106 with e = 0.1 (the node
/// laws and the applied forces differ by a few % on meshes); half as much again as e^2, 0.5 % of the
/// absorbed work and 0.1 % of the relative kinetic energy before it stand above that. A coarse rally
/// car into a centred round pole gave back 3.9 % with e = 0.1 and left at 1.067 times (1 + e) v
inline constexpr double kReboundMarginOfESquared = 1.5;
inline constexpr double kReboundMarginOfAbsorbed = 0.005;
inline constexpr double kReboundMarginOfEnergy = 0.001;

/// Separation speed along the impulse, as a fraction of the closing speed, below which the bodies
/// passed through each other: contact that stops them leaves them receding (a positive fraction, the
/// restitution), or on eccentric and yawing impacts a CG-based speed a little below zero (the demos:
/// down to -0.11, -0.20 on the oblique one with the polygon-normal search); still closing at half
/// their speed, the contact failed to stop them (coarse car meshes head-on: -0.56 to -0.97 of 60 mph).
inline constexpr double kPassThroughSeparation = -0.5;
/// The same with a body ended inside the other (obstacle_inside, the independent sign that it went
/// in): past the most negative fraction any stopped collision ends at (-0.20, a display-mesh demo,
/// which obstacle_inside does not judge); stopped with a body inside, -0.15 at worst (boxes into
/// posts at 20 mph keeping 17.1 of 20 mph with the post inside; a box spun 48 deg about a post 25 in
/// off its axis ends at -0.08). A 10 in cube through a box's faces and out its side ends at -0.23
/// (-0.25 until the 60th session's margin: README, obstacle_inside)
inline constexpr double kPassThroughWithObstacleInside = -0.20;

/// Whether a run warning says a complete run's delta-V, crush and energies are not physical
/// (passed_through, crush_beyond_length, energy_balance, energy_created, rebound_beyond_restitution):
/// an ensemble counts such a sample as failed
/// and leaves it out of its statistics.
bool WarningVoidsResults(std::string_view code);

/// Relative speed [m/s] below which bodies still in contact at the end count as at rest.
inline constexpr double kRestSpeed = 0.05;

/// Share of their peak contact force under which bodies still touching at the end no longer push each
/// other: acting for ten contact durations after a half-sine pulse (mean 0.64 of the peak) it moves
/// delta-V by under 0.2 %.
inline constexpr double kLightContactShare = 1e-4;

/// Status and warnings of a run from its recorded history and summary (the summary's own status and
/// warnings are not read). The scenario's warnings (implausible values, allowed overlap) come first.
struct RunAssessment {
  RunStatus status = RunStatus::kComplete;
  std::vector<RunWarning> warnings;
};
RunAssessment AssessRun(const Simulation& sim, const Summary& summary);

}  // namespace dymesh
