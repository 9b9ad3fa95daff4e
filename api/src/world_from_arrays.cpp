#include "world_from_arrays.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>

#include "argument_checks.h"
#include "dymesh/core/physical_ranges.h"
#include "dymesh/core/units.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/printable.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh::api {
namespace {

// the sizes each definition struct was published with, this header's first: a caller passes the
// size of the header it was built with. Any other size is a mistake: past sizeof it would hold
// fields this library does not read, partway through a field it would be half read (a sweep,
// 2026-11-28). The first ABI's structs (2026-11-23) end where the appended fields begin: dm_body_desc
// before `motion` (appended 2026-11-24), dm_world_desc before `search_direction` (2026-11-28)
constexpr size_t kBodyDescSizes[] = {sizeof(dm_body_desc), offsetof(dm_body_desc, motion)};
constexpr size_t kWorldDescSizes[] = {sizeof(dm_world_desc), offsetof(dm_world_desc, search_direction)};
static_assert(offsetof(dm_body_desc, motion) == offsetof(dm_body_desc, initial) + sizeof(dm_body_state),
              "the first dm_body_desc ended with `initial`, no padding after it");
static_assert(offsetof(dm_world_desc, search_direction) == offsetof(dm_world_desc, passes_per_step) + sizeof(int32_t) &&
                  offsetof(dm_world_desc, search_direction) % alignof(dm_world_desc) == 0,
              "the first dm_world_desc ended with `passes_per_step`, no padding after it");

// the published sizes of a struct, for messages: "224 (this header) or 216 (the first ABI, before motion)"
std::string PublishedSizes(const size_t (&sizes)[2], const char* appended) {
  return std::to_string(sizes[0]) + " (this header) or " + std::to_string(sizes[1]) + " (the first ABI, before " +
         appended + ")";
}

// a struct_size refused unless it is one of the published sizes
void RequirePublishedSize(size_t size, const size_t (&sizes)[2], const std::string& field, const char* appended) {
  Require(size == sizes[0] || size == sizes[1],
          field + ": expected " + PublishedSizes(sizes, appended) + ", got " + std::to_string(size));
}

// a value refused outside its physical range and warned outside the plausible one (io's
// CheckPhysical, in SI)
void CheckRange(const std::string& field, double value, const PhysicalRange& r, const char* unit,
                std::vector<RunWarning>* warnings) {
  auto text = [&](double v) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.4g", v);
    return std::string(digits) + unit;
  };
  Require(value >= r.hard_lo && value <= r.hard_hi, field + ": expected a physically possible " + r.what + " in " +
                                                        text(r.hard_lo) + " .. " + text(r.hard_hi) + ", got " + text(value));
  if (value < r.lo || value > r.hi)
    warnings->push_back({"implausible_value", field,
                         std::string(r.what) + " " + text(value) + " is outside the range met in vehicle collisions, " +
                             text(r.lo) + " .. " + text(r.hi) + ": check the value and its unit"});
}

// body i of the caller's array, whose elements are bodies[0].struct_size bytes apart (a published
// size); fields the caller's header did not have read as 0 (their defaults)
dm_body_desc BodyDescAt(const dm_body_desc* bodies, int i) {
  size_t stride = 0;
  std::memcpy(&stride, bodies, sizeof stride);
  RequirePublishedSize(stride, kBodyDescSizes, "bodies[0].struct_size", "motion");
  const auto* element = reinterpret_cast<const unsigned char*>(bodies) + static_cast<size_t>(i) * stride;
  dm_body_desc d;
  std::memset(&d, 0, sizeof d);
  std::memcpy(&d, element, std::min(stride, sizeof d));
  const std::string at = "bodies[" + std::to_string(i) + "]";
  Require(d.struct_size == stride, at + ".struct_size: expected bodies[0]'s " + std::to_string(stride) +
                                       " (the array's elements are that far apart), got " + std::to_string(d.struct_size));
  return d;
}

// the motion model of a description (a fixed body takes only the default)
MotionModel MotionFromDesc(const dm_body_desc& d, const std::string& at) {
  const bool fixed = d.fixed != 0;
  Require(d.motion >= DM_MOTION_DEFAULT && d.motion <= DM_MOTION_GRAVITY,
          at + ".motion: expected a dm_motion: DM_MOTION_DEFAULT, _PLANAR, _FREE or _GRAVITY (0-3), got " +
              std::to_string(d.motion));
  Require(!fixed || d.motion == DM_MOTION_DEFAULT, at + ".motion: a fixed body takes DM_MOTION_DEFAULT");
  switch (d.motion) {
    case DM_MOTION_FREE: return MotionModel::kFree6Dof;
    case DM_MOTION_GRAVITY: return MotionModel::kGravityGround;
    case DM_MOTION_PLANAR: return MotionModel::kPlanar;
    default: return fixed ? MotionModel::kFixed : MotionModel::kPlanar;
  }
}

// the mesh of a description, its indices in range and its size possible (its CG within reach)
TriMesh MeshFromDesc(const dm_body_desc& d, const std::string& at, std::vector<RunWarning>* warnings) {
  NotNull(d.vertices, at + ".vertices");
  NotNull(d.triangles, at + ".triangles");
  Require(d.vertex_count >= 3 && d.triangle_count >= 1, at + ": expected at least 3 vertices and 1 triangle");
  for (size_t k = 0; k < 3 * static_cast<size_t>(d.vertex_count); ++k)
    RequireFinite(d.vertices[k], at + ".vertices[" + std::to_string(k) + "]");
  TriMesh mesh;
  for (size_t v = 0; v < static_cast<size_t>(d.vertex_count); ++v)
    mesh.vertices.emplace_back(d.vertices[3 * v], d.vertices[3 * v + 1], d.vertices[3 * v + 2]);
  for (size_t t = 0; t < static_cast<size_t>(d.triangle_count); ++t) {
    std::array<int, 3> tri{d.triangles[3 * t], d.triangles[3 * t + 1], d.triangles[3 * t + 2]};
    for (int k : tri) Require(k >= 0 && k < d.vertex_count, at + ".triangles: vertex index out of range");
    mesh.triangles.push_back(tri);
  }
  // every face outward, as a mesh file's (a face wound against its neighbours, or the whole mesh wound
  // in, read its inside as the outside); the vertices keep their indices
  OrientOutward(&mesh);
  // as a mesh file's built body (CheckRunStart) and a scenario's CG about its mesh
  const MeshStats stats = ComputeStats(mesh);
  CheckRange(at + ".vertices", (stats.max - stats.min).maxCoeff(), kBodySizeRange, " m (largest extent)", warnings);
  // a moving body turns about its CG (a fixed one's origin is only where its vertices are measured from)
  const Vec3 centre = 0.5 * (stats.min + stats.max);
  for (int k = 0; d.fixed == 0 && k < 3; ++k)
    CheckRange(at + ".vertices", -centre[k], kCgRange, " m (the CG from the bounds centre)", warnings);
  return mesh;
}

// the pose and velocities of a description, in the ranges a scenario's "initial" has
void CheckInitial(const dm_body_desc& d, MotionModel motion, const std::string& at, std::vector<RunWarning>* warnings) {
  const dm_body_state& s = d.initial;
  for (int k = 0; k < 3; ++k)
    CheckRange(at + ".initial.position[" + std::to_string(k) + "]", s.position[k], kPositionRange, " m", warnings);
  CheckRange(at + ".initial.yaw", s.yaw / units::kDegree, kHeadingRange, "", warnings);
  CheckRange(at + ".initial.roll", s.roll / units::kDegree, kTiltRange, "", warnings);
  CheckRange(at + ".initial.pitch", s.pitch / units::kDegree, kTiltRange, "", warnings);
  CheckRange(at + ".initial.velocity", std::hypot(s.velocity[0], s.velocity[1], s.velocity[2]), kSpeedRange, " m/s", warnings);
  // the angular rate: each component named (refused past the bound alone), then its size (refused
  // and warned as a scenario's yaw rate)
  const char* rates[] = {"roll rate p [deg/s]", "pitch rate q [deg/s]", "yaw rate r [deg/s]"};
  for (int k = 0; k < 3; ++k) {
    const PhysicalRange bound{kYawRateRange.hard_lo, kYawRateRange.hard_hi, kYawRateRange.hard_lo, kYawRateRange.hard_hi, rates[k]};
    CheckRange(at + ".initial.omega[" + std::to_string(k) + "]", s.omega[k] / units::kDegree, bound, "", warnings);
  }
  PhysicalRange rate = kYawRateRange;
  rate.what = "angular rate |omega| [deg/s]";
  CheckRange(at + ".initial.omega", std::hypot(s.omega[0], s.omega[1], s.omega[2]) / units::kDegree, rate, "", warnings);
  // a planar body holds its height: a vertical velocity would be dropped (delta-V and the energy
  // balance read wrong)
  Require(motion != MotionModel::kPlanar || s.velocity[2] == 0.0,
          at + ".initial.velocity[2]: a planar body holds its height: expected 0, got " + Number(s.velocity[2]) +
              " m/s (give DM_MOTION_FREE or DM_MOTION_GRAVITY for vertical motion)");
}

// one body's scenario entry and model from its description
std::shared_ptr<const BodyModel> BodyFromDesc(const dm_body_desc& d, int i, BodySpec* spec,
                                              std::vector<RunWarning>* warnings) {
  const std::string at = "bodies[" + std::to_string(i) + "]";
  Require(d.name != nullptr && d.name[0] != '\0', at + ".name: expected a non-empty name");
  // the summary and the report are UTF-8: a name that is not was taken, and failed only there
  Require(IsUtf8(d.name), at + ".name: expected UTF-8 text, got \"" + HexEscaped(d.name) + "\"");
  Require(UsableInFileNames(d.name), at + ".name: expected " + kFileNameRule + ", got \"" + Printable(d.name) + "\"");
  TriMesh mesh = MeshFromDesc(d, at, warnings);
  const bool fixed = d.fixed != 0, rigid = d.rigid != 0;
  // finite even where unused (a fixed body's mass and inertia): a NaN is a mistake wherever it is
  RequireFinite(d.mass, at + ".mass");
  for (int k = 0; k < 3; ++k) RequireFinite(d.inertia[k], at + ".inertia[" + std::to_string(k) + "]");
  Require(fixed || (std::isfinite(d.mass) && d.mass > 0.0), at + ".mass: expected a finite mass > 0");
  Require(fixed || (Finite(d.inertia, 3) && d.inertia[0] > 0 && d.inertia[1] > 0 && d.inertia[2] > 0),
          at + ".inertia: expected three finite values > 0");
  if (!fixed) {
    CheckRange(at + ".mass", d.mass, kMassRange, " kg", warnings);
    for (int k = 0; k < 3; ++k)
      CheckRange(at + ".inertia[" + std::to_string(k) + "]", std::sqrt(d.inertia[k] / d.mass), kGyrationRange, " m",
                 warnings);
  }
  Require(std::isfinite(d.stiffness_a) && std::isfinite(d.stiffness_b) && d.stiffness_a >= 0 && d.stiffness_b >= 0,
          at + ".stiffness: expected finite A, B >= 0");
  Require(rigid || d.stiffness_a > 0 || d.stiffness_b > 0, at + ".stiffness: a deformable body needs A > 0 or B > 0");
  if (!rigid) {
    CheckRange(at + ".stiffness_a", d.stiffness_a, kStiffnessARange, "", warnings);
    CheckRange(at + ".stiffness_b", d.stiffness_b, kStiffnessBRange, "", warnings);
    RefuseFlatMesh(mesh, "(dm_world_create)", at + ".vertices");
  }
  Require(d.restitution >= 0 && d.restitution <= 1, at + ".restitution: expected a value in [0, 1]");
  Require(std::isfinite(d.friction) && d.friction >= 0, at + ".friction: expected a finite value >= 0");
  CheckRange(at + ".friction", d.friction, kFrictionRange, "", warnings);
  // the scenario entry and the model
  std::array<Stiffness, kBodySurfaceCount> k;
  Stiffness s;
  s.A = d.stiffness_a, s.B = d.stiffness_b;
  k.fill(s);
  spec->name = d.name;
  spec->mass = fixed ? 0.0 : d.mass;
  spec->rigid = rigid;
  spec->motion = MotionFromDesc(d, at);
  spec->restitution = d.restitution, spec->friction = d.friction;
  spec->stiffness = k;
  spec->initial = ToRigid(d.initial, at + ".initial");
  CheckInitial(d, spec->motion, at, warnings);
  const Mat3 inertia = fixed ? Mat3::Identity() : Vec3(d.inertia[0], d.inertia[1], d.inertia[2]).asDiagonal().toDenseMatrix();
  return std::make_shared<const BodyModel>(
      MakeBodyModel(d.name, std::move(mesh), k, spec->mass, inertia, d.restitution, d.friction, rigid));
}

// the caller's world description (a published size): fields its header did not have read as 0
// (their defaults)
dm_world_desc WorldDescFrom(const dm_world_desc* world) {
  size_t size = 0;
  std::memcpy(&size, world, sizeof size);
  RequirePublishedSize(size, kWorldDescSizes, "world.struct_size", "search_direction");
  dm_world_desc d;
  std::memset(&d, 0, sizeof d);
  std::memcpy(&d, world, std::min(size, sizeof d));
  return d;
}

// the contact search a world description asks for (0: the defaults); a specified direction given to
// another search is refused, as in a scenario file (it would not act)
void ReadSearch(const dm_world_desc& d, ContactOptions* o) {
  const SearchDirection searches[] = {o->search_direction, SearchDirection::kVelocity,
                                      SearchDirection::kLocalAverageNormal, SearchDirection::kPolyNormal,
                                      SearchDirection::kSpecified};
  Require(d.search_direction >= 0 && d.search_direction <= DM_SEARCH_SPECIFIED,
          "world.search_direction: expected a dm_search_direction (0..4), got " + std::to_string(d.search_direction));
  o->search_direction = searches[d.search_direction];
  const StopRule rules[] = {o->stop_rule, StopRule::kAfterOne, StopRule::kBestOfTwo, StopRule::kBestOfAll};
  Require(d.stop_rule >= 0 && d.stop_rule <= DM_STOP_BEST_OF_ALL,
          "world.stop_rule: expected a dm_stop_rule (0..3), got " + std::to_string(d.stop_rule));
  o->stop_rule = rules[d.stop_rule];
  const Vec3 v(d.specified_direction[0], d.specified_direction[1], d.specified_direction[2]);
  Require(v.allFinite(), "world.specified_direction: expected finite components");
  if (o->search_direction != SearchDirection::kSpecified) {
    Require(v.isZero(0.0), "world.specified_direction: acts only with DM_SEARCH_SPECIFIED; leave it zero");
    return;
  }
  o->specified_direction = UnitAlong(v);
  Require(!o->specified_direction.isZero(), "world.specified_direction: expected a vector of nonzero length with DM_SEARCH_SPECIFIED");
}

// the scenario part of a world description
Scenario ScenarioFromDesc(const dm_world_desc& d) {
  // each time on its own, then the step against the duration (blamed on the step, as a scenario
  // file's time.step)
  Require(std::isfinite(d.time_step) && d.time_step > 0,
          "world.time_step: expected a finite step > 0 s, got " + Number(d.time_step));
  Require(std::isfinite(d.duration), "world.duration: expected a finite duration [s], got " + Number(d.duration));
  Require(d.duration > 0, "world.duration: expected a duration > 0 s, got " + Number(d.duration));
  Require(d.passes_per_step >= 0 && d.passes_per_step <= 1000,
          "world.passes_per_step: expected 0..1000, got " + std::to_string(d.passes_per_step));
  Scenario s;
  CheckRange("world.duration", d.duration, kDurationRange, " s", &s.warnings);
  Require(d.time_step <= d.duration, "world.time_step: expected a step no longer than world.duration (" +
                                         Number(d.duration) + " s), got " + Number(d.time_step) + " s");
  Require(d.duration / d.time_step <= kMaxSteps,
          "world.time_step: expected at most 1e7 steps over world.duration (" + Number(d.duration) +
              " s): a step of at least " + Number(d.duration / kMaxSteps) + " s, got " + Number(d.time_step) + " s");
  s.file = "(dm_world_create)";
  s.units = UnitSystem::kSI;
  s.time_step = d.time_step;
  s.duration = d.duration;
  s.stop_at_separation = d.stop_at_separation != 0;
  if (d.passes_per_step > 0) s.contact.passes_per_step = d.passes_per_step;
  ReadSearch(d, &s.contact);
  return s;
}

}  // namespace

RigidState ToRigid(const dm_body_state& s, const std::string& at) {
  // each component named
  for (int k = 0; k < 3; ++k) RequireFinite(s.position[k], at + ".position[" + std::to_string(k) + "]");
  RequireFinite(s.roll, at + ".roll");
  RequireFinite(s.pitch, at + ".pitch");
  RequireFinite(s.yaw, at + ".yaw");
  for (int k = 0; k < 3; ++k) RequireFinite(s.velocity[k], at + ".velocity[" + std::to_string(k) + "]");
  for (int k = 0; k < 3; ++k) RequireFinite(s.omega[k], at + ".omega[" + std::to_string(k) + "]");
  RigidState r;
  r.position = Vec3(s.position[0], s.position[1], s.position[2]);
  r.roll = s.roll, r.pitch = s.pitch, r.yaw = s.yaw;
  r.velocity = Vec3(s.velocity[0], s.velocity[1], s.velocity[2]);
  r.omega = Vec3(s.omega[0], s.omega[1], s.omega[2]);
  return r;
}

ArrayWorld WorldFromArrays(const dm_world_desc* world, const dm_body_desc* bodies, int32_t body_count) {
  Require(body_count >= 2, "body_count: expected at least 2 bodies, got " + std::to_string(body_count));
  ArrayWorld out;
  out.scenario = ScenarioFromDesc(WorldDescFrom(world));
  out.scenario.bodies.resize(body_count);
  bool any_deformable = false;
  for (int i = 0; i < body_count; ++i) {
    BodySpec& spec = out.scenario.bodies[i];
    out.models.push_back(BodyFromDesc(BodyDescAt(bodies, i), i, &spec, &out.scenario.warnings));
    // the name becomes output file names: one body's files would overwrite another's
    for (int k = 0; k < i; ++k)
      Require(out.scenario.bodies[k].name != spec.name,
              "bodies[" + std::to_string(i) + "].name: duplicate body name \"" + spec.name + "\"");
    any_deformable = any_deformable || !spec.rigid;
  }
  Require(any_deformable, "bodies: every body is rigid: at least one must be deformable");
  WarnOfTheSpecifiedDirection(&out.scenario);
  return out;
}

}  // namespace dymesh::api
