#include "bench_command.h"

#include <chrono>
#include <cstdio>
#include <functional>

#include <nlohmann/json.hpp>

#include "contact_setup.h"
#include "dymesh/core/scenario.h"
#include "dymesh/ensemble/spec.h"
#include "locate_rates.h"
#include "step_timing.h"

namespace dymesh::cli {
namespace {

constexpr double kPenetration = 0.10;  // [m]
constexpr double kSpeed = 13.4;        // [m/s] 30 mph
constexpr size_t kNeighborBoxSample = 4000;

// best of three timings of one pass over the segments [segments/s]
double Rate(size_t segments, const std::function<void()>& locate) {
  double best = 0.0;
  for (int k = 0; k < 3; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    locate();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::max(best, segments / s);
  }
  return best;
}

}  // namespace

int RunBench(const BenchRequest& request) {
  if (!request.ensemble.empty()) return RunEnsembleBench(request);
  if (request.master.empty() || request.slave.empty())
    throw InputError("bench", "--master/--slave", "give both mesh files, or --ensemble SPEC");
  // the two meshes in contact, and one pass's Location segments
  const bench::ContactSetup setup =
      bench::PlaceInContact(bench::LoadUserMesh(request.master, request.axes),
                            bench::LoadUserMesh(request.slave, request.axes), kPenetration, kSpeed);
  const ContactOptions options;
  const bench::RaySet rays = bench::PassRays(setup, options);
  const TriMesh& master = setup.master->mesh;
  if (rays.size() == 0) {
    std::fprintf(stderr, "error: %s and %s do not reach each other when placed in contact (the slave's front %g m into "
                 "the master's side): check --axes and that the files are in metres\n",
                 request.master.c_str(), request.slave.c_str(), kPenetration);
    return 2;
  }
  // locate rates on the same segments (one thread each)
  auto device = std::make_shared<const accel::EmbreeDevice>();
  const accel::EmbreeLocator embree(device, master);
  const BodyState rest = MakeBodyState(*setup.master, RigidState{});
  const double raw = Rate(rays.size(), [&] { bench::LocateWithRawEmbree(embree, rays); });
  const double engine = Rate(rays.size(), [&] { bench::LocateWithEmbreeLocator(embree, master, rest.tri_normal, rays); });
  const bench::RaySet sample = bench::SampleRays(rays, kNeighborBoxSample);
  accel::NeighborBoxLocator boxes(master, options);
  int step = 0;
  const double neighbor = Rate(sample.size(), [&] {
    bench::LocateWithNeighborBox(&boxes, step, sample, options.search_backoff);
    step += options.calc_nabor_interval;  // every timed pass rebuilds its lists, as a new contact does
  });
  // whole collision steps at one and N threads, and the memory of the master body
  const bench::StepTiming one = bench::MeasureSteps(setup, 1, 2, 5);
  const bench::StepTiming many = bench::MeasureSteps(setup, request.threads, 2, 5);
  // the same in mid-pulse, most faces met already crushed (on the benchmark's cars 4-5 early steps)
  const bench::StepTiming mid_one = bench::MeasureSteps(setup, 1, bench::kMidPulseWarmup, 5);
  const bench::StepTiming mid_many = bench::MeasureSteps(setup, request.threads, bench::kMidPulseWarmup, 5);
  // determinism: each timing's final state, bit for bit the same at 1 and N threads
  const bool identical = one.state_hash == many.state_hash && mid_one.state_hash == mid_many.state_hash;
  const bench::BodyMemory memory = bench::MeasureBodyMemory(*setup.master);
  const double nt = static_cast<double>(master.triangles.size());

  nlohmann::json j = {
      {"master_triangles", master.triangles.size()},
      {"slave_triangles", setup.slave->mesh.triangles.size()},
      {"segments", rays.size()},
      {"locate_per_second", {{"engine", engine}, {"raw_embree", raw}, {"neighbor_box", neighbor}}},
      {"ratio_to_raw_embree", {{"engine", engine / raw}, {"neighbor_box", neighbor / raw}}},
      {"step_ms", {{"threads_1", 1e3 * one.step_seconds}, {"threads_n", 1e3 * many.step_seconds}}},
      {"mid_pulse_step_ms", {{"threads_1", 1e3 * mid_one.step_seconds}, {"threads_n", 1e3 * mid_many.step_seconds}}},
      {"mid_pulse_segments_per_step", mid_many.segments},
      {"final_state_hash", {{"threads_1", ensemble::HashText(mid_one.state_hash)}, {"threads_n", ensemble::HashText(mid_many.state_hash)}}},
      {"bit_identical_across_threads", identical},
      {"threads", request.threads},
      {"speedup", one.step_seconds / many.step_seconds},
      {"step_vs_raycast", many.step_seconds / many.raycast_seconds},
      {"bytes_per_triangle", memory.total() / nt},
  };
  if (!identical)
    std::fprintf(stderr, "error: the final state differs between 1 and %d threads (a determinism bug)\n",
                 request.threads);
  if (request.json) {
    std::printf("%s\n", j.dump(2).c_str());
    return identical ? 0 : 1;
  }
  std::printf("master %zu triangles, slave %zu triangles, %zu Location segments per pass\n", master.triangles.size(),
              setup.slave->mesh.triangles.size(), rays.size());
  std::printf("locate (1 thread)       segments/s    vs raw Embree\n");
  std::printf("  engine (Embree)     %12.0f    %6.2fx\n", engine, engine / raw);
  std::printf("  raw Embree          %12.0f    %6.2fx\n", raw, 1.0);
  std::printf("  neighbour box       %12.0f    %6.3fx   (sample of %zu)\n", neighbor, neighbor / raw, sample.size());
  std::printf("collision step        %.3f ms at 1 thread, %.3f ms at %d threads (%.2fx); %.2fx its ray casts\n",
              1e3 * one.step_seconds, 1e3 * many.step_seconds, request.threads, one.step_seconds / many.step_seconds,
              many.step_seconds / many.raycast_seconds);
  std::printf("  in mid-pulse        %.3f ms at 1 thread, %.3f ms at %d threads (after %d steps; %lld segments)\n",
              1e3 * mid_one.step_seconds, 1e3 * mid_many.step_seconds, request.threads, bench::kMidPulseWarmup,
              mid_many.segments);
  std::printf("memory                %.0f bytes per triangle (model %.0f, state %.0f, Embree %.0f)\n",
              memory.total() / nt, memory.model / nt, memory.state / nt, memory.embree / nt);
  std::printf("final state           %s at 1 thread, %s at %d threads: %s\n", ensemble::HashText(mid_one.state_hash).c_str(),
              ensemble::HashText(mid_many.state_hash).c_str(), request.threads, identical ? "bit-identical" : "DIFFERENT");
  return identical ? 0 : 1;
}

}  // namespace dymesh::cli
