#pragma once
#include <Eigen/Core>

#include "dymesh/core/units.h"

/// Contact options: every constant of the spec as a named option with its default (SI inside).
namespace dymesh {

/// Search-ray direction method of Location (spec §2).
enum class SearchDirection { kLocalAverageNormal, kVelocity, kPolyNormal, kSpecified };

/// How many accepted master triangles Location examines per slave node (spec §2), in the order of
/// master triangle index as DyMESH's surface lists are: the first, the best of the first two, or
/// the best of all ("best" = smallest |depth|, ties to the lower triangle index).
enum class StopRule { kAfterOne, kBestOfTwo, kBestOfAll };

/// Shape of the rebound branch of NodeForce (spec §6).
enum class ReboundLaw {
  kScaled,   ///< F = e * g(delta_r / e): returns exactly e^2 of the loading energy (default)
  kLiteral,  ///< F = cubic(delta_r) as the spec's text reads; equal to kScaled for a pure linear B law
};

/// Which normal of a deformable master's face a deformable slave node is pushed and loaded along.
enum class ContactNormal {
  kCrushed,     ///< the face as crushed (the default until the 60th session)
  kConforming,  ///< the crushed face's or its rest face's, whichever meets the node's own faces more squarely (default)
};

/// Every option of the contact step, SI units.
struct ContactOptions {
  int passes_per_step = 2;                                   ///< master/slave swaps per step (spec §1)
  SearchDirection search_direction = SearchDirection::kVelocity;  ///< velocity: pushback follows the relative motion (energy-consistent)
  StopRule stop_rule = StopRule::kBestOfAll;
  int version = 3;                                           ///< DyMESH version: 4 enables PushbackReduction
  double null_band = 0.5 * units::kInch;                     ///< [m] NULL_TEST, delta_0 of Eq. 1 (spec §3)
  double pushback_reduction = 0.5;                           ///< [-] PushbackReduction fraction withheld (v4)
  double pushback_reduce_limit = 0.1 * units::kInch;         ///< [m] PUSHBACK_REDUCE_LIMIT: most penetration withheld
  double toofar_margin = 1.0 * units::kInch;                 ///< [m] TOOFAR_MARGIN: restore per pass <= |v_rel| dt + margin
  double toofar_maximum = 6.0 * units::kInch;                ///< [m] TOOFAR_MAXIMUM: deepest penetration searched
  double search_backoff = 2.0 * units::kInch;                ///< [m] ray origin backed off the node (finds gaps for unloading)
  double contact_tolerance = 1e-5 * units::kInch;            ///< [m] a node this close outside the surface still touches it
  double unload_begin = 0.05 * units::kInch;                 ///< [m] UNLOAD_BEGIN: delta_max needed before a node can unload
  double unload_pot = 0.001 * units::kInch;                  ///< [m] UNLOAD_POT: drop below delta_max that counts as unloading
  double unload_stop = 0.001 * units::kInch;                 ///< [m] UNLOAD_STOP: within this of (1-e) delta_max unloading is finished
  double max_grow_unload = 0.25 * units::kInch;              ///< [m] MAX_GROW_UNLOAD: reload growth per step beyond the surfaces' approach
  double friction_null_band = 1.0 * units::kInch;            ///< [m/s] FRICTION_NULL_BAND (spec §7)
  ReboundLaw rebound_law = ReboundLaw::kScaled;
  bool turn_within_step = true;  ///< spec §6: loading force ends where the approach does (README)
  ContactNormal contact_normal = ContactNormal::kConforming;  ///< between deformable bodies (README)
  Eigen::Vector3d specified_direction{-1.0, 0.0, 0.0};       ///< pushback direction in the slave body frame (kSpecified)
  int calc_nabor_interval = 5;                               ///< CALC_NABOR_INTERVAL (neighbour-box locator)
  double global_search_box = 0.0;                            ///< [m] GLOBAL_SEARCH_BOX half-size; 0 = SetBoxSize (automatic)
};

}  // namespace dymesh
