#pragma once
#include <string>

#include "dymesh/core/simulation.h"

/// history.csv: the recorded time history, one row per step, units in the column headers.
namespace dymesh {

/// Per step and body: position, yaw, velocity, yaw rate, CG acceleration (g), collision force and
/// yaw moment (body frame), cumulative crush and friction work, kinetic energy; scenario units.
std::string HistoryCsv(const Simulation& sim);

}  // namespace dymesh
