// The vertex normals against closed forms on a box: the local average normal (the search direction of
// USE_LOCAL_AVERAGE_NORMAL) of a node on an edge or corner does not depend on how the faces are cut.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/geometry.h"

namespace dymesh {
namespace {

// a 180 x 66 x 30 in box (in metres) with `length_segments` along x, 22 across, 10 up
BodyModel Box(int length_segments) {
  return MakeBodyModel("box", MakeBox(4.572, 1.6764, 0.762, length_segments, 22, 10), {}, 1.0, Mat3::Identity(),
                       0.0, 0.0, false);
}

// the vertex of `model` at `p` [m]
int VertexAt(const BodyModel& model, const Vec3& p) {
  for (size_t v = 0; v < model.mesh.vertices.size(); ++v)
    if ((model.mesh.vertices[v] - p).norm() < 1e-9) return static_cast<int>(v);
  ADD_FAILURE() << "no vertex at " << p.transpose();
  return 0;
}

// pushes every vertex from x = `from` [m] forward back by `depth` [m] and unevenly (a wavy crush,
// tilted up); returns them
std::vector<int> PushBack(const BodyModel& model, double from, double depth, BodyState* s) {
  std::vector<int> moved;
  for (size_t v = 0; v < model.mesh.vertices.size(); ++v) {
    const Vec3& p = model.mesh.vertices[v];
    if (p.x() < from) continue;
    s->vertices[v] = p - Vec3(depth + 0.2 * std::sin(7.0 * p.y()) * std::cos(5.0 * p.z()), 0.05 * p.z(), 0.0);
    moved.push_back(static_cast<int>(v));
  }
  return moved;
}

TEST(LocalAverageNormal, EdgesAndCornersLookHalfwayBetweenTheirFacesHoweverTheFacesAreCut) {
  // each face counts by its angle at the node: a node on the front-right edge has 180 degrees of the
  // front and 180 of the side, so its normal is their bisector (1, 1, 0)/sqrt 2; a corner has 90
  // degrees of each of three faces, (1, 1, 1)/sqrt 3. Tolerance: round-off of the angle sums.
  const Vec3 edge(2.286, 0.8382, 0.0), corner(2.286, 0.8382, 0.381);
  for (int segments : {1, 60}) {
    const BodyModel model = Box(segments);
    const BodyState rest = MakeBodyState(model, RigidState{});
    EXPECT_LT((LocalAverageNormal(model, rest, VertexAt(model, edge)) - Vec3(1, 1, 0).normalized()).norm(), 1e-12)
        << segments << " along";
    EXPECT_LT((LocalAverageNormal(model, rest, VertexAt(model, corner)) - Vec3(1, 1, 1).normalized()).norm(), 1e-12)
        << segments << " along";
  }
  // by area, the strip's 180 in long side triangles (270 in^2 against the front's 4.5 in^2) turn the
  // edge node nearly sideways: the search would run along the face in front of it
  const BodyModel strip = Box(1);
  const Vec3 by_area = AreaWeightedNormal(strip, MakeBodyState(strip, RigidState{}), VertexAt(strip, edge));
  EXPECT_GT(by_area.y(), 0.99);
}

TEST(LocalAverageNormal, AFaceCrushedFlatDropsOut) {
  // each face's weight is its rest angle times the share of its rest area it keeps: squash the front
  // face's cells at the edge node to no area and only the side is left
  const BodyModel model = Box(60);
  BodyState s = MakeBodyState(model, RigidState{});
  const int v = VertexAt(model, Vec3(2.286, 0.8382, 0.0));
  const auto& adj = model.vertex_triangles;
  for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k)
    if (s.tri_normal[adj.ids[k]].x() > 0.5) s.tri_area[adj.ids[k]] = 0.0;
  EXPECT_LT((LocalAverageNormal(model, s, v) - Vec3(0, 1, 0)).norm(), 1e-12);
}

TEST(AreaWeightedNormal, TheKeptVertexNormalsFollowEveryCrush) {
  // the state keeps each vertex's normal (Location reads it for every node it searches): after the
  // front's nodes are pushed in unevenly, every vertex's kept normal is the one summed afresh from its
  // faces, bit for bit, the moved nodes' neighbours included (they share the turned faces)
  const BodyModel model = Box(60);
  BodyState s = MakeBodyState(model, RigidState{});
  const std::vector<int> moved = PushBack(model, 2.2, 0.3, &s);
  ASSERT_GT(moved.size(), 100u);
  UpdateTriangles(model, moved, &s);
  int turned = 0;
  for (size_t v = 0; v < model.mesh.vertices.size(); ++v) {
    const Vec3 fresh = AreaWeightedNormal(model, s, static_cast<int>(v));
    EXPECT_EQ(s.vertex_normal[v], fresh) << "vertex " << v;
    turned += fresh.x() < 0.999 && model.mesh.vertices[v].x() > 2.28 ? 1 : 0;
  }
  EXPECT_GT(turned, 100);  // the crush did turn the front's normals
}

TEST(UpdateTriangles, InChunksEveryFaceAndNormalIsTheOneComputedAfresh) {
  // the commit recomputes each face round the moved vertices once, at its lowest moved corner, and
  // each corner's normal, in parallel chunks of 256: with the box's front half moved (about 2,000
  // vertices, listed in a shuffled order) every face's area and normal and every vertex normal equal
  // the ones computed afresh from the moved vertices, bit for bit
  const BodyModel model = Box(60);
  BodyState s = MakeBodyState(model, RigidState{});
  std::vector<int> moved = PushBack(model, 0.0, 0.1, &s);
  ASSERT_GT(moved.size(), 4 * 256u);
  std::shuffle(moved.begin(), moved.end(), std::mt19937(7));
  UpdateTriangles(model, moved, &s);
  for (size_t t = 0; t < model.mesh.triangles.size(); ++t) {
    const auto& tri = model.mesh.triangles[t];
    const Vec3 cross = TriangleCross(s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]);
    EXPECT_EQ(s.tri_area[t], 0.5 * cross.norm()) << "face " << t;
    EXPECT_EQ(s.tri_normal[t], Vec3(cross / cross.norm())) << "face " << t;
  }
  for (size_t v = 0; v < model.mesh.vertices.size(); ++v) {
    EXPECT_EQ(s.vertex_normal[v], AreaWeightedNormal(model, s, static_cast<int>(v))) << "vertex " << v;
  }
  EXPECT_TRUE(std::all_of(s.update_mark.begin(), s.update_mark.end(), [](auto m) { return m == 0; }));
}

TEST(UpdateTriangles, RefusesAVertexListedTwiceAndKeepsItsMarksClear) {
  // a vertex listed twice would have its faces written by two chunks at once
  const BodyModel model = Box(1);
  BodyState s = MakeBodyState(model, RigidState{});
  EXPECT_THROW(UpdateTriangles(model, {3, 5, 3}, &s), std::invalid_argument);
  EXPECT_TRUE(std::all_of(s.update_mark.begin(), s.update_mark.end(), [](auto m) { return m == 0; }));
  EXPECT_NO_THROW(UpdateTriangles(model, {3, 5}, &s));
}

}  // namespace
}  // namespace dymesh
