#include "dymesh/analysis/output_units.h"

#include "dymesh/core/units.h"

namespace dymesh {

OutputUnits UnitsOf(UnitSystem system) {
  if (system == UnitSystem::kSI) return {1, 1, 1, 1, 1, 1, 1, "m", "m/s", "N", "N*m", "J", "kg*m/s", "kg"};
  return {1 / units::kInch, 1 / units::kMph, 1 / units::kPoundForce, 1 / (units::kPoundForce * units::kInch),
          1 / (units::kPoundForce * units::kFoot), 1 / (units::kPoundForce), 1 / units::kPoundMass,
          "in", "mph", "lbf", "lbf*in", "ft*lbf", "lbf*s", "lb"};
}

}  // namespace dymesh
