// Six-point crush: damaged face, damage width, stations and C1..C6 on a box with prescribed crush.
#include "dymesh/analysis/crush_profile.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dymesh {
namespace {

// a 4 x 2 x 1 m box about the origin: columns across the front at y = -1, -0.6, ..., 1;
// along the sides at x = -2, -1.2, ..., 2
struct CrushBox {
  BodyModel model = MakeBodyModel("box", MakeBox(4.0, 2.0, 1.0, 5, 5, 1), {}, 1000.0, Mat3::Identity(), 0.0, 0.0, false);
  BodyState state = MakeBodyState(model, RigidState{});
};

TEST(CrushProfile, UndamagedBodyHasNoFace) {
  CrushBox box;
  const CrushProfile p = MeasureCrushProfile(box.model, box.state);
  EXPECT_EQ(p.face, CrushFace::kNone);
  EXPECT_EQ(p.width, 0.0);
  // less than 1 mm is no damage either
  for (std::size_t v = 0; v < box.state.delta.size(); ++v)
    if (box.model.mesh.vertices[v].x() == 2.0) box.state.delta[v] = Vec3(-0.0005, 0, 0);
  EXPECT_EQ(MeasureCrushProfile(box.model, box.state).face, CrushFace::kNone);
}

TEST(CrushProfile, FrontStationsFromLeftToRight) {
  // front column k (y = -1 + 0.4 k) pushed back by 0.1 (k + 1)
  CrushBox box;
  for (std::size_t v = 0; v < box.state.delta.size(); ++v) {
    const Vec3& p = box.model.mesh.vertices[v];
    if (p.x() != 2.0) continue;
    const int k = static_cast<int>(std::lround((p.y() + 1.0) / 0.4));
    box.state.delta[v] = Vec3(-0.1 * (k + 1), 0.02, 0);
  }
  const CrushProfile p = MeasureCrushProfile(box.model, box.state);
  EXPECT_EQ(p.face, CrushFace::kFront);
  EXPECT_STREQ(CrushFaceName(p.face), "front");
  EXPECT_NEAR(p.width, 2.0, 1e-12);
  EXPECT_NEAR(p.centre, 0.0, 1e-12);
  EXPECT_NEAR(p.max_depth, 0.6, 1e-12);
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(p.station[k], -1.0 + 0.4 * k, 1e-12) << k;  // C1 at the left (-y)
    EXPECT_NEAR(p.crush[k], 0.1 * (k + 1), 1e-12) << k;
  }
}

TEST(CrushProfile, DamageWidthOnlyWhereDamaged) {
  // only the three left columns crushed: width 0.8, centred at y = -0.6; 5 % of the largest is the threshold
  CrushBox box;
  for (std::size_t v = 0; v < box.state.delta.size(); ++v) {
    const Vec3& p = box.model.mesh.vertices[v];
    if (p.x() == 2.0 && p.y() < -0.1) box.state.delta[v] = Vec3(-0.3, 0, 0);
    if (p.x() == 2.0 && p.y() > 0.9) box.state.delta[v] = Vec3(-0.01, 0, 0);  // under 5 %: not damage
  }
  const CrushProfile p = MeasureCrushProfile(box.model, box.state);
  EXPECT_EQ(p.face, CrushFace::kFront);
  EXPECT_NEAR(p.width, 0.8, 1e-12);
  EXPECT_NEAR(p.centre, -0.6, 1e-12);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(p.crush[k], 0.3, 1e-12) << k;  // nearest vertex where none lies within
}

TEST(CrushProfile, LeftSideFromFrontToRear) {
  // left side (y = -1) pushed toward +y, deepest at the front; a smaller dent on the back
  CrushBox box;
  for (std::size_t v = 0; v < box.state.delta.size(); ++v) {
    const Vec3& p = box.model.mesh.vertices[v];
    if (p.y() == -1.0) box.state.delta[v] = Vec3(0, 0.1 + 0.05 * (p.x() + 2.0), 0);
    if (p.x() == -2.0 && p.y() > 0.5) box.state.delta[v] += Vec3(0.05, 0, 0);
  }
  const CrushProfile p = MeasureCrushProfile(box.model, box.state);
  EXPECT_EQ(p.face, CrushFace::kLeft);
  EXPECT_NEAR(p.width, 4.0, 1e-12);
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(p.station[k], 2.0 - 0.8 * k, 1e-12) << k;  // C1 at the front (+x)
    EXPECT_NEAR(p.crush[k], 0.1 + 0.05 * (4.0 - 0.8 * k), 1e-12) << k;
  }
  // depth only counts motion into the face
  EXPECT_EQ(CrushDepth(box.state, 0, CrushFace::kNone), 0.0);
}

}  // namespace
}  // namespace dymesh
