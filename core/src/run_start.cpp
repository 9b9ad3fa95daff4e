#include "dymesh/core/run_start.h"

#include <cstdio>
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

namespace {

// how a mesh file was sized, for messages
std::string SizedBy(const Scenario& scenario, const MeshSource& mesh) {
  char scale[48];
  std::snprintf(scale, sizeof scale, "%.4g", mesh.scale);
  return mesh.fit_length ? "fit_length " + LengthText(scenario.units, *mesh.fit_length)
                         : std::string("mesh.unit times mesh.scale: ") + scale + " m per file unit";
}

// a mesh file's body is as large as a generated box may be: refused outside the possible sizes,
// warned outside those met in vehicle collisions (a unit or scale off by 1000 builds either)
void CheckMeshFileSizes(Scenario* scenario, const std::vector<std::shared_ptr<const BodyModel>>& models) {
  const PhysicalRange& r = kBodySizeRange;
  auto range = [&](double lo, double hi) { return LengthText(scenario->units, lo) + " .. " + LengthText(scenario->units, hi); };
  for (std::size_t i = 0; i < models.size(); ++i) {
    const MeshSource& mesh = scenario->bodies[i].mesh;
    if (mesh.file.empty()) continue;  // generated: its sizes were checked as given
    const MeshStats stats = ComputeStats(models[i]->mesh);
    const double extent = (stats.max - stats.min).maxCoeff();
    const std::string field = "bodies[" + std::to_string(i) + "].mesh";
    const std::string what = "the mesh file " + mesh.file + " (" + SizedBy(*scenario, mesh) + ") builds a body " +
                             LengthText(scenario->units, extent) + " across at its largest";
    if (extent < r.hard_lo || extent > r.hard_hi)
      throw InputError(scenario->file, field, what + "; expected a physically possible body size in " +
                                                  range(r.hard_lo, r.hard_hi) + ": check mesh.unit and mesh.scale");
    if (extent < r.lo || extent > r.hi)
      scenario->warnings.push_back({"implausible_value", field, what + ", outside the range met in vehicle collisions, " +
                                                                    range(r.lo, r.hi) + ": check mesh.unit and mesh.scale"});
  }
}

}  // namespace

RunStart CheckRunStart(Scenario* scenario, const std::vector<std::shared_ptr<const BodyModel>>& models) {
  CheckMeshFileSizes(scenario, models);
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
