// A host that owns its own bodies: a box car into a rigid wall at 30 mph, built in code (no files),
// run by dymesh::Simulation with the Embree search. Exits 0 when the box stops and rebounds as the
// barrier closed form says (delta-V between v and 2v), 1 otherwise.
#include <cmath>
#include <cstdio>
#include <memory>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/units.h"

int main() {
  using namespace dymesh;
  const double in = units::kInch;
  // the car: a 180 x 66 x 30 in box, 3000 lb, A = 300 lb/in, B = 100 lb/in^2 over 30 in
  std::array<Stiffness, kBodySurfaceCount> k;
  k.fill(StiffnessFrom2D(300 * units::PoundPerInchPow(1), 100 * units::PoundPerInchPow(2), 30 * in));
  const double mass = 3000 * units::kPoundMass;
  auto car = std::make_shared<const BodyModel>(MakeBodyModel("car", MakeBox(180 * in, 66 * in, 30 * in, 1, 11, 5), k,
                                                             mass, Mat3::Identity() * mass, 0.1, 0.0, false));
  auto wall = std::make_shared<const BodyModel>(MakeBodyModel("wall", MakeBox(40 * in, 400 * in, 100 * in, 1, 4, 2), k,
                                                              0.0, Mat3::Identity(), 0.1, 0.0, true));
  Scenario s;
  s.time_step = 0.0005;
  s.duration = 0.3;
  s.bodies.resize(2);
  s.bodies[0].name = "car";
  s.bodies[0].mass = mass;
  s.bodies[0].initial.velocity = Vec3(30 * units::kMph, 0, 0);
  s.bodies[1].name = "wall";
  s.bodies[1].rigid = true;
  s.bodies[1].motion = MotionModel::kFixed;
  s.bodies[1].initial.position = Vec3(110.5 * in, 0, 0);
  Simulation sim(s, {car, wall}, accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  sim.Run();
  const double dv = std::abs(sim.engine().state(0).rigid.velocity.x() - 30 * units::kMph) / units::kMph;
  std::printf("delta-V %.2f mph after %d steps\n", dv, sim.steps());
  return dv > 30.0 && dv < 60.0 ? 0 : 1;
}
