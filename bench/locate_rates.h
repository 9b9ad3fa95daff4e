#pragma once
// The same Location segments through every search: the engine's Embree locator, raw Embree on the
// same scene, the original neighbour-box search, brute force, and CGAL's AABB tree.
#include <memory>

#include "contact_setup.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/accel/neighbor_box_locator.h"

namespace dymesh::bench {

/// The engine's Locate for each segment: Embree candidates, then the depth in double and the inside
/// test where the locator did not prove it (`normals`: the master's unit triangle normals).
/// Returns how many segments located a triangle.
size_t LocateWithEmbreeLocator(const accel::EmbreeLocator& locator, const TriMesh& master,
                               const std::vector<Vec3>& normals, const RaySet& rays);

/// Raw closest-hit rtcIntersect1 on `scene` (an RTCScene) for segments [begin, end); returns the hits.
size_t RawClosestHits(void* scene, const RaySet& rays, size_t begin, size_t end);

/// Raw rtcIntersect1 (closest hit, no filter, no exact test) on the locator's own scene: the limit.
size_t LocateWithRawEmbree(const accel::EmbreeLocator& locator, const RaySet& rays);

/// The neighbour-box search: lists prepared for the segments' nodes, then the exact test of each list.
size_t LocateWithNeighborBox(accel::NeighborBoxLocator* locator, int step, const RaySet& rays, double backoff);

/// Every triangle tested exactly.
size_t LocateWithBruteForce(const TriMesh& master, const RaySet& rays);

}  // namespace dymesh::bench
