#include "dymesh/core/run_start.h"

#include <string>

namespace dymesh {

void RefuseMovingFixedBodies(const Scenario& scenario) {
  // a velocity given to a fixed body would be dropped, and its kinetic energy would break the energy
  // account
  for (std::size_t i = 0; i < scenario.bodies.size(); ++i) {
    const BodySpec& b = scenario.bodies[i];
    if (b.motion == MotionModel::kFixed && (b.initial.velocity.norm() > 0.0 || b.initial.omega.norm() > 0.0))
      throw InputError(scenario.file, "bodies[" + std::to_string(i) + "].initial",
                       "a body with motion \"fixed\" does not move: expected no speed, velocity or yaw_rate");
  }
}

RunStart CheckRunStart(Scenario* scenario, const std::vector<std::shared_ptr<const BodyModel>>& models) {
  RefuseMovingFixedBodies(*scenario);
  // bodies placed at contact; an initial overlap refused or warned
  RunStart start;
  start.placements = PlaceBodies(scenario, models);
  // a step the host cannot integrate stably for the stiffest pair
  start.guide = GuideTimeStep(*scenario, models);
  RefuseUnstableStep(*scenario, start.guide);
  return start;
}

}  // namespace dymesh
