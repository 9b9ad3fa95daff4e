#pragma once
#include <memory>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/scenario.h"
#include "dymesh/dymesh.h"

/// dm_world_create's descriptions turned into a scenario and body models, held to the checks a
/// scenario file gets (io's parser, README "Physical ranges"), in SI.
namespace dymesh::api {

struct ArrayWorld {
  Scenario scenario;
  std::vector<std::shared_ptr<const BodyModel>> models;
};

/// The world of `world` (its struct_size bytes: an older caller's shorter struct reads the fields it
/// lacks as their defaults) and `body_count` descriptions `bodies` (struct_size bytes apart). Throws ArgumentError
/// naming the field for a value outside its physical range (warned, implausible_value, outside the
/// plausible one), a name unusable in file names or used twice, a planar body given a vertical
/// velocity, a mesh of an impossible size; InputError for a deformable body whose mesh encloses no
/// volume.
ArrayWorld WorldFromArrays(const dm_world_desc* world, const dm_body_desc* bodies, int32_t body_count);

/// A host's body state, refused (ArgumentError) unless finite.
RigidState ToRigid(const dm_body_state& s, int body);

}  // namespace dymesh::api
