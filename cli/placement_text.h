#pragma once
#include <string>

#include "dymesh/core/placement.h"
#include "dymesh/analysis/summary.h"
#include "format.h"

/// One line per pair of bodies: the gap or overlap at t = 0, in the scenario's units.
namespace dymesh::cli {

inline std::string PlacementText(const Scenario& scenario, const PairPlacement& p) {
  const OutputUnits u = UnitsOf(scenario.units);
  const std::string pair = "\"" + scenario.bodies[p.a].name + "\" / \"" + scenario.bodies[p.b].name + "\"";
  if (!p.meet) return "  placement " + pair + ": they do not meet along their closing direction\n";
  const char* what = p.gap < 0.0 ? "overlap" : "gap";
  return Format("  placement %s: %s %.3f %s along [%.3f, %.3f, %.3f]\n", pair.c_str(), what,
                std::abs(p.gap) * u.length, u.length_name, p.direction.x(), p.direction.y(), p.direction.z());
}

}  // namespace dymesh::cli
