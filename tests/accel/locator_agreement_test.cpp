// Embree and the brute-force oracle agree: same candidate hits, same contact results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "dymesh/io/summary_json.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/accel/brute_force_locator.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/accel/neighbor_box_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/contact_step.h"
#include "dymesh/io/mesh_import.h"

namespace dymesh {
namespace {

TriMesh CarMesh() {
  MeshSource source;
  source.file = std::string(DYMESH_DATA_DIR) + "/meshes/torcs_p406-lod3.obj";
  source.axes = {"x", "z", "-y"};
  TriMesh mesh = BuildBodyMesh(source, "(test)", "mesh");
  const MeshStats stats = ComputeStats(mesh);
  for (Vec3& p : mesh.vertices) p -= 0.5 * (stats.min + stats.max);
  return mesh;
}

// every face the oracle finds along the segment is among Embree's proposals; returns how many it finds
int ExpectOracleFacesProposed(const Locator& brute, const Locator& embree, int key, const Vec3& origin,
                              const Vec3& dir, double length, const std::string& label) {
  std::vector<Candidate> exact, found;
  brute.TrianglesAlongSegment(key, origin, dir, length, &exact);
  embree.TrianglesAlongSegment(key, origin, dir, length, &found);
  std::vector<int> fast;
  for (const Candidate& c : found) fast.push_back(c.triangle);
  std::sort(fast.begin(), fast.end());
  for (const Candidate& c : exact) EXPECT_TRUE(std::binary_search(fast.begin(), fast.end(), c.triangle)) << label;
  return static_cast<int>(exact.size());
}

TEST(LocatorAgreement, EmbreeFindsEveryTriangleTheOracleFinds) {
  const TriMesh mesh = CarMesh();
  auto device = std::make_shared<const accel::EmbreeDevice>();
  accel::EmbreeLocator embree(device, mesh);
  accel::BruteForceLocator brute(mesh);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> box(-2.5, 2.5), unit(-1.0, 1.0);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    // random short segments through the car's bounds, as Location casts them
    const Vec3 origin(box(rng), box(rng) * 0.5, box(rng) * 0.4);
    const Vec3 dir = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    hits += ExpectOracleFacesProposed(brute, embree, i, origin, dir, 0.3, std::to_string(i));
  }
  EXPECT_GT(hits, 100);  // the sample really crosses the surface
}

TEST(LocatorAgreement, EmbreeFollowsACrushOnAMeshOfManyGroups) {
  // a mesh of more than 65,536 triangles is cut into Embree groups of 4096, each refit alone from
  // its own run of float corners. The lod3 car subdivided twice (66,720 triangles, 17 groups), its
  // front 0.4 m pushed back unevenly: every face the oracle finds along random segments through the
  // crushed front is proposed, before the crush and after it
  const TriMesh mesh = Subdivide(Subdivide(CarMesh()));
  ASSERT_GT(mesh.triangles.size(), 65536u);
  auto device = std::make_shared<const accel::EmbreeDevice>();
  accel::EmbreeLocator embree(device, mesh);
  accel::BruteForceLocator brute(mesh);
  const double front = ComputeStats(mesh).max.x();
  std::vector<Vec3> crushed = mesh.vertices;
  std::vector<int> moved;
  for (size_t v = 0; v < crushed.size(); ++v) {
    if (crushed[v].x() < front - 0.4) continue;
    crushed[v].x() -= 0.1 + 0.05 * std::sin(9.0 * crushed[v].y()) * std::cos(7.0 * crushed[v].z());
    moved.push_back(static_cast<int>(v));
  }
  ASSERT_GT(moved.size(), 1000u);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> along(front - 0.6, front), across(-1.0, 1.0), unit(-1.0, 1.0);
  for (int crush = 0; crush < 2; ++crush) {
    if (crush == 1) {
      embree.Update(crushed, moved);
      embree.Commit();
      brute.Update(crushed, moved);
    }
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
      const Vec3 origin(along(rng), across(rng), 0.5 * across(rng));
      const Vec3 dir = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
      const std::string label = "crush " + std::to_string(crush) + ", segment " + std::to_string(i);
      hits += ExpectOracleFacesProposed(brute, embree, i, origin, dir, 0.3, label);
    }
    EXPECT_GT(hits, 100) << "crush " << crush;  // the segments really cross the surface
  }
}

TEST(LocatorAgreement, EmbreeFindsTheSeamOfADisplayMesh) {
  // a tent whose two roof faces meet at a ridge made of separate, coincident vertices (a display
  // mesh's seam). Inflated along each face's own normal the float ridges part and a ray down the
  // ridge slips between them; the oracle (edge-inclusive, double) finds the ridge triangles
  TriMesh tent;
  tent.vertices = {{0, 0, 1}, {1, 0, 1}, {0, -1, 0}, {1, -1, 0},   // face A with its own ridge
                   {0, 0, 1}, {1, 0, 1}, {0, 1, 0}, {1, 1, 0}};    // face B with its own ridge
  tent.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
  auto device = std::make_shared<const accel::EmbreeDevice>();
  accel::EmbreeLocator embree(device, tent);
  accel::BruteForceLocator brute(tent);
  for (int i = 1; i < 100; ++i) {
    const Vec3 origin(i / 100.0, 0.0, 2.0), down(0, 0, -1);
    EXPECT_GT(ExpectOracleFacesProposed(brute, embree, i, origin, down, 2.0, "x = " + std::to_string(i / 100.0)), 0);
  }
}

// rays from origin(i), i in [-n, n], along dir: every face the double test crosses is proposed by
// Embree, and every proposal trusted as inside is crossed. Returns how many rays cross a face
int ExpectEveryCrossedFaceProposed(const TriMesh& mesh, const std::function<Vec3(int)>& origin, const Vec3& dir,
                                   double length, int n) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  accel::EmbreeLocator embree(device, mesh);
  accel::BruteForceLocator brute(mesh);
  int crossed = 0;
  for (int i = -n; i <= n; ++i) {
    std::vector<Candidate> exact, found;
    brute.TrianglesAlongSegment(i, origin(i), dir, length, &exact);
    embree.TrianglesAlongSegment(i, origin(i), dir, length, &found);
    std::vector<int> crosses, proposed;
    for (const Candidate& e : exact) crosses.push_back(e.triangle);
    for (const Candidate& f : found) proposed.push_back(f.triangle);
    std::sort(crosses.begin(), crosses.end());
    std::sort(proposed.begin(), proposed.end());
    for (int t : crosses) EXPECT_TRUE(std::binary_search(proposed.begin(), proposed.end(), t)) << "ray " << i << " face " << t;
    for (const Candidate& f : found) {
      if (!f.inside) continue;
      EXPECT_TRUE(std::binary_search(crosses.begin(), crosses.end(), f.triangle)) << "ray " << i;
    }
    crossed += !crosses.empty();
  }
  return crossed;
}

TEST(LocatorAgreement, EmbreeTrustsNoGrazingHitNearAnEdge) {
  // two faces of a car's flat side (the stock car's, where a sample of the ensemble demo met it),
  // rays grazing them at 89.5 degrees across their shared edge. A float hit's error along a face
  // grows as 1 / cos of that angle: the ray landed on the neighbour of the face the double test
  // crosses, a millimetre from the edge, and was trusted as clear of the edge (the neighbours around
  // it were not proposed, and the face it crosses was missed)
  const Vec3 a(1.67486003, -0.566591024, 0.202000006), b(1.48739007, -0.566591024, -0.120362),
      c(1.56504992, -0.566591024, -0.0612070127);
  TriMesh panel;
  panel.vertices = {a, b, c, a + c - b};
  panel.triangles = {{0, 1, 2}, {0, 2, 3}};
  // the sample's ray, moved up to 2 mm along z: crossings on both sides of the edge and on it
  auto origin = [](int i) { return Vec3(1.67415636, -0.567167749, 0.033792417 + 2e-5 * i); };
  const Vec3 dir(-0.999965598, 0.00829474236, 0.0);
  EXPECT_EQ(ExpectEveryCrossedFaceProposed(panel, origin, dir, 0.2032, 100), 201);  // every ray crosses
}

TEST(LocatorAgreement, EmbreeProposesBothSheetsOfAFold) {
  // two faces of the stock car's crushed front folded back onto each other (sample 94 of the ensemble
  // demo, step 755), and a ray through both sheets a hair from their shared edge. Their vertex
  // normals nearly cancel, so inflating along them did not carry the fold's edge outward: the ray
  // crossed both faces in double and neither in float. The same for the fold's other orientation
  // (windings reversed: the normals, and so the inflation, turn over) and for rays past the edge
  const Vec3 v1439(1.98631602, 0.0519918906, 0.0628153023), v2821(2.00016229, 0.065896574, 0.110369883),
      v3536(1.83280847, 0.16302044, 0.219156662), v2814(1.90260036, 0.0436656875, 0.128754858);
  const Vec3 o(1.94727278, 0.192497915, 0.159436955), dir(-0.263272379, -0.964721543, 0.0);
  // rays 10 nm apart across the edge, 2 um either side of the sample's ray
  const Vec3 across = dir.cross(v3536 - v2821).normalized();
  auto origin = [&](int i) { return Vec3(o + 1e-8 * i * across); };
  for (bool reversed : {false, true}) {
    TriMesh fold;
    fold.vertices = {v1439, v2821, v3536, v2814};
    fold.triangles = {{0, 1, 2}, {3, 2, 1}};
    if (reversed) {
      for (auto& t : fold.triangles) std::swap(t[1], t[2]);
    }
    const int crossed = ExpectEveryCrossedFaceProposed(fold, origin, dir, 0.2032, 200);
    EXPECT_GT(crossed, 100) << "reversed " << reversed;  // the sweep reaches both sides of the edge
    EXPECT_LT(crossed, 401) << "reversed " << reversed;
  }
}

// same contact step with either locator, from random interpenetrating poses
void ExpectSameContact(SearchDirection method, StopRule rule) {
  const TriMesh mesh = CarMesh();
  std::array<Stiffness, kBodySurfaceCount> k{};
  k.fill(StiffnessFrom2D(5e4, 1e6, 0.76));
  auto model = std::make_shared<const BodyModel>(
      MakeBodyModel("car", mesh, k, 1400, Mat3::Identity() * 2000, 0.1, 0.3, false));
  ContactOptions options;
  options.search_direction = method;
  options.stop_rule = rule;
  auto device = std::make_shared<const accel::EmbreeDevice>();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    // the second car nose-first into the first one's side, randomly turned and offset
    RigidState a, b;
    b.position = Vec3(0.3 * jitter(rng), -3.07 + 0.05 * jitter(rng), 0.02 * jitter(rng));
    b.yaw = 1.5708 + 0.15 * jitter(rng);
    b.velocity = Vec3(0.0, 10.0, 0.0);
    ContactEngine with_embree({model, model}, {a, b}, options, accel::MakeEmbreeLocatorFactory(device));
    ContactEngine with_boxes({model, model}, {a, b}, options, accel::MakeNeighborBoxLocatorFactory(options));
    ContactEngine with_oracle({model, model}, {a, b}, options, accel::MakeBruteForceLocatorFactory());
    for (int step = 0; step < 3; ++step) {
      const StepResult fast = with_embree.Step(1e-3);
      const StepResult boxes = with_boxes.Step(1e-3);
      const StepResult exact = with_oracle.Step(1e-3);
      EXPECT_EQ(fast.diagnostics.located, exact.diagnostics.located);
      EXPECT_EQ(boxes.diagnostics.located, exact.diagnostics.located);
      for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(fast.loads[i].force_earth, exact.loads[i].force_earth);
        EXPECT_EQ(boxes.loads[i].force_earth, exact.loads[i].force_earth);
        EXPECT_EQ(with_embree.state(i).delta, with_oracle.state(i).delta);
        EXPECT_EQ(with_boxes.state(i).delta, with_oracle.state(i).delta);
      }
    }
    EXPECT_GT(with_oracle.state(0).crush_energy + with_oracle.state(1).crush_energy, 0.0) << "trial " << trial << " made no contact";
  }
}

TEST(LocatorAgreement, LocalNormalBestOfAll) { ExpectSameContact(SearchDirection::kLocalAverageNormal, StopRule::kBestOfAll); }
TEST(LocatorAgreement, VelocityAfterOne) { ExpectSameContact(SearchDirection::kVelocity, StopRule::kAfterOne); }
TEST(LocatorAgreement, PolyNormalBestOfTwo) { ExpectSameContact(SearchDirection::kPolyNormal, StopRule::kBestOfTwo); }
TEST(LocatorAgreement, SpecifiedDirection) { ExpectSameContact(SearchDirection::kSpecified, StopRule::kBestOfAll); }

// a whole car-to-car run on coarse real meshes: the three locators give the same summary and crush
TEST(LocatorAgreement, WholeRunIdenticalForAllLocators) {
  Scenario scenario = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/car_to_car_side.json");
  for (BodySpec& b : scenario.bodies) b.mesh.file = std::string(DYMESH_DATA_DIR) + "/meshes/torcs_p406-lod3.obj";
  scenario.duration = 0.02;
  scenario.contact.calc_nabor_interval = 5;  // lists reused across steps, as DyMESH did
  auto device = std::make_shared<const accel::EmbreeDevice>();
  const LocatorFactory factories[] = {accel::MakeBruteForceLocatorFactory(), accel::MakeEmbreeLocatorFactory(device),
                                      accel::MakeNeighborBoxLocatorFactory(scenario.contact)};
  std::vector<std::string> summaries;
  std::vector<std::vector<Vec3>> crush;
  for (const LocatorFactory& factory : factories) {
    Simulation sim(scenario, BuildBodyModels(scenario), factory);
    sim.Run();
    summaries.push_back(SummaryJson(Summarize(sim), scenario, {}));
    crush.push_back(sim.engine().state(1).delta);
    EXPECT_GT(sim.engine().state(1).crush_energy, 0.0);
  }
  EXPECT_EQ(summaries[1], summaries[0]) << "Embree";
  EXPECT_EQ(summaries[2], summaries[0]) << "neighbour box";
  EXPECT_EQ(crush[1], crush[0]);
  EXPECT_EQ(crush[2], crush[0]);
}

}  // namespace
}  // namespace dymesh
