#pragma once
#include "dymesh/core/geometry.h"

/// Coulomb sticking of a node pushed out of a master face (spec §7 in the node's motion).
namespace dymesh {

/// The tangential correction [m] a node takes with its normal push: the node goes back along the
/// surface by its share (`push` / `depth`) of the step's tangential slide over the face
/// (`slide_step`, the relative motion's part along the face), so that it sticks where it touched;
/// never more than `mu` * `push` (Coulomb's cone in displacement form: friction can hold a slip only
/// up to mu times what the normal contact pushes). Zero without friction or without a push: a
/// frictionless face only pushes along its normal.
Vec3 StickingCorrection(const Vec3& slide_step, double push, double depth, double mu);

}  // namespace dymesh
