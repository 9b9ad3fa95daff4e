// The C ABI over the C++ engine: handles, argument checks, status codes and the thread-local last
// error. No exception leaves this file.
#include "dymesh/dymesh.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
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
#include "dymesh/core/simulation.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/io/summary_json.h"
#include "dymesh/report/output_files.h"

struct dm_world {
  std::unique_ptr<dymesh::Simulation> sim;
  std::string summary_text;  // the last summary handed out as a view
};

namespace {

using dymesh::RigidState;
using dymesh::Vec3;

thread_local std::string last_error;

std::mutex threads_mutex;
std::unique_ptr<tbb::global_control> thread_limit;

// a refused argument: the status and the message for dm_last_error
struct ArgumentError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

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

// ---- argument checks --------------------------------------------------------------------------

void Require(bool ok, const std::string& what) {
  if (!ok) throw ArgumentError(what);
}

template <typename T>
void NotNull(const T* p, const char* name) {
  Require(p != nullptr, std::string(name) + " is null");
}

const dymesh::Simulation& Sim(const dm_world* w) {
  NotNull(w, "world");
  return *w->sim;
}

void BodyIndex(const dm_world* w, int32_t body) {
  const int n = Sim(w).engine().body_count();
  Require(body >= 0 && body < n, "body " + std::to_string(body) + " is out of range 0.." + std::to_string(n - 1));
}

bool Finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

RigidState ToRigid(const dm_body_state& s, int body) {
  Require(Finite(s.position, 3) && Finite(s.velocity, 3) && Finite(s.omega, 3) &&
              std::isfinite(s.roll) && std::isfinite(s.pitch) && std::isfinite(s.yaw),
          "state of body " + std::to_string(body) + " is not finite");
  RigidState r;
  r.position = Vec3(s.position[0], s.position[1], s.position[2]);
  r.roll = s.roll, r.pitch = s.pitch, r.yaw = s.yaw;
  r.velocity = Vec3(s.velocity[0], s.velocity[1], s.velocity[2]);
  r.omega = Vec3(s.omega[0], s.omega[1], s.omega[2]);
  return r;
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
  for (int i = 0; i < n; ++i) out.push_back(ToRigid(states[i], i));
  return out;
}

dymesh::LocatorFactory Locators() {
  return dymesh::accel::MakeEmbreeLocatorFactory(std::make_shared<const dymesh::accel::EmbreeDevice>());
}

// ---- worlds from arrays -----------------------------------------------------------------------

// bytes of dm_body_desc before the fields appended since the first ABI (a caller built with that
// header passes this struct_size)
constexpr size_t kBodyDescFirstSize = offsetof(dm_body_desc, motion);

// body i of the caller's array, whose elements are struct_size bytes apart; fields the caller's
// header did not have read as 0 (their defaults), fields of a newer header are not read
dm_body_desc BodyDescAt(const dm_body_desc* bodies, int i) {
  size_t stride = 0;
  std::memcpy(&stride, bodies, sizeof stride);
  Require(stride >= kBodyDescFirstSize, "bodies[0].struct_size: expected sizeof(dm_body_desc)");
  const auto* element = reinterpret_cast<const unsigned char*>(bodies) + static_cast<size_t>(i) * stride;
  dm_body_desc d;
  std::memset(&d, 0, sizeof d);
  std::memcpy(&d, element, std::min(stride, sizeof d));
  const std::string at = "bodies[" + std::to_string(i) + "]";
  Require(d.struct_size == stride, at + ".struct_size: expected the same size as bodies[0]'s");
  return d;
}

// the motion model of a description (a fixed body takes only the default)
dymesh::MotionModel MotionFromDesc(const dm_body_desc& d, const std::string& at) {
  const bool fixed = d.fixed != 0;
  Require(d.motion >= DM_MOTION_DEFAULT && d.motion <= DM_MOTION_GRAVITY,
          at + ".motion: expected a dm_motion: DM_MOTION_DEFAULT, _PLANAR, _FREE or _GRAVITY (0-3), got " +
              std::to_string(d.motion));
  Require(!fixed || d.motion == DM_MOTION_DEFAULT, at + ".motion: a fixed body takes DM_MOTION_DEFAULT");
  switch (d.motion) {
    case DM_MOTION_FREE: return dymesh::MotionModel::kFree6Dof;
    case DM_MOTION_GRAVITY: return dymesh::MotionModel::kGravityGround;
    case DM_MOTION_PLANAR: return dymesh::MotionModel::kPlanar;
    default: return fixed ? dymesh::MotionModel::kFixed : dymesh::MotionModel::kPlanar;
  }
}

// one body's model and scenario entry from its description
std::shared_ptr<const dymesh::BodyModel> BodyFromDesc(const dm_body_desc& d, int i, dymesh::BodySpec* spec) {
  const std::string at = "bodies[" + std::to_string(i) + "]";
  Require(d.name != nullptr && d.name[0] != '\0', at + ".name: expected a non-empty name");
  NotNull(d.vertices, (at + ".vertices").c_str());
  NotNull(d.triangles, (at + ".triangles").c_str());
  Require(d.vertex_count >= 3 && d.triangle_count >= 1, at + ": expected at least 3 vertices and 1 triangle");
  Require(Finite(d.vertices, 3 * d.vertex_count), at + ".vertices: not finite");
  dymesh::TriMesh mesh;
  for (int v = 0; v < d.vertex_count; ++v)
    mesh.vertices.emplace_back(d.vertices[3 * v], d.vertices[3 * v + 1], d.vertices[3 * v + 2]);
  for (int t = 0; t < d.triangle_count; ++t) {
    std::array<int, 3> tri{d.triangles[3 * t], d.triangles[3 * t + 1], d.triangles[3 * t + 2]};
    for (int k : tri) Require(k >= 0 && k < d.vertex_count, at + ".triangles: vertex index out of range");
    mesh.triangles.push_back(tri);
  }
  const bool fixed = d.fixed != 0, rigid = d.rigid != 0;
  Require(fixed || (std::isfinite(d.mass) && d.mass > 0.0), at + ".mass: expected a finite mass > 0");
  Require(fixed || (Finite(d.inertia, 3) && d.inertia[0] > 0 && d.inertia[1] > 0 && d.inertia[2] > 0),
          at + ".inertia: expected three finite values > 0");
  Require(std::isfinite(d.stiffness_a) && std::isfinite(d.stiffness_b) && d.stiffness_a >= 0 && d.stiffness_b >= 0,
          at + ".stiffness: expected finite A, B >= 0");
  Require(rigid || d.stiffness_a > 0 || d.stiffness_b > 0, at + ".stiffness: a deformable body needs A > 0 or B > 0");
  Require(d.restitution >= 0 && d.restitution <= 1, at + ".restitution: expected a value in [0, 1]");
  Require(std::isfinite(d.friction) && d.friction >= 0, at + ".friction: expected a finite value >= 0");
  // the scenario entry and the model
  std::array<dymesh::Stiffness, dymesh::kBodySurfaceCount> k;
  dymesh::Stiffness s;
  s.A = d.stiffness_a, s.B = d.stiffness_b;
  k.fill(s);
  spec->name = d.name;
  spec->mass = fixed ? 0.0 : d.mass;
  spec->rigid = rigid;
  spec->motion = MotionFromDesc(d, at);
  spec->restitution = d.restitution, spec->friction = d.friction;
  spec->stiffness = k;
  spec->initial = ToRigid(d.initial, i);
  const dymesh::Mat3 inertia = fixed ? dymesh::Mat3::Identity() : dymesh::Vec3(d.inertia[0], d.inertia[1], d.inertia[2]).asDiagonal().toDenseMatrix();
  return std::make_shared<const dymesh::BodyModel>(
      dymesh::MakeBodyModel(d.name, std::move(mesh), k, spec->mass, inertia, d.restitution, d.friction, rigid));
}

// the scenario part of a world description
dymesh::Scenario ScenarioFromDesc(const dm_world_desc& d) {
  Require(d.struct_size >= sizeof(dm_world_desc), "world.struct_size: expected sizeof(dm_world_desc)");
  Require(std::isfinite(d.time_step) && d.time_step > 0, "world.time_step: expected a finite step > 0");
  Require(std::isfinite(d.duration) && d.duration >= d.time_step, "world.duration: expected a duration >= the step");
  Require(d.passes_per_step >= 0 && d.passes_per_step <= 1000, "world.passes_per_step: expected 0..1000");
  dymesh::Scenario s;
  s.file = "(dm_world_create)";
  s.units = dymesh::UnitSystem::kSI;
  s.time_step = d.time_step;
  s.duration = d.duration;
  s.stop_at_separation = d.stop_at_separation != 0;
  if (d.passes_per_step > 0) s.contact.passes_per_step = d.passes_per_step;
  return s;
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
    Require(body_count >= 2, "body_count: expected at least 2 bodies, got " + std::to_string(body_count));
    dymesh::Scenario scenario = ScenarioFromDesc(*desc);
    std::vector<std::shared_ptr<const dymesh::BodyModel>> models;
    scenario.bodies.resize(body_count);
    bool any_deformable = false;
    for (int i = 0; i < body_count; ++i) {
      models.push_back(BodyFromDesc(BodyDescAt(bodies, i), i, &scenario.bodies[i]));
      any_deformable = any_deformable || !scenario.bodies[i].rigid;
    }
    Require(any_deformable, "bodies: every body is rigid: at least one must be deformable");
    auto world = std::make_unique<dm_world>();
    world->sim = std::make_unique<dymesh::Simulation>(scenario, std::move(models), Locators());
    *out = world.release();
  });
}

dm_status dm_world_run(dm_world* w) {
  return Guarded("dm_world_run", [&] {
    NotNull(w, "world");
    w->sim->Run();
  });
}

dm_status dm_world_step(dm_world* w, int32_t* finished) {
  return Guarded("dm_world_step", [&] {
    NotNull(w, "world");
    NotNull(finished, "finished");
    if (!w->sim->finished()) w->sim->Advance();
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
    NotNull(out_seconds, "out_seconds");
    *out_seconds = Sim(w).time();
  });
}

dm_status dm_world_run_status(const dm_world* w, dm_run_status* out) {
  return Guarded("dm_world_run_status", [&] {
    NotNull(out, "out");
    *out = static_cast<dm_run_status>(dymesh::Summarize(Sim(w)).status);
  });
}

dm_status dm_body_name(const dm_world* w, int32_t body, const char** out) {
  return Guarded("dm_body_name", [&] {
    BodyIndex(w, body);
    NotNull(out, "out");
    *out = Sim(w).engine().model(body).name.c_str();
  });
}

dm_status dm_body_state_get(const dm_world* w, int32_t body, dm_body_state* out) {
  return Guarded("dm_body_state_get", [&] {
    BodyIndex(w, body);
    NotNull(out, "out");
    *out = FromRigid(Sim(w).engine().state(body).rigid);
  });
}

dm_status dm_body_delta_v(const dm_world* w, int32_t body, double out_xyz[3]) {
  return Guarded("dm_body_delta_v", [&] {
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
    NotNull(w, "world");
    NotNull(out_text, "out_text");
    const dymesh::Simulation& sim = *w->sim;
    w->summary_text = dymesh::SummaryJson(dymesh::Summarize(sim), sim.scenario(), dymesh::OutputFileNames(sim.scenario()));
    *out_text = w->summary_text.c_str();
  });
}

dm_status dm_world_copy_summary_json(dm_world* w, char* buffer, size_t size, size_t* needed) {
  const char* text = nullptr;
  if (const dm_status s = dm_world_summary_json(w, &text); s != DM_OK) return s;
  return Guarded("dm_world_copy_summary_json", [&] {
    NotNull(needed, "needed");
    *needed = std::strlen(text) + 1;
    Require(size >= *needed, "buffer of " + std::to_string(size) + " bytes is below the " + std::to_string(*needed) +
                                 " the summary needs");
    NotNull(buffer, "buffer");
    std::memcpy(buffer, text, *needed);
  });
}

dm_status dm_world_write_outputs(dm_world* w, const char* dir) {
  const dm_status s = Guarded("dm_world_write_outputs", [&] {
    NotNull(w, "world");
    NotNull(dir, "dir");
    const dymesh::Simulation& sim = *w->sim;
    dymesh::OutputFolder folder(dir, dymesh::OutputFileNames(sim.scenario()), dymesh::InputFiles(sim.scenario()));
    folder.ReplacePreviousRun();
    dymesh::WriteOutputs(sim, dymesh::Summarize(sim), dir);
  });
  // a write that failed is an I/O failure, not an internal one
  return s == DM_ERROR_INTERNAL ? DM_ERROR_IO : s;
}

dm_status dm_world_state_hash(const dm_world* w, uint64_t* out) {
  return Guarded("dm_world_state_hash", [&] {
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
    NotNull(w, "world");
    NotNull(out_loads, "out_loads");
    Require(std::isfinite(dt) && dt > 0.0, "dt: expected a finite step > 0");
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
    NotNull(w, "world");
    w->sim->FinishHostRun(States(w, states, count));
  });
}

}  // extern "C"
