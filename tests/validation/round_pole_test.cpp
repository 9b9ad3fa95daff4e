// A car into a round rigid pole struck off its centreline: the pole stops it; it does not pass
// through. A node pushed only along the pole's normal slid round the pole with the car (the p406 at
// 20 mph kept all but 0.35 mph of its speed with the pole 5 in off its axis); spec §7's Coulomb
// friction in the node's motion (StickingCorrection) holds it where it touched, and the pole's nodes
// push the faces they cross between the car's nodes (PushFacesOffRigidNodes).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/run_assessment.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/units.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = units;

// the shipped demo: the p406 at 20 mph into a 12 in round pole, its axis on the car's centreline
Scenario RoundPole(double offset_in) {
  Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/pole_cylinder.json");
  s.bodies[1].initial.position.y() += offset_in * u::kInch;
  return s;
}

struct PoleRun {
  double delta_v = 0.0;  // [m/s] the car's
  double balance = 0.0;
  double yaw_radius2 = 0.0;  // [m^2] the car's yaw inertia over its mass
  double restitution = 0.0;
  bool in_contact_at_end = false;
  RunStatus status = RunStatus::kComplete;
};

PoleRun RunPole(Scenario s) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  const int car = sim.engine().model(0).rigid ? 1 : 0;
  const BodyModel& m = sim.engine().model(car);
  const Summary sum = Summarize(sim);
  return {sum.bodies[car].delta_v, sum.energy_balance_error, m.inertia(2, 2) / m.mass, m.restitution,
          sim.in_contact_at_end(), sum.status};
}

// Known answer (impulse-momentum, planar): the pole stops the contact point (e = 0, friction holding
// it) at lever arm r from the CG, r reaching the pole's axis offset d sideways. The CG's delta-V along
// the approach is then V (1 - d^2 / (k^2 + |r|^2)), k^2 = I_zz / m, least when |r| is least (= d):
// the lower bar V (1 - d^2 / (k^2 + d^2)), 0.99 V at 5 in and 0.90 V at 18 in for the p406 (k = 52.6
// in). A car that goes through keeps most of its speed (0.35 mph of 20 before the fix). The upper bar
// is the rebound's: a node gives back at most its peak force over e delta_max (spec §6), and the
// loading law A + B delta has F_peak delta_max <= 2 x its work, so the car leaves at most sqrt(2 e) V.
// The energy balance within 2 % (the issue's bar)
enum class LowerBar { kHeld, kHeldOrStillPushing, kPrinted };

void ExpectPoleStopsCar(const std::string& label, double offset_in, const std::function<void(Scenario*)>& vary,
                        LowerBar lower_bar = LowerBar::kHeld) {
  Scenario s = RoundPole(offset_in);
  vary(&s);
  const double speed = 20.0 * u::kMph, d = offset_in * u::kInch;
  const PoleRun r = RunPole(s);
  const double lower = speed * (1.0 - d * d / (r.yaw_radius2 + d * d));
  const double upper = speed * (1.0 + std::sqrt(2.0 * r.restitution));
  if (lower_bar == LowerBar::kHeld) {
    EXPECT_GT(r.delta_v, lower) << label << ", pole " << offset_in << " in off the centreline";
  } else if (lower_bar == LowerBar::kHeldOrStillPushing) {
    EXPECT_TRUE(r.delta_v > lower || r.status == RunStatus::kEndedInContact)
        << label << ", pole " << offset_in << " in off the centreline: under the bar and not marked";
  }
  EXPECT_LT(r.delta_v, upper) << label << ", pole " << offset_in << " in off the centreline";
  EXPECT_NEAR(r.balance, 0.0, 0.02) << label;
  std::printf("[measured] round pole %.0f in off, %s: delta-V %.2f mph (bars %.2f-%.2f), balance %.4f %%\n", offset_in,
              label.c_str(), r.delta_v / u::kMph, lower / u::kMph, upper / u::kMph, 100 * r.balance);
}

TEST(RoundPole, StopsTheCarAtEveryOffset) {
  for (double offset : {0.0, 5.0, 10.0, 14.0, 18.0}) ExpectPoleStopsCar("default", offset, [](Scenario*) {});
}

TEST(RoundPole, StopsTheCarForEverySearchStopRulePassCountStepMeshOrderAndFrame) {
  const std::vector<testing::ScenarioVariant> variants =
      testing::ContactVariantsWithMeshAndOrder("car mesh 1:4", "pole first");
  // known limit (README): with the polygon-normal search the car's front slides round the pole 14 in
  // off instead of being held at it, the lower bar's premise: over eight starts 0.004 in apart it
  // leaves 18.35-20.17 mph, six of them 0.2-1.8 % under the bar (18.38-20.93, six, before the friction
  // read the slide at the step's end); printed, held to the upper bar and the balance only
  for (const auto& [label, vary] : variants) {
    for (double offset : {5.0, 14.0}) {
      const bool printed = label == std::string("polygon normal") && offset == 14.0;
      ExpectPoleStopsCar(label, offset, vary, printed ? LowerBar::kPrinted : LowerBar::kHeld);
    }
  }
}

// Without friction nothing holds a node on the round face: the car's nodes slide round the pole, which
// went on between them (0.20 mph of 20 at 5 in off). The pole's own nodes now push the faces it
// crosses between the car's nodes (CoarseFace tests), and the car stops, with the same upper bar. The
// lower bar's premise, friction holding the contact point, is gone: the car's front wraps round the
// pole and slides along it, a chaotic case (README, Known limits: shifting the pole 0.01 in at a time
// moved delta-V 19.4-29.0 mph at 5 in off without the turn within the step, 18.6-28.1 with it, the
// four runs of eleven under the bar still pushing at the demo's 0.7 s). So under the bar the run must
// say it has not finished (`ended_in_contact`). (How deep the pole goes before it stops is a known
// limit: README)
TEST(RoundPole, FrictionlessPoleStopsTheCar) {
  for (double offset : {5.0, 14.0})
    ExpectPoleStopsCar("frictionless", offset, [](Scenario* s) {
      for (BodySpec& b : s->bodies) b.friction = 0.0;
    }, LowerBar::kHeldOrStillPushing);
}

// Centred and frictionless, the pole ploughs deep into the car, which has not come to rest at the
// demo's 0.7 s (0.6 mph left of 20): the run must say so (ended in contact, README status table)
// rather than report a delta-V that is not yet the collision's
TEST(RoundPole, FrictionlessCentredPoleStillPushingAtTheEndIsMarked) {
  Scenario s = RoundPole(0.0);
  for (BodySpec& b : s.bodies) b.friction = 0.0;
  const PoleRun r = RunPole(s);
  std::printf("[measured] round pole centred, frictionless: delta-V %.2f mph, in contact at the end: %d\n",
              r.delta_v / u::kMph, r.in_contact_at_end ? 1 : 0);
  EXPECT_TRUE(r.delta_v > 20.0 * u::kMph || r.in_contact_at_end) << "stopped short of V and not marked";
  EXPECT_GT(r.delta_v, 0.9 * 20.0 * u::kMph) << "the pole let the car through";
}

// The pole's axis point and direction at every recorded state, in the car's frame, and its radius and
// half-height: a vertical cylinder, centred in its rest bounds
struct PoleTrack {
  std::vector<Vec3> centre, axis;
  double radius = 0.0, half_height = 0.0;
};

PoleTrack TrackPole(const Simulation& sim, int car, int pole) {
  const MeshStats rest = ComputeStats(sim.engine().model(pole).mesh);
  const Vec3 mid = 0.5 * (rest.min + rest.max);
  PoleTrack track{{}, {}, 0.5 * (rest.max.x() - rest.min.x()), 0.5 * (rest.max.z() - rest.min.z())};
  for (const Sample& sample : sim.history()) {
    const RigidState& a = sample.bodies[car].rigid;
    const RigidState& b = sample.bodies[pole].rigid;
    const Mat3 to_car = a.Rotation().transpose();
    track.centre.push_back(to_car * (b.position + b.Rotation() * mid - a.position));
    track.axis.push_back(to_car * b.Rotation() * Vec3::UnitZ());
  }
  return track;
}

// How far along a node's crush u, from its rest place p0, the pole ever came (car frame): the support
// of a cylinder, axis point c, radius r, half-height h, is c.u + r |u across the axis| + h |u along
// it|, its largest over the run's recorded states
double PoleReach(const PoleTrack& pole, const Vec3& p0, const Vec3& u) {
  double reach = -INFINITY;
  for (std::size_t k = 0; k < pole.centre.size(); ++k) {
    const double along_axis = u.dot(pole.axis[k]);
    const double across = std::sqrt(std::max(0.0, 1.0 - along_axis * along_axis));
    reach = std::max(reach, (pole.centre[k] - p0).dot(u) + pole.radius * across +
                                pole.half_height * std::abs(along_axis));
  }
  return reach;
}

// Known answer: a node is crushed only where the pole pushed it, so along its crush it lies no farther
// from its rest place than the pole came (PoleReach, exact for the cylinder). With the pole 5 in off,
// faces of the car's crushed front are pushed by the pole's nodes and tipped past it (a least-squares
// plane through a curved row of them: Known limits): the deepest crush scatters from 38 to 89 in under
// 0.001 in moves of the pole while the pole reached about 42 in. Such a run must say so
// (crush_beyond_reach); one whose every node lies within the pole's reach must not. The run's check
// takes the pole as its bounding box (reach up to (sqrt 2 - 1) r = 2.5 in larger on a slant) and
// allows TOOFAR_MARGIN (1 in, spec §2) past it: runs in that band may go either way
TEST(RoundPole, CrushDeeperThanThePoleCameIsMarked) {
  // the nodes looked at: crushed 4 in or more (the run's check looks at the deepest 256; the deep
  // ones are those a tipped face can carry past the pole)
  constexpr double kDeepCrush = 0.1;
  for (const SearchDirection search : {SearchDirection::kVelocity, SearchDirection::kPolyNormal}) {
    int beyond = 0;
    // (four starts of the polygon-normal search, which runs long: they all cross the pole's reach)
    const int starts = search == SearchDirection::kVelocity ? 8 : 4;
    for (int jitter = 0; jitter < starts; ++jitter) {
      Scenario s = RoundPole(5.0);
      s.contact.search_direction = search;
      s.bodies[1].initial.position.y() += 0.001 * jitter * u::kInch;
      auto device = std::make_shared<const accel::EmbreeDevice>();
      Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device));
      sim.Run();
      const BodyState& car = sim.engine().state(0);
      const std::vector<Vec3>& rest = sim.engine().model(0).mesh.vertices;
      const PoleTrack pole = TrackPole(sim, 0, 1);
      double worst = -INFINITY;  // [m] the largest crush beyond the pole's reach
      for (std::size_t v = 0; v < rest.size(); ++v) {
        const double crush = car.delta[v].norm();
        if (crush < kDeepCrush) continue;
        worst = std::max(worst, crush - PoleReach(pole, rest[v], car.delta[v] / crush));
      }
      const Summary sum = Summarize(sim);
      bool marked = false;
      for (const RunWarning& w : sum.warnings) marked = marked || (w.code == "crush_beyond_reach" && w.field == "bodies[0]");
      std::printf("[measured] round pole 5 in off, %s search, moved %d thou: deepest crush %.1f in, %.1f in beyond the "
                  "pole's reach, marked %d\n", search == SearchDirection::kVelocity ? "velocity" : "polygon-normal",
                  jitter, sum.bodies[0].max_crush / u::kInch, worst / u::kInch, marked ? 1 : 0);
      if (worst > 3.5 * u::kInch) {
        EXPECT_TRUE(marked) << jitter << " thou: crushed beyond the pole's reach, unmarked";
      }
      if (worst < 1.0 * u::kInch) {
        EXPECT_FALSE(marked) << jitter << " thou: within the pole's reach, marked";
      }
      beyond += worst >= 3.5 * u::kInch ? 1 : 0;
    }
    // with the velocity search the crush stays within the pole's reach since the faces the p406 had wound
    // inward are turned (68th session: 1 of the 8 at 3.5 in beyond; 7 or 8 of the 8 marked before); the
    // polygon-normal search still tips the stretched faces past it (12-26 in), which exercises the marking;
    // delta-V stands (an ensemble keeps the sample). The bar, 2 of 8: the measured 1 and one more, as each
    // start is a draw of the contact's branch (0.001 in moves); 7 or 8, as before, fail it
    if (search == SearchDirection::kVelocity) {
      EXPECT_LE(beyond, 2);
    } else {
      EXPECT_GT(beyond, 0);
    }
  }
  EXPECT_FALSE(WarningVoidsResults("crush_beyond_reach"));
}

// a 3000 lb box 180 x 66 x 30 in (A 300 lb/in, B 100 lb/in^2 over 30 in, e 0), its front in `cell` in
// cells, into a fixed 12 in round pole (32 facets) `offset` in off its axis, friction mu on both
struct BoxPole {
  int cell = 3;              // [in]
  double speed = 10.0;       // [mph]
  double offset = 0.0;       // [in]
  double mu = 0.3;
  double duration = 1.0;     // [s]
  std::string search = "velocity";
};

Scenario BoxIntoPole(const BoxPole& c) {
  const std::string segments = "[18, " + std::to_string(66 / c.cell) + ", " + std::to_string(30 / c.cell) + "]";
  const std::string friction = std::to_string(c.mu);
  return ParseScenario(R"({"units": "US", "time": {"step": 0.0005, "duration": )" + std::to_string(c.duration) +
                           R"(, "stop_at_separation": true},
    "contact": {"passes_per_step": 2, "search_direction": ")" + c.search + R"("},
    "bodies": [
      {"name": "box", "mesh": {"box": {"length": 180, "width": 66, "height": 30, "segments": )" + segments + R"(}},
       "weight": 3000, "restitution": 0, "friction": )" + friction + R"(, "motion": "planar",
       "stiffness": {"default": {"A": 300, "B": 100, "conversion_height": 30}},
       "initial": {"position": [-150, 0, 0], "heading": 0, "speed": )" + std::to_string(c.speed) +
                           R"(, "place_at_contact": {"with": "pole", "gap": 0.5}}},
      {"name": "pole", "mesh": {"cylinder": {"radius": 6, "height": 100, "segments": 32}}, "rigid": true,
       "motion": "fixed", "friction": )" + friction + R"(, "restitution": 0, "initial": {"position": [0, )" +
                           std::to_string(c.offset) + R"(, 0]}}]})",
                       "box_into_round_pole.json");
}

// the box (3 in cells) at 20 mph into the pole 15 in off its axis, mu 0.3
Scenario BoxIntoOffsetPole(const std::string& search_direction) {
  return BoxIntoPole({3, 20.0, 15.0, 0.3, 1.5, search_direction});
}

// With the local-average-normal search the box's own nodes and the pole's nodes pushed the same faces
// back and forth, and nodes ended far outside the box (the max crush read 161 in where the velocity
// search gave 37.6). The pole's nodes now press only the faces none of whose corners the box's own
// nodes meet the pole with (touching it, or finding it on their search line) over the half of the
// face nearer those corners: both searches keep the box's nodes within its outline (not marked
// crush_outside_outline), and their deepest crush agrees within 20 % (the same impact; measured 3 %)
TEST(RoundPole, NodesStayInTheBoxForBothSearches) {
  double velocity_crush = 0.0;
  for (const std::string search : {"velocity", "local_average_normal"}) {
    const Scenario s = BoxIntoOffsetPole(search);
    auto device = std::make_shared<const accel::EmbreeDevice>();
    Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device));
    sim.Run();
    const Summary sum = Summarize(sim);
    bool marked = false;
    for (const RunWarning& w : sum.warnings) marked = marked || (w.code == "crush_outside_outline" && w.field == "bodies[0]");
    std::printf("[measured] box into the pole 15 in off, %s search: max crush %.1f in, marked %d\n", search.c_str(),
                sum.bodies[0].max_crush / u::kInch, marked ? 1 : 0);
    EXPECT_FALSE(marked) << search;
    if (search == "velocity") velocity_crush = sum.bodies[0].max_crush;
    EXPECT_NEAR(sum.bodies[0].max_crush, velocity_crush, 0.20 * velocity_crush) << search;
  }
}

// CRASH3 over the pole's shadow: each strip dy of the front is a column crushed c - R + sqrt(R^2 - y^2)
// where the pole reached it, with the force per width A + B d, so the kinetic energy 1/2 m v^2 =
// int_0^C int_shadow (A + B d(y)) dy dc gives the crush C on the axis (midpoint sums, 1e-3 in: C to
// 1e-3 in). The box's deepest node is on the axis (centred) or beside it: its max crush is C
double ColumnClosedFormCrushIn() {
  const double radius = 6.0, a = 300.0, b = 100.0;  // [in], [lb/in], [lb/in^2]
  // [lbf in] the 3000 lb box at 10 mph
  const double energy = 0.5 * 3000.0 * u::kPoundMass * std::pow(10.0 * u::kMph, 2) / (u::kPoundForce * u::kInch);
  auto force = [&](double c) {
    const double half = c >= radius ? radius : std::sqrt(radius * radius - (radius - c) * (radius - c));
    const int n = 400;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double y = -half + (i + 0.5) * 2.0 * half / n;
      sum += (a + b * std::max(0.0, c - radius + std::sqrt(radius * radius - y * y))) * 2.0 * half / n;
    }
    return sum;
  };
  double work = 0.0, c = 0.0;
  const double dc = 1e-3;
  while (work < energy) {
    work += force(c + 0.5 * dc) * dc;
    c += dc;
  }
  return c;
}

// Known answer: the column closed form above (12.70 in). The engine crushes each node along the pole's
// normal and friction holds it on the pole's flanks (spec §7), where the columns take no sideways load:
// with mu 0.3 its crush is within 10 % of the columns' for fronts in 2 and 3 in cells (the pole's 12 in
// shadow over 6 and 4 node columns), at dt to dt/4, centred or 1.5 in off, and for every search, stop
// rule, pass count, body order and frame (measured 2026-11-26: -2.0 to +7.6 %, the 3 in cells the high
// end; 1.5 in cells -2.8 %).
// Friction stiffens the flanks (mu 0.5: -10 %, mu 0.8: -13 to -15 %, mu 0.1: +4-14 %, README); 6 in cells, two
// node columns across the pole, let it through between them (marked, README)
TEST(RoundPole, BoxCrushFollowsTheColumnClosedForm) {
  const double closed = ColumnClosedFormCrushIn();
  EXPECT_NEAR(closed, 12.70, 0.01);  // the sum itself, against the figure quoted above
  auto expect_crush = [&](const std::string& label, Scenario s) {
    auto device = std::make_shared<const accel::EmbreeDevice>();
    Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device));
    sim.Run();
    const Summary sum = Summarize(sim);
    const int box = sim.engine().model(0).rigid ? 1 : 0;
    const double crush = sum.bodies[box].max_crush / u::kInch;
    std::printf("[measured] box into the round pole, %s: max crush %.2f in (columns %.2f, %+.1f %%)\n", label.c_str(),
                crush, closed, 100.0 * (crush / closed - 1.0));
    EXPECT_NEAR(crush, closed, 0.10 * closed) << label;
    EXPECT_EQ(sum.status, RunStatus::kComplete) << label;
    EXPECT_NEAR(sum.energy_balance_error, 0.0, 0.02) << label;
  };
  for (int cell : {2, 3})
    for (double offset : {0.0, 1.5})
      for (double divide : {1.0, 2.0, 4.0}) {
        Scenario s = BoxIntoPole({cell, 10.0, offset});
        s.time_step /= divide;
        expect_crush(std::to_string(cell) + " in cells, " + std::to_string(offset).substr(0, 3) + " in off, dt/" +
                         std::to_string(static_cast<int>(divide)),
                     s);
      }
  std::vector<testing::ScenarioVariant> variants = testing::ContactVariants();
  variants.push_back({"pole first", [](Scenario* s) {
                        std::swap(s->bodies[0], s->bodies[1]);
                        s->bodies[1].place_at_contact->with = 0;
                      }});
  for (const auto& [label, vary] : variants) {
    Scenario s = BoxIntoPole({2});
    vary(&s);
    expect_crush("2 in cells, " + label, s);
  }
}

// A box stopped against the pole with e = 0 (3 in cells, 1.5 in off its axis) slides on past it,
// turning, with a touch of under 1e-4 of its peak contact force to the run's end (the two bodies'
// loads summed: measured 0.007 of 40,000 lbf): `complete`, warned `light_contact_at_end`
// (kLightContactShare). The same run cut at its peak force ends pushing: `ended_in_contact`
TEST(RoundPole, TouchAfterTheStopIsALightContact) {
  BoxPole c{3, 10.0, 1.5};
  c.duration = 0.3;
  auto run = [](const Scenario& s, double* peak_time) {
    auto device = std::make_shared<const accel::EmbreeDevice>();
    Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device));
    sim.Run();
    auto load = [](const Sample& sample) {
      double f = 0.0;
      for (const BodySample& b : sample.bodies) f += b.loads.force_earth.norm();
      return f;
    };
    double peak = 0.0;
    for (const Sample& sample : sim.history()) {
      if (load(sample) <= peak) continue;
      peak = load(sample);
      *peak_time = sample.time;
    }
    const double end = load(sim.history().back());
    std::printf("[measured] box stopped against the pole 1.5 in off: load at %.3f s %.3g lbf of its %.0f lbf peak\n",
                sim.time(), end / u::kPoundForce, peak / u::kPoundForce);
    return std::make_pair(Summarize(sim), end / peak);
  };
  double peak_time = 0.0, unused = 0.0;
  const auto [touching, share] = run(BoxIntoPole(c), &peak_time);
  EXPECT_GT(share, 0.0);  // the case: still touching at the end
  EXPECT_LE(share, kLightContactShare);
  EXPECT_EQ(touching.status, RunStatus::kComplete);
  bool warned = false;
  for (const RunWarning& w : touching.warnings) warned = warned || w.code == "light_contact_at_end";
  EXPECT_TRUE(warned);
  c.duration = peak_time;
  EXPECT_EQ(run(BoxIntoPole(c), &unused).first.status, RunStatus::kEndedInContact);
}

}  // namespace
}  // namespace dymesh
