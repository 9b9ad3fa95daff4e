// Google Benchmark programs: locate throughput against raw Embree, the original neighbour-box
// search, brute force and CGAL; collision step cost at 1 and 2 threads; refit against rebuild;
// memory per triangle. Meshes are real cars subdivided at run time.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <mutex>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "contact_setup.h"
#include "dymesh/core/contact_step.h"
#include "dymesh/core/parallel.h"
#include "locate_rates.h"
#include "dymesh/ensemble/design.h"
#include "dymesh/ensemble/sample_run.h"
#include "dymesh/ensemble/spec.h"
#ifdef DYMESH_WITH_CGAL
#include "cgal_tree.h"
#endif
#include "step_timing.h"

namespace dymesh::bench {
namespace {

// the mesh ladder: real car bodies, subdivided 1-to-4 at run time (2k to 2.2M triangles)
struct Rung {
  const char* file;
  int subdivisions;
};
constexpr Rung kLadder[] = {{"torcs_p406-lod6.obj", 0}, {"torcs_p406.obj", 0}, {"torcs_p406.obj", 1},
                            {"torcs_p406.obj", 2},      {"torcs_p406.obj", 3}, {"torcs_p406.obj", 4}};
// the step benchmark's cars: about 10k, 100k and 1M triangles each
constexpr Rung kStepCars[] = {{"torcs_p406.obj", 0}, {"torcs_p406.obj", 2}, {"torcs_p406-lod3.obj", 4}};

constexpr double kPenetration = 0.10;  // [m] slave front driven into the master's side
constexpr double kSpeed = 13.4;        // [m/s] closing speed (30 mph)

double Seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

// one contact set-up per rung, built once (subdividing to 2M triangles takes a while)
struct Fixture {
  ContactSetup setup;
  RaySet rays;
  std::shared_ptr<const accel::EmbreeDevice> device;
  std::unique_ptr<accel::EmbreeLocator> embree;
  double raw_rate = 0.0;  // [segments/s] raw Embree on these rays, measured once
};

const Fixture& GetFixture(const Rung& rung) {
  static std::map<std::pair<std::string, int>, std::unique_ptr<Fixture>> cache;
  auto& slot = cache[{rung.file, rung.subdivisions}];
  if (!slot) {
    slot = std::make_unique<Fixture>();
    TriMesh mesh = LoadDataMesh(rung.file, rung.subdivisions);
    slot->setup = PlaceInContact(mesh, mesh, kPenetration, kSpeed);
    slot->rays = PassRays(slot->setup, ContactOptions{});
    slot->device = std::make_shared<const accel::EmbreeDevice>();
    slot->embree = std::make_unique<accel::EmbreeLocator>(slot->device, slot->setup.master->mesh);
    // the baseline of every ratio: raw rtcIntersect1 on the same scene and rays, best of three
    for (int k = 0; k < 3; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(LocateWithRawEmbree(*slot->embree, slot->rays));
      slot->raw_rate = std::max(slot->raw_rate, slot->rays.size() / Seconds(std::chrono::steady_clock::now() - t0));
    }
  }
  return *slot;
}

// items, triangle count, located fraction and the ratio to raw Embree (on `rays`, default all)
void Report(benchmark::State& state, const Fixture& f, size_t located, const RaySet* rays = nullptr) {
  const RaySet& used = rays ? *rays : f.rays;
  const double n = static_cast<double>(used.size());
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * used.size()));
  state.counters["triangles"] = static_cast<double>(f.setup.master->mesh.triangles.size());
  state.counters["segments"] = n;
  state.counters["located_fraction"] = located / n;
  state.counters["vs_raw_embree"] = benchmark::Counter(n / f.raw_rate, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_LocateRawEmbree(benchmark::State& state) {
  const Fixture& f = GetFixture(kLadder[state.range(0)]);
  size_t located = 0;
  for (auto _ : state) located = LocateWithRawEmbree(*f.embree, f.rays);
  Report(state, f, located);
}

void BM_LocateEmbreeLocator(benchmark::State& state) {
  const Fixture& f = GetFixture(kLadder[state.range(0)]);
  size_t located = 0;
  const BodyState rest = MakeBodyState(*f.setup.master, RigidState{});
  for (auto _ : state) located = LocateWithEmbreeLocator(*f.embree, f.setup.master->mesh, rest.tri_normal, f.rays);
  Report(state, f, located);
}

void BM_LocateNeighborBox(benchmark::State& state) {
  // lists rebuilt every CALC_NABOR_INTERVAL = 5 steps, as DyMESH: ten queries, two rebuilds; at the
  // largest sizes an evenly spread sample of 4000 segments (the rate is per segment)
  const Fixture& f = GetFixture(kLadder[state.range(0)]);
  const RaySet rays = SampleRays(f.rays, 4000);
  ContactOptions options;
  accel::NeighborBoxLocator boxes(f.setup.master->mesh, options);
  size_t located = 0;
  int step = 0;
  for (auto _ : state) located = LocateWithNeighborBox(&boxes, step++, rays, options.search_backoff);
  Report(state, f, located, &rays);
}

void BM_LocateBruteForce(benchmark::State& state) {
  const Fixture& f = GetFixture(kLadder[state.range(0)]);
  size_t located = 0;
  for (auto _ : state) located = LocateWithBruteForce(f.setup.master->mesh, f.rays);
  Report(state, f, located);
}

#ifdef DYMESH_WITH_CGAL
void BM_LocateCgal(benchmark::State& state) {
  const Fixture& f = GetFixture(kLadder[state.range(0)]);
  const CgalTree tree(f.setup.master->mesh);
  size_t located = 0;
  for (auto _ : state) located = tree.Locate(f.rays);
  Report(state, f, located);
}
#endif

// car-to-car contact: both passes, forces, sums, refit; the slave driven in at constant speed,
// `warmup` steps before the timed ones
void TimeSteps(benchmark::State& state, const ContactOptions& options, int warmup = 2) {
  const Rung rung = kStepCars[state.range(0)];
  const int threads = static_cast<int>(state.range(1));
  TriMesh mesh = LoadDataMesh(rung.file, rung.subdivisions);
  const ContactSetup setup = PlaceInContact(mesh, mesh, kPenetration, kSpeed);
  StepTiming timing;
  for (auto _ : state) {
    timing = MeasureSteps(setup, threads, warmup, 8, options);
    state.SetIterationTime(timing.step_seconds);
  }
  state.counters["triangles_per_car"] = static_cast<double>(setup.master->mesh.triangles.size());
  state.counters["threads"] = threads;
  state.counters["segments_per_step"] = static_cast<double>(timing.segments);
  state.counters["raycast_ms"] = 1e3 * timing.raycast_seconds;
  state.counters["step_vs_raycast"] = timing.step_seconds / timing.raycast_seconds;
  // determinism: the final state's hash, the same at any thread count
  state.SetLabel("state " + ensemble::HashText(timing.state_hash));
}

void BM_Step(benchmark::State& state) { TimeSteps(state, ContactOptions{}); }

// the same steps with the crushed contact normal (the default until the 60th session): the baseline
// of the conforming normal's cost, in the same run
void BM_StepCrushedNormal(benchmark::State& state) {
  ContactOptions options;
  options.contact_normal = ContactNormal::kCrushed;
  TimeSteps(state, options);
}

// the same steps in mid-pulse: the first steps meet mostly undamaged faces (in BM_Step/2 74 % of
// the located nodes' master faces are still uncrushed; on the side demo 6 %), these crushed ones
void BM_StepMidPulse(benchmark::State& state) { TimeSteps(state, ContactOptions{}, kMidPulseWarmup); }

void BM_RefitVersusRebuild(benchmark::State& state) {
  // range(1) = 0: refit the deformed mesh (DYNAMIC scene); 1: build a new scene from scratch
  const Fixture& f = GetFixture(kLadder[state.range(0)]);
  // a crushed patch: the vertices within 0.3 m of the front pushed back 1 cm
  std::vector<Vec3> crushed = f.setup.master->mesh.vertices;
  std::vector<int> moved;
  const double front = ComputeStats(f.setup.master->mesh).max.x();
  for (size_t v = 0; v < crushed.size(); ++v) {
    if (crushed[v].x() > front - 0.3) {
      crushed[v].x() -= 0.01;
      moved.push_back(static_cast<int>(v));
    }
  }
  accel::EmbreeLocator locator(f.device, f.setup.master->mesh);
  for (auto _ : state) {
    if (state.range(1) == 0) {
      locator.Update(crushed, moved);
      locator.Commit();
    } else {
      accel::EmbreeLocator fresh(f.device, f.setup.master->mesh);
      benchmark::DoNotOptimize(fresh.scene());
    }
  }
  state.counters["triangles"] = static_cast<double>(f.setup.master->mesh.triangles.size());
}

void BM_Memory(benchmark::State& state) {
  // bytes of one deformable body: model, state and Embree scene (BVH and buffers)
  const Fixture& f = GetFixture(kLadder[state.range(0)]);
  BodyMemory m;
  for (auto _ : state) m = MeasureBodyMemory(*f.setup.master);
  const double nt = static_cast<double>(f.setup.master->mesh.triangles.size());
  const double nv = static_cast<double>(f.setup.master->mesh.vertices.size());
  state.counters["triangles"] = nt;
  state.counters["bytes_per_triangle"] = m.total() / nt;
  state.counters["bytes_per_vertex"] = m.total() / nv;
  state.counters["model_B_per_tri"] = m.model / nt;
  state.counters["state_B_per_tri"] = m.state / nt;
  state.counters["embree_B_per_tri"] = m.embree / nt;
}

BENCHMARK(BM_LocateRawEmbree)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LocateEmbreeLocator)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LocateNeighborBox)->DenseRange(0, 5)->Iterations(10)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LocateBruteForce)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
#ifdef DYMESH_WITH_CGAL
BENCHMARK(BM_LocateCgal)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
#endif
BENCHMARK(BM_Step)->ArgsProduct({{0, 1, 2}, {1, 2}})->Iterations(1)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_StepCrushedNormal)->ArgsProduct({{2}, {1, 2}})->Iterations(1)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_StepMidPulse)->ArgsProduct({{2}, {1, 2}})->Iterations(1)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_RefitVersusRebuild)->ArgsProduct({{1, 3, 5}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Memory)->DenseRange(0, 5)->Iterations(1)->Unit(benchmark::kMillisecond);

// issue 11: samples of the p406 ensemble demo per second at 1 and 2 threads (meshes loaded once,
// outside the timing; each iteration runs the same 4 samples)
void BM_EnsembleSamples(benchmark::State& state) {
  static const ensemble::Spec spec = ensemble::LoadSpec(std::string(DYMESH_DATA_DIR) + "/ensembles/p406_oblique.json");
  static const ensemble::DesignTable design(spec);
  static ensemble::SharedAssets assets;
  ensemble::RunSample(spec, 0, design.Values(0), &assets);
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<int>(state.range(0)));
  constexpr int kSamples = 4;
  for (auto _ : state)
    tbb::parallel_for(1, 1 + kSamples, [&](int i) { ensemble::RunSample(spec, i, design.Values(i), &assets); });
  state.counters["samples_per_second"] =
      benchmark::Counter(static_cast<double>(kSamples) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EnsembleSamples)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace dymesh::bench

BENCHMARK_MAIN();
