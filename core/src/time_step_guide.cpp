#include "dymesh/core/time_step_guide.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dymesh/core/units.h"

namespace dymesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

// samples of the loading law's slope between no crush and the crush the pair can reach
constexpr int kSlopeSamples = 16;
// halvings of the crush bracket: 60 take the body's length below a double's resolution of it
constexpr int kBisectionSteps = 60;

// spec §4 loading law per area: its work W(c) [N/m] and its slope dp/dc [N/m^3] at crush c (the null
// band and saturation left out: estimates)
double LawWork(const Stiffness& k, double c) { return c * (k.A + c * (k.B / 2 + c * (k.C / 3 + c * k.D / 4))); }
double LawSlope(const Stiffness& k, double c) { return k.B + c * (2 * k.C + 3 * k.D * c); }

// the crush at which the law over `area` takes `energy` [m] (bisection up to `longest`; 0 without energy)
double CrushTaking(const Stiffness& k, double area, double energy, double longest) {
  if (!(energy > 0.0) || !(area > 0.0) || LawWork(k, longest) * area <= energy) return energy > 0.0 ? longest : 0.0;
  double low = 0.0, high = longest;
  for (int i = 0; i < kBisectionSteps; ++i) {
    const double mid = 0.5 * (low + high);
    (LawWork(k, mid) * area < energy ? low : high) = mid;
  }
  return high;
}

// stiffest slope of a body's surfaces [N/m^3] (0 for a rigid body: it takes no crush): B, the
// unloading slope Kv, and with quadratic or cubic terms (C3, D3) the law's slope up to the crush at
// which that surface alone, over `area`, takes the pair's relative kinetic energy `energy` (at most
// the body's longest bounds side `longest`)
double SurfaceSlope(const BodyModel& model, double longest, double area, double energy) {
  if (model.rigid) return 0.0;
  double slope = 0.0;
  for (const Stiffness& k : model.stiffness) {
    slope = std::max({slope, k.B, k.unload_slope});
    if (k.C == 0.0 && k.D == 0.0) continue;
    double reach = CrushTaking(k, area, energy, longest);
    if (k.sat_crush > 0.0) reach = std::min(reach, k.sat_crush);
    if (k.max_crush > 0.0) reach = std::min(reach, k.max_crush);
    for (int i = 1; i <= kSlopeSamples; ++i) slope = std::max(slope, LawSlope(k, reach * i / kSlopeSamples));
  }
  return slope;
}

// area of a body's bounds box (sides `size`) projected across the earth direction d [m^2]
double ProjectedArea(const Vec3& size, const RigidState& pose, const Vec3& d) {
  const Vec3 db = pose.Rotation().transpose() * d;
  return size.y() * size.z() * std::abs(db.x()) + size.x() * size.z() * std::abs(db.y()) +
         size.x() * size.y() * std::abs(db.z());
}

// direction the pair closes along: relative velocity, else the line between the CGs
Vec3 ClosingDirection(const RigidState& a, const RigidState& b) {
  const Vec3 v = a.velocity - b.velocity;
  if (v.norm() > 0.0) return v.normalized();
  const Vec3 r = b.position - a.position;
  return r.norm() > 0.0 ? r.normalized() : Vec3(1, 0, 0);
}

// 1 / m of a body for the pair's reduced mass (0 for a fixed body)
double InverseMass(const Scenario& scenario, const BodyModel& model, int i) {
  return scenario.bodies[i].motion == MotionModel::kFixed ? 0.0 : 1.0 / model.mass;
}

// the fastest pair that can carry a load, and the step over which it closes by the search reach
void SetReachStep(const Scenario& scenario, const std::vector<std::shared_ptr<const BodyModel>>& models,
                  TimeStepGuide* guide) {
  for (int a = 0; a < static_cast<int>(models.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(models.size()); ++b) {
      if (models[a]->rigid && models[b]->rigid) continue;
      const double speed = (scenario.bodies[a].initial.velocity - scenario.bodies[b].initial.velocity).norm();
      if (!(speed > guide->relative_speed)) continue;
      guide->fastest_a = a;
      guide->fastest_b = b;
      guide->relative_speed = speed;
      guide->reach_step = scenario.contact.toofar_maximum / speed;
    }
}

// the `gravity` bodies' ground support: x'' = -omega^2 x - 2 omega x' (critically damped) stepped as
// the host does (spec §8, semi-implicit Euler: v += h a, then x += h v) maps (v, x) by a matrix of trace 2 - 2 omega h - (omega h)^2 and
// determinant 1 - 2 omega h; both roots stay inside the unit circle (Jury: |det| < 1, 1 + det > |trace|)
// while omega h < 2 (sqrt 2 - 1) = 0.83
void SetGroundLimits(const Scenario& scenario, TimeStepGuide* guide) {
  const auto gravity = std::find_if(scenario.bodies.begin(), scenario.bodies.end(),
                                    [](const BodySpec& b) { return b.motion == MotionModel::kGravityGround; });
  if (gravity == scenario.bodies.end()) return;
  const double omega = std::sqrt(units::kStandardGravity / kGroundStaticDeflection);
  guide->ground_body = static_cast<int>(gravity - scenario.bodies.begin());
  guide->ground_omega = omega;
  guide->ground_stable_limit = 2.0 * (std::sqrt(2.0) - 1.0) / omega;
}

}  // namespace

TimeStepGuide GuideTimeStep(const Scenario& scenario, const std::vector<std::shared_ptr<const BodyModel>>& models) {
  TimeStepGuide guide;
  double best_omega = 0.0;
  // each body's bounds box sides, body frame
  std::vector<Vec3> sizes;
  for (const auto& model : models) {
    const MeshStats s = ComputeStats(model->mesh);
    sizes.push_back(s.max - s.min);
  }
  for (int a = 0; a < static_cast<int>(models.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(models.size()); ++b) {
      const RigidState& pa = scenario.bodies[a].initial;
      const RigidState& pb = scenario.bodies[b].initial;
      const Vec3 d = ClosingDirection(pa, pb);
      const double area = std::min(ProjectedArea(sizes[a], pa, d), ProjectedArea(sizes[b], pb, d));
      // reduced mass; two fixed bodies never move relative to each other
      const double inverse_mass = InverseMass(scenario, *models[a], a) + InverseMass(scenario, *models[b], b);
      if (!(inverse_mass > 0.0)) continue;
      const double energy = 0.5 * (pa.velocity - pb.velocity).squaredNorm() / inverse_mass;
      // the two bodies' surfaces in series over the smaller projected area
      const double slope_a = SurfaceSlope(*models[a], sizes[a].maxCoeff(), area, energy);
      const double slope_b = SurfaceSlope(*models[b], sizes[b].maxCoeff(), area, energy);
      if (slope_a == 0.0 && slope_b == 0.0) continue;
      const double compliance = (slope_a > 0.0 ? 1.0 / slope_a : 0.0) + (slope_b > 0.0 ? 1.0 / slope_b : 0.0);
      const double k = area / compliance;
      if (!(k > 0.0)) continue;
      const double omega = std::sqrt(k * inverse_mass);
      if (omega <= best_omega) continue;
      best_omega = omega;
      guide = TimeStepGuide{true, a, b, k, 1.0 / inverse_mass, kPi / omega, kPi / omega / kMinStepsPerContact,
                            2.0 / omega};
    }
  SetReachStep(scenario, models, &guide);
  SetGroundLimits(scenario, &guide);
  return guide;
}

void RefuseUnstableStep(const Scenario& scenario, const TimeStepGuide& guide) {
  char text[400];
  if (guide.bounded && scenario.time_step > guide.stable_limit) {
    std::snprintf(text, sizeof text,
                  "step %g s is beyond the stable limit %.3g s of \"%s\" against \"%s\" (contact period %.3g s): the "
                  "integration would diverge; use at most %.3g s (recommended %.3g s)",
                  scenario.time_step, guide.stable_limit, scenario.bodies[guide.body_a].name.c_str(),
                  scenario.bodies[guide.body_b].name.c_str(), guide.contact_period, guide.stable_limit,
                  guide.recommended_step);
    throw InputError(scenario.file, "time.step", text);
  }
  if (guide.ground_body >= 0 && scenario.time_step > guide.ground_stable_limit) {
    std::snprintf(text, sizeof text,
                  "step %g s is beyond the stable limit %.3g s of the ground support under \"%s\" (motion "
                  "\"gravity\": its weight on a critically damped support of %.0f rad/s): the integration would "
                  "diverge; use at most %.3g s",
                  scenario.time_step, guide.ground_stable_limit, scenario.bodies[guide.ground_body].name.c_str(),
                  guide.ground_omega, guide.ground_stable_limit);
    throw InputError(scenario.file, "time.step", text);
  }
}

}  // namespace dymesh
