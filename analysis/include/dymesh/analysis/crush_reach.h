#pragma once

#include <vector>

#include "dymesh/core/mesh.h"

/// Whether a body's crush lies within the reach of the bodies that crushed it.
namespace dymesh {

class Simulation;

/// A node crushed farther along its crush than any other body's material ever came.
struct NodeBeyondReach {
  int vertex = -1;     ///< the node, or -1 when every node tested lies within reach
  double crush = 0.0;  ///< [m] its crush |Delta|
  double reach = 0.0;  ///< [m] how far along that crush, from its rest place, the other bodies came
};

/// The node of body `body` that lies farthest beyond the other bodies' reach, of its deepest nodes
/// (spec §2-§5: a node moves only where another body's surface pushes it, so it lies, along its
/// crush, no deeper than some point of that body came). The other bodies are taken as their rest
/// bounding boxes at every state recorded while the bodies touched, in this body's frame: a crushed
/// body reaches less far, so the reach is never under-estimated. `rest`: every body's rest-mesh stats
/// (ComputeStats), by body index. vertex is -1 when none lies beyond it.
NodeBeyondReach DeepestNodeBeyondReach(const Simulation& sim, int body, const std::vector<MeshStats>& rest);

}  // namespace dymesh
