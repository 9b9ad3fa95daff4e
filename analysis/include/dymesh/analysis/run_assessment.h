#pragma once
#include <vector>

#include "dymesh/core/run_status.h"

/// Judges a finished (or stopped) run: its status and the warnings a user must read.
namespace dymesh {

class Simulation;
struct Summary;

/// |energy balance error| beyond which a run is warned: the ledger closes to round-off on every
/// validation case, so 1 % is far above numerical noise and far below a physically wrong run.
inline constexpr double kEnergyBalanceTolerance = 0.01;

/// Relative speed [m/s] below which bodies still in contact at the end count as at rest.
inline constexpr double kRestSpeed = 0.05;

/// Status and warnings of a run from its recorded history and summary (the summary's own status and
/// warnings are not read). The scenario's warnings (implausible values, allowed overlap) come first.
struct RunAssessment {
  RunStatus status = RunStatus::kComplete;
  std::vector<RunWarning> warnings;
};
RunAssessment AssessRun(const Simulation& sim, const Summary& summary);

}  // namespace dymesh
