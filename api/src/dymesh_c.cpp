// The C ABI over the C++ engine: handles, argument checks, status codes and the thread-local last
// error. No exception leaves this file.
#include "dymesh/dymesh.h"

#include <tbb/global_control.h>

#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/byte_hash.h"
#include "dymesh/core/physical_ranges.h"
#include "dymesh/core/simulation.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/io/summary_json.h"
#include "dymesh/report/output_files.h"
#include "argument_checks.h"
#include "world_from_arrays.h"

struct dm_world {
  std::unique_ptr<dymesh::Simulation> sim;
  // views stay valid until the world changes: the summary handed out is made again only once the
  // run has stepped or finished since (under summary_mutex: calls that read may overlap)
  std::string summary_text;
  int summary_steps = -1;
  bool summary_finished = false;
  mutable std::mutex summary_mutex;
  // the calls in progress on this world (WorldAccess): -1 while one changes it, else how many read it
  mutable std::atomic<int> users{0};
};

namespace {

using dymesh::RigidState;
using dymesh::Vec3;
using dymesh::api::NotNull;
using dymesh::api::Require;
using dymesh::api::ToRigid;

thread_local std::string last_error;

std::mutex threads_mutex;
std::unique_ptr<tbb::global_control> thread_limit;

dm_status Fail(dm_status status, const std::string& message) {
  last_error = message;
  return status;
}

// runs `body`, turning every exception into a status and a message
template <typename F>
dm_status Guarded(const char* function, F&& body) {
  try {
    last_error.clear();
    body();
    return DM_OK;
  } catch (const dymesh::InputError& e) {
    return Fail(DM_ERROR_INPUT, std::string(function) + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    return Fail(DM_ERROR_ARGUMENT, std::string(function) + ": " + e.what());
  } catch (const std::logic_error& e) {
    return Fail(DM_ERROR_STATE, std::string(function) + ": " + e.what());
  } catch (const dymesh::OutputFolderBusy& e) {
    return Fail(DM_ERROR_IO, std::string(function) + ": " + e.what());
  } catch (const std::bad_alloc&) {
    return Fail(DM_ERROR_INTERNAL, std::string(function) + ": out of memory");
  } catch (const std::exception& e) {
    return Fail(DM_ERROR_INTERNAL, std::string(function) + ": " + e.what());
  } catch (...) {
    return Fail(DM_ERROR_INTERNAL, std::string(function) + ": unknown failure");
  }
}

// ---- one call at a time ---------------------------------------------------------------------------

// a call refused because another thread's call on the same world is in progress (DM_ERROR_STATE)
struct WorldBusy : std::logic_error {
  WorldBusy()
      : std::logic_error("another call on this world is in progress (in another thread): a world takes a call that "
                         "steps or changes it only while no other call on it runs, and no call while one does "
                         "(dymesh.h, \"Threads\")") {}
};

// the access a call has to its world for as long as it runs: a call that changes the world (steps,
// host steps, ends the run, writes its outputs) alone, calls that only read it beside each other.
// One that cannot have it at once is refused, never made to wait (a sweep, 2026-11-28: a step
// beside a run corrupted the heap)
class WorldAccess {
 public:
  enum Kind { kRead, kChange };
  WorldAccess(const dm_world* w, Kind kind) : users_(UsersOf(w)), kind_(kind) {
    int now = users_.load(std::memory_order_relaxed);
    do {
      if (now < 0 || (kind == kChange && now > 0)) throw WorldBusy();
    } while (!users_.compare_exchange_weak(now, kind == kChange ? -1 : now + 1, std::memory_order_acquire,
                                           std::memory_order_relaxed));
  }
  ~WorldAccess() {
    if (kind_ == kChange)
      users_.store(0, std::memory_order_release);
    else
      users_.fetch_sub(1, std::memory_order_release);
  }
  WorldAccess(const WorldAccess&) = delete;
  WorldAccess& operator=(const WorldAccess&) = delete;

 private:
  static std::atomic<int>& UsersOf(const dm_world* w) {
    NotNull(w, "world");
    return w->users;
  }
  std::atomic<int>& users_;
  Kind kind_;
};

// ---- argument checks --------------------------------------------------------------------------

const dymesh::Simulation& Sim(const dm_world* w) {
  NotNull(w, "world");
  return *w->sim;
}

void BodyIndex(const dm_world* w, int32_t body) {
  const int n = Sim(w).engine().body_count();
  Require(body >= 0 && body < n, "body " + std::to_string(body) + " is out of range 0.." + std::to_string(n - 1));
}

dm_body_state FromRigid(const RigidState& r) {
  dm_body_state s{};
  for (int k = 0; k < 3; ++k) {
    s.position[k] = r.position[k];
    s.velocity[k] = r.velocity[k];
    s.omega[k] = r.omega[k];
  }
  s.roll = r.roll, s.pitch = r.pitch, s.yaw = r.yaw;
  return s;
}

std::vector<RigidState> States(const dm_world* w, const dm_body_state* states, int32_t count) {
  NotNull(states, "states");
  const int n = Sim(w).engine().body_count();
  Require(count == n, "expected " + std::to_string(n) + " body states, got " + std::to_string(count));
  std::vector<RigidState> out;
  for (int i = 0; i < n; ++i) out.push_back(ToRigid(states[i], "states[" + std::to_string(i) + "]"));
  return out;
}

// the summary text of the world as it is now, made again only when the run has stepped or finished
// since it was last made (the view handed out stays valid until then)
const std::string& SummaryText(dm_world* w) {
  const dymesh::Simulation& sim = *w->sim;
  std::lock_guard<std::mutex> lock(w->summary_mutex);
  if (w->summary_steps != sim.steps() || w->summary_finished != sim.finished()) {
    w->summary_text = dymesh::SummaryJson(dymesh::Summarize(sim), sim.scenario(), dymesh::OutputFileNames(sim.scenario()));
    w->summary_steps = sim.steps();
    w->summary_finished = sim.finished();
  }
  return w->summary_text;
}

dymesh::LocatorFactory Locators() {
  return dymesh::accel::MakeEmbreeLocatorFactory(std::make_shared<const dymesh::accel::EmbreeDevice>());
}

}  // namespace

extern "C" {

uint32_t dm_abi_version(void) { return DM_ABI_VERSION; }

const char* dm_last_error(void) { return last_error.c_str(); }

dm_status dm_set_threads(int32_t threads) {
  return Guarded("dm_set_threads", [&] {
    Require(threads >= 0 && threads <= 4096, "threads: expected 0 (all cores) .. 4096");
    std::lock_guard<std::mutex> lock(threads_mutex);
    thread_limit.reset();
    if (threads > 0)
      thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  });
}

dm_status dm_world_load_scenario(const char* path, dm_world** out) {
  return Guarded("dm_world_load_scenario", [&] {
    NotNull(path, "path");
    NotNull(out, "out");
    *out = nullptr;
    const dymesh::Scenario scenario = dymesh::LoadScenario(path);
    auto world = std::make_unique<dm_world>();
    world->sim = std::make_unique<dymesh::Simulation>(scenario, dymesh::BuildBodyModels(scenario), Locators());
    *out = world.release();
  });
}

dm_status dm_world_create(const dm_world_desc* desc, const dm_body_desc* bodies, int32_t body_count, dm_world** out) {
  return Guarded("dm_world_create", [&] {
    NotNull(desc, "world");
    NotNull(bodies, "bodies");
    NotNull(out, "out");
    *out = nullptr;
    dymesh::api::ArrayWorld built = dymesh::api::WorldFromArrays(desc, bodies, body_count);
    auto world = std::make_unique<dm_world>();
    world->sim = std::make_unique<dymesh::Simulation>(built.scenario, std::move(built.models), Locators());
    *out = world.release();
  });
}

dm_status dm_world_run(dm_world* w) {
  return Guarded("dm_world_run", [&] {
    const WorldAccess access(w, WorldAccess::kChange);
    w->sim->Run();
  });
}

dm_status dm_world_step(dm_world* w, int32_t* finished) {
  return Guarded("dm_world_step", [&] {
    const WorldAccess access(w, WorldAccess::kChange);
    NotNull(finished, "finished");
    *finished = w->sim->finished() ? 1 : 0;
    w->sim->Advance();
    *finished = w->sim->finished() ? 1 : 0;
  });
}

int32_t dm_world_body_count(const dm_world* w) {
  if (w == nullptr) {
    last_error = "dm_world_body_count: world is null";
    return -1;
  }
  return w->sim->engine().body_count();
}

dm_status dm_world_time(const dm_world* w, double* out_seconds) {
  return Guarded("dm_world_time", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    NotNull(out_seconds, "out_seconds");
    *out_seconds = Sim(w).time();
  });
}

dm_status dm_world_run_status(const dm_world* w, dm_run_status* out) {
  return Guarded("dm_world_run_status", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    NotNull(out, "out");
    *out = static_cast<dm_run_status>(dymesh::Summarize(Sim(w)).status);
  });
}

dm_status dm_body_name(const dm_world* w, int32_t body, const char** out) {
  return Guarded("dm_body_name", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    BodyIndex(w, body);
    NotNull(out, "out");
    *out = Sim(w).engine().model(body).name.c_str();
  });
}

dm_status dm_body_state_get(const dm_world* w, int32_t body, dm_body_state* out) {
  return Guarded("dm_body_state_get", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    BodyIndex(w, body);
    NotNull(out, "out");
    *out = FromRigid(Sim(w).engine().state(body).rigid);
  });
}

dm_status dm_body_delta_v(const dm_world* w, int32_t body, double out_xyz[3]) {
  return Guarded("dm_body_delta_v", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    BodyIndex(w, body);
    NotNull(out_xyz, "out_xyz");
    const dymesh::Simulation& sim = Sim(w);
    const Vec3 dv = sim.engine().state(body).rigid.velocity - sim.history().front().bodies[body].rigid.velocity;
    const double speed = dymesh::UnitsOf(sim.scenario().units).speed;
    for (int k = 0; k < 3; ++k) out_xyz[k] = dv[k] * speed;
  });
}

dm_status dm_body_vertices(const dm_world* w, int32_t body, const double** out_xyz, int32_t* out_count) {
  return Guarded("dm_body_vertices", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    BodyIndex(w, body);
    NotNull(out_xyz, "out_xyz");
    NotNull(out_count, "out_count");
    const std::vector<Vec3>& v = Sim(w).engine().state(body).vertices;
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
    *out_xyz = v.empty() ? nullptr : v.front().data();
    *out_count = static_cast<int32_t>(v.size());
  });
}

dm_status dm_body_copy_vertices(const dm_world* w, int32_t body, double* xyz, int32_t capacity, int32_t* out_count) {
  return Guarded("dm_body_copy_vertices", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    BodyIndex(w, body);
    NotNull(out_count, "out_count");
    const std::vector<Vec3>& v = Sim(w).engine().state(body).vertices;
    *out_count = static_cast<int32_t>(v.size());
    Require(capacity >= *out_count, "capacity " + std::to_string(capacity) + " is below the vertex count " +
                                        std::to_string(*out_count));
    NotNull(xyz, "xyz");
    std::memcpy(xyz, v.front().data(), v.size() * sizeof(Vec3));
  });
}

dm_status dm_body_deformation(const dm_world* w, int32_t body, const double** out_xyz, int32_t* out_count) {
  return Guarded("dm_body_deformation", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    BodyIndex(w, body);
    NotNull(out_xyz, "out_xyz");
    NotNull(out_count, "out_count");
    const std::vector<Vec3>& d = Sim(w).engine().state(body).delta;
    *out_xyz = d.empty() ? nullptr : d.front().data();
    *out_count = static_cast<int32_t>(d.size());
  });
}

dm_status dm_body_copy_crush(const dm_world* w, int32_t body, double* crush, int32_t capacity, int32_t* out_count) {
  return Guarded("dm_body_copy_crush", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    BodyIndex(w, body);
    NotNull(out_count, "out_count");
    const std::vector<double> c = dymesh::VertexCrush(Sim(w), body);
    *out_count = static_cast<int32_t>(c.size());
    Require(capacity >= *out_count, "capacity " + std::to_string(capacity) + " is below the vertex count " +
                                        std::to_string(*out_count));
    NotNull(crush, "crush");
    std::memcpy(crush, c.data(), c.size() * sizeof(double));
  });
}

dm_status dm_world_summary_json(dm_world* w, const char** out_text) {
  return Guarded("dm_world_summary_json", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    NotNull(out_text, "out_text");
    *out_text = SummaryText(w).c_str();
  });
}

dm_status dm_world_copy_summary_json(dm_world* w, char* buffer, size_t size, size_t* needed) {
  return Guarded("dm_world_copy_summary_json", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    NotNull(needed, "needed");
    const std::string& text = SummaryText(w);
    *needed = text.size() + 1;
    Require(size >= *needed, "buffer of " + std::to_string(size) + " bytes is below the " + std::to_string(*needed) +
                                 " the summary needs");
    NotNull(buffer, "buffer");
    std::memcpy(buffer, text.c_str(), *needed);
  });
}

dm_status dm_world_write_outputs(dm_world* w, const char* dir) {
  bool summary_made = false, folder_taken = false;
  const dm_status s = Guarded("dm_world_write_outputs", [&] {
    const WorldAccess access(w, WorldAccess::kChange);
    NotNull(dir, "dir");
    Require(*dir != '\0', "dir: expected a folder name, got \"\"");
    const dymesh::Simulation& sim = *w->sim;
    // the summary and its text before the folder is touched: a run they cannot describe writes nothing
    // (WriteOutputs makes the text last, after the meshes)
    const dymesh::Summary summary = dymesh::Summarize(sim);
    dymesh::SummaryJson(summary, sim.scenario(), dymesh::OutputFileNames(sim.scenario()));
    summary_made = true;
    dymesh::OutputFolder folder(dir, dymesh::OutputFileNames(sim.scenario()), dymesh::InputFiles(sim.scenario()), "dir");
    folder_taken = true;
    folder.ReplacePreviousRun();
    dymesh::WriteOutputs(sim, summary, dir);
  });
  // a folder that cannot take the outputs, or a write that failed, is an I/O failure
  return (s == DM_ERROR_INTERNAL && summary_made) || (s == DM_ERROR_INPUT && summary_made && !folder_taken) ? DM_ERROR_IO : s;
}

dm_status dm_world_state_hash(const dm_world* w, uint64_t* out) {
  return Guarded("dm_world_state_hash", [&] {
    const WorldAccess access(w, WorldAccess::kRead);
    NotNull(out, "out");
    const dymesh::ContactEngine& engine = Sim(w).engine();
    std::uint64_t h = dymesh::kFnv1aBasis;
    for (int i = 0; i < engine.body_count(); ++i) {
      const dymesh::BodyState& s = engine.state(i);
      const dm_body_state r = FromRigid(s.rigid);
      h = dymesh::Fnv1a(&r, sizeof r, h);
      h = dymesh::Fnv1a(s.vertices.data(), s.vertices.size() * sizeof(Vec3), h);
    }
    *out = h;
  });
}

void dm_world_destroy(dm_world* w) { delete w; }

dm_status dm_world_host_step(dm_world* w, const dm_body_state* states, int32_t count, double dt, dm_loads* out_loads) {
  return Guarded("dm_world_host_step", [&] {
    const WorldAccess access(w, WorldAccess::kChange);
    NotNull(out_loads, "out_loads");
    Require(dt > 0.0 && dt <= dymesh::kDurationRange.hard_hi, "dt: expected a step > 0 and at most 1e4 s");
    const dymesh::StepResult step = w->sim->HostStep(States(w, states, count), dt);
    for (int i = 0; i < count; ++i)
      for (int k = 0; k < 3; ++k) {
        out_loads[i].force_body[k] = step.loads[i].force_body[k];
        out_loads[i].moment_body[k] = step.loads[i].moment_body[k];
        out_loads[i].force_earth[k] = step.loads[i].force_earth[k];
      }
  });
}

dm_status dm_world_host_finish(dm_world* w, const dm_body_state* states, int32_t count) {
  return Guarded("dm_world_host_finish", [&] {
    const WorldAccess access(w, WorldAccess::kChange);
    // a host-driven run is one host step or more: ended before its first, it read "complete" with
    // 0 steps (a sweep, 2026-11-28)
    if (!w->sim->finished() && w->sim->steps() == 0)
      throw std::logic_error("no host step taken: a host-driven run ends after its first dm_world_host_step");
    w->sim->FinishHostRun(States(w, states, count));
  });
}

}  // extern "C"
