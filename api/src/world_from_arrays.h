#pragma once
#include <memory>
#include <string>
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

/// The world of `world` (its struct_size bytes, a published size: an older caller's shorter struct
/// reads the fields it lacks as their defaults) and `body_count` descriptions `bodies` (struct_size
/// bytes apart). Throws ArgumentError naming the field for a struct_size that is not a published
/// size, a non-finite value, a value outside its physical range (warned, implausible_value, outside
/// the plausible one), a name that is not UTF-8, unusable in file names or used twice, a planar body
/// given a vertical velocity, a mesh of an impossible size; InputError for a deformable body whose
/// mesh encloses no volume.
ArrayWorld WorldFromArrays(const dm_world_desc* world, const dm_body_desc* bodies, int32_t body_count);

/// A body state, refused (ArgumentError naming the component, `at` + ".velocity[0]") unless finite.
RigidState ToRigid(const dm_body_state& s, const std::string& at);

}  // namespace dymesh::api
