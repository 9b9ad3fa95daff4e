#pragma once
#include <memory>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/physical_ranges.h"
#include "dymesh/core/placement.h"
#include "dymesh/core/scenario.h"
#include "dymesh/core/time_step_guide.h"

/// What a run refuses (or warns of) before its first step, once its bodies are built: the one list
/// every Simulation, `dymesh check` and an ensemble spec's trial samples go through.
namespace dymesh {

/// Throws InputError (field bodies[i].initial) for a body with motion "fixed" given a velocity or
/// angular rate.
void RefuseMovingFixedBodies(const Scenario& scenario);

/// The bodies' placement at t = 0 and the time-step guide of a scenario that may start.
struct RunStart {
  std::vector<PairPlacement> placements;
  TimeStepGuide guide;
};

/// Refuses a mesh file's body whose largest built extent is outside kBodySizeRange's possible sizes
/// (field bodies[i].mesh) and warns outside its plausible ones, refuses a fixed body given motion,
/// resolves place_at_contact and refuses a deep initial overlap
/// (PlaceBodies, which moves bodies and may add warnings to `scenario`), and refuses a step beyond
/// the stable limit (RefuseUnstableStep). Throws InputError naming the field.
RunStart CheckRunStart(Scenario* scenario, const std::vector<std::shared_ptr<const BodyModel>>& models);

}  // namespace dymesh
