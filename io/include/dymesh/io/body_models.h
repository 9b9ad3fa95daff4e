#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/scenario.h"

/// The body models of a scenario, built from its mesh sources (files read through assimp).
namespace dymesh {

/// Loads the meshes of a scenario and builds the body models (shared, immutable): each mesh in body
/// axes about its CG (given, or the bounds centre), inertia given or that of a solid box of the
/// bounds. Refuses (InputError) a deformable body whose mesh encloses no volume.
std::vector<std::shared_ptr<const BodyModel>> BuildBodyModels(const Scenario& scenario);

/// Refuses (InputError naming `file` and `field`) a deformable body's mesh that encloses no volume (a
/// sheet, a single triangle, however turned). A mesh of an impossible size (kBodySizeRange) passes:
/// its caller refuses it for that, by name.
void RefuseFlatMesh(const TriMesh& mesh, const std::string& file, const std::string& field);

/// The body-frame mesh of a mesh source (as BuildBodyMesh makes it); `field` names it in messages.
using MeshProvider = std::function<TriMesh(const MeshSource& source, const std::string& field)>;

/// The same from meshes the caller provides (e.g. cached between the runs of an ensemble).
std::vector<std::shared_ptr<const BodyModel>> BuildBodyModels(const Scenario& scenario, const MeshProvider& mesh_for);

}  // namespace dymesh
