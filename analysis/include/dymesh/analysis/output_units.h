#pragma once
#include "dymesh/core/scenario.h"

/// The units a run's outputs are written in: those of its scenario.
namespace dymesh {

/// Output units of a unit system: the factor from SI and the label of each quantity
/// (US: in, mph, lbf, lbf*in, ft*lbf, lbf*s, lb; SI: m, m/s, N, N*m, J, kg*m/s, kg).
struct OutputUnits {
  double length, speed, force, moment, energy, momentum, mass;
  const char *length_name, *speed_name, *force_name, *moment_name, *energy_name, *momentum_name, *mass_name;
};

/// The output units of `system`.
OutputUnits UnitsOf(UnitSystem system);

/// Degrees per radian (angles are written in degrees).
inline constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

}  // namespace dymesh
