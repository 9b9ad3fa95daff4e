// The contact area A_v of spec §3 (ContactNodeArea) against closed forms: a third of each face wholly
// in contact, projected on the contact plane, and only the part of a face that reaches the master.
#include <gtest/gtest.h>

#include <cmath>

#include "dymesh/core/body.h"

namespace dymesh {
namespace {

// one right triangle of legs `leg` [m] in the z = 0 plane, outward normal +z; vertex 0 at the origin
BodyState OneTriangle(double leg, BodyModel* model) {
  TriMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(leg, 0, 0), Vec3(0, leg, 0)};
  mesh.triangles = {{0, 1, 2}};
  *model = MakeBodyModel("plate", mesh, {}, 1.0, Mat3::Identity(), 0.0, 0.0, false);
  return MakeBodyState(*model, RigidState{});
}

TEST(ContactNodeArea, FaceWhollyInContactGivesAThirdProjected) {
  // a master whose outward normal is -z turned by 30 degrees about y, vertex 0 lying 1 mm inside:
  // every corner of the face lies inside the tangent plane, so A_v = A cos(30 deg) / 3
  BodyModel model;
  const BodyState s = OneTriangle(1.0, &model);
  const double angle = 30.0 * 3.14159265358979323846 / 180.0;
  const Vec3 normal(-std::sin(angle), 0.0, -std::cos(angle));  // leans toward -x: the far corners sink deeper
  EXPECT_NEAR(ContactNodeArea(model, s, 0, normal, 0.001), 0.5 * std::cos(angle) / 3.0, 1e-12);
  // a master on the face's back side (outward normal +z) does not press on it
  EXPECT_EQ(ContactNodeArea(model, s, 0, Vec3(0, 0, 1), 0.001), 0.0);
}

TEST(ContactNodeArea, OnlyThePartOfAFaceThatReachesTheMasterCounts) {
  // a 10 m face whose corner 1 rises out of the master: the tangent plane's outward normal
  // n = (sin a, 0, -cos a) with sin a = 0.1, vertex 0 lying d = 0.1 m inside. The depth below the plane
  // is psi = d - x sin a, zero at x = 1 m: in the face's own coordinates (x / 10, y / 10) the part in
  // contact is x' <= 0.1, and vertex 0's barycentric weight 1 - x' - y' integrates over it to
  // int_0^0.1 (1 - x')^2 / 2 dx' = (1 - 0.9^3) / 6, a fraction (1 - 0.9^3) / 3 of the face
  BodyModel model;
  const BodyState s = OneTriangle(10.0, &model);
  const double sin_a = 0.1, cos_a = std::sqrt(1.0 - sin_a * sin_a);
  const double expected = 50.0 * cos_a * (1.0 - 0.729) / 3.0;
  EXPECT_NEAR(ContactNodeArea(model, s, 0, Vec3(sin_a, 0.0, -cos_a), 0.1), expected, 1e-9);
  // the unclipped third would be 3.7 times as large
  EXPECT_LT(expected, 0.3 * 50.0 * cos_a / 3.0);
}

TEST(ContactNodeArea, CrushCountsFromTheRestShape) {
  // vertex 0 pushed 0.5 m back along the master's normal by earlier crush, now touching (depth 0):
  // its rest position still lies 0.5 m inside, so the face is counted as the rest shape overlaps
  BodyModel model;
  BodyState s = OneTriangle(10.0, &model);
  const Vec3 normal(0.1, 0.0, -std::sqrt(0.99));
  s.vertices[0] += 0.5 * normal;
  UpdateTriangles(model, {0}, &s);
  // psi = 0.5 - x sin a on the rest face (corner 2 stays inside): zero at x' = 0.5
  const double facing = -s.tri_normal[0].dot(normal);
  const double expected = s.tri_area[0] * facing * (1.0 - 0.125) / 3.0;
  EXPECT_NEAR(ContactNodeArea(model, s, 0, normal, 0.0), expected, 1e-9);
}

}  // namespace
}  // namespace dymesh
