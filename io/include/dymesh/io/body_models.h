#pragma once
#include <memory>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/scenario.h"

/// The body models of a scenario, built from its mesh sources (files read through assimp).
namespace dymesh {

/// Loads the meshes of a scenario and builds the body models (shared, immutable): each mesh in body
/// axes about its CG (given, or the bounds centre), inertia given or that of a solid box of the
/// bounds. Refuses (InputError) a deformable body whose mesh encloses no volume.
std::vector<std::shared_ptr<const BodyModel>> BuildBodyModels(const Scenario& scenario);

}  // namespace dymesh
