#include "step_timing.h"

#include <chrono>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/byte_hash.h"
#include "dymesh/core/contact_step.h"
#include "dymesh/core/parallel.h"
#include "locate_rates.h"

namespace dymesh::bench {
namespace {

constexpr double kDt = 0.0005;  // [s] collision time step

double Seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

// an Embree locator that can record the segments it is asked for, to replay them as raw rays
class RecordingLocator final : public Locator {
 public:
  RecordingLocator(std::shared_ptr<const accel::EmbreeDevice> device, const TriMesh& mesh) : inner_(std::move(device), mesh) {}
  void Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) override {
    inner_.Update(vertices, moved);
  }
  void Prepare(int slave_body, int step, const std::vector<int>& keys,
               const std::function<Vec3(int)>& position) override {
    inner_.Prepare(slave_body, step, keys, position);
  }
  void TrianglesAlongSegment(int key, const Vec3& o, const Vec3& d, double length,
                             std::vector<Candidate>* out) const override {
    if (recording_) segments_.local().push_back({o, d, length});
    inner_.TrianglesAlongSegment(key, o, d, length, out);
  }
  void TrianglesNearPoint(int key, const Vec3& p, double r, std::vector<Candidate>* out) const override {
    inner_.TrianglesNearPoint(key, p, r, out);
  }
  void SetRecording(bool on) { recording_ = on; }

  // the recorded segments as raw closest-hit rays on the same scene, in parallel; returns seconds
  // (every Location segment has the same length: search_backoff + toofar_maximum)
  double ReplayRaw(long long* count) {
    RaySet rays;
    for (auto& list : segments_) {
      for (const Segment& s : list) {
        rays.origin.push_back(s.o);
        rays.dir.push_back(s.d);
        rays.length = s.length;
      }
      list.clear();
    }
    *count += static_cast<long long>(rays.size());
    const auto t0 = std::chrono::steady_clock::now();
    ForEachChunk(rays.size(), [&](std::size_t, std::size_t begin, std::size_t end) {
      RawClosestHits(inner_.scene(), rays, begin, end);
    });
    return Seconds(std::chrono::steady_clock::now() - t0);
  }

 private:
  struct Segment {
    Vec3 o, d;
    double length;
  };
  accel::EmbreeLocator inner_;
  bool recording_ = false;
  mutable tbb::enumerable_thread_specific<std::vector<Segment>> segments_;
};

// FNV-1a over every body's current vertex positions (determinism: DESIGN asks the step benchmark for a
// hash of the final state)
std::uint64_t FinalStateHash(const ContactEngine& engine) {
  std::uint64_t hash = kFnv1aBasis;
  for (int i = 0; i < engine.body_count(); ++i) {
    const std::vector<Vec3>& vertices = engine.state(i).vertices;
    hash = Fnv1a(vertices.data(), vertices.size() * sizeof(Vec3), hash);
  }
  return hash;
}

}  // namespace

StepTiming MeasureSteps(const ContactSetup& setup, int threads, int warmup, int steps, const ContactOptions& options) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  auto device = std::make_shared<const accel::EmbreeDevice>();
  std::vector<RecordingLocator*> recorders;
  const LocatorFactory factory = [&](const TriMesh& mesh) {
    auto locator = std::make_unique<RecordingLocator>(device, mesh);
    recorders.push_back(locator.get());
    return locator;
  };
  ContactEngine engine({setup.master, setup.slave}, {setup.master_pose, setup.slave_pose}, options, factory);
  // one collision step, then the slave closes by its speed (no dynamics: a steady pulse)
  RigidState slave = setup.slave_pose;
  auto step = [&] {
    engine.Step(kDt);
    slave.position += slave.velocity * kDt;
    engine.SetRigidState(1, slave);
  };
  for (int k = 0; k < warmup; ++k) step();
  StepTiming timing;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) step();
  timing.step_seconds = Seconds(std::chrono::steady_clock::now() - t0) / steps;
  // the same kind of step once more, recorded, and its segments cast raw
  for (RecordingLocator* r : recorders) r->SetRecording(true);
  step();
  for (RecordingLocator* r : recorders) timing.raycast_seconds += r->ReplayRaw(&timing.segments);
  timing.state_hash = FinalStateHash(engine);
  return timing;
}

}  // namespace dymesh::bench
