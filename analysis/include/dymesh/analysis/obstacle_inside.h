#pragma once

#include "dymesh/core/geometry.h"
#include "dymesh/core/mesh.h"

/// Whether a rigid body went inside a deformable body, past what the contact search can reach.
namespace dymesh {

class Simulation;

/// The rigid body's vertex that came farthest inside a deformable body beyond the body's crush there.
struct ObstacleInside {
  int vertex = -1;     ///< the rigid body's vertex, or -1 when none does (or the body is not closed)
  double depth = 0.0;  ///< [m] how far behind the body's rest front it came, beyond the crush there
};

/// The vertex of rigid body `obstacle` that lies deepest inside deformable body `body` beyond the
/// crush the body took there, at any state recorded from the first contact on (at most 256, evenly
/// spaced, and the last: an obstacle that went in between the nodes may be out the far side by the
/// end), measured along `toward_earth` (unit, earth frame: out of `body` toward where the obstacle
/// came from, against the normal impulse it gave the body; taken in the body's frame as the contact
/// began), against the deepest crush the body ended with.
/// spec §2-§5: a node is pushed out of the master, so where an obstacle came in the body's surface
/// was crushed as deep as it came (with a deformable obstacle, the body's share of the closure); an
/// obstacle deeper than that went in between the nodes (the nodes slid aside, or never met it) and the
/// contact no longer sees it once past TOOFAR_MAXIMUM. A deformable obstacle's vertices are taken as
/// crushed at the end (no farther out than they were when it went in). Judged
/// for a closed `body` mesh only, or one closed but for a few holes (at most one open edge per 200
/// triangles, none shared by more than two), as `rest` (its rest mesh's ComputeStats) says: a display
/// car's panels, window gaps and interior parts have no front and back to be inside. Judged on the obstacle's vertices
/// facing into the body along the line (one on its flank lies against the notch's walls), against
/// the shallowest rest front and the deepest crush (the corners' deepest crush interpolated across
/// each face) in the lateral cells round each vertex (the body's median edge, the vertex's cell and
/// its eight neighbours).
ObstacleInside DeepestObstacleVertexInside(const Simulation& sim, int body, int obstacle, const Vec3& toward_earth,
                                           const MeshStats& rest);

}  // namespace dymesh
