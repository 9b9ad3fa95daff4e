#include "dymesh/analysis/run_assessment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "dymesh/analysis/crush_reach.h"
#include "dymesh/analysis/obstacle_inside.h"
#include "dymesh/analysis/plan_overlap.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"

namespace dymesh {
namespace {

// printf into a std::string (warning texts)
template <typename... Args>
std::string Text(const char* format, Args... args) {
  // sized to the text: body names of any length are written whole
  std::string text(std::snprintf(nullptr, 0, format, args...), '\0');
  std::snprintf(text.data(), text.size() + 1, format, args...);
  return text;
}

// every number of the summary a reader relies on is finite
bool SummaryFinite(const Summary& s) {
  bool ok = std::isfinite(s.kinetic_before + s.kinetic_after + s.crush_energy + s.friction_energy + s.law_energy +
                          s.energy_balance_error + s.closing_speed + s.separation_speed) &&
            s.momentum_before.allFinite() && s.momentum_after.allFinite();
  for (const PairSummary& p : s.pairs)
    ok = ok && std::isfinite(p.closing_speed + p.separation_speed + p.point_closing_speed + p.point_separation_speed +
                             p.impulse_ratio + p.yaw_rate_change[0] + p.yaw_rate_change[1] +
                             p.friction_yaw_rate_change[0] + p.friction_yaw_rate_change[1]) &&
         p.direction.allFinite();
  for (const BodySummary& b : s.bodies)
    ok = ok && std::isfinite(b.delta_v + b.pdof_deg + b.peak_accel + b.average_accel + b.max_crush +
                             b.max_dynamic_crush + b.crush_energy + b.friction_energy + b.law_energy +
                             b.final_yaw_rate + b.peak_contact_area) &&
         b.delta_v_earth.allFinite() && b.final_velocity.allFinite();
  return ok;
}

// resultant collision force on all bodies in one recorded sample [N]
double TotalLoad(const Sample& s) {
  double f = 0.0;
  for (const BodySample& b : s.bodies) f += b.loads.force_earth.norm();
  return f;
}

// the other body's vertex that went deepest inside a deformable body of the pair beyond the crush
// there, kept where that is more than the search reaches (spec §2 TOOFAR_MAXIMUM): a rigid obstacle, or
// a deformable body whose nodes missed the faces (fuzzing, 2026-11-27: a 10 in cube at 80 mph through a
// 200 in box, the p406 through a soft box, both unmarked)
struct BodyInside {
  int body = -1, obstacle = -1, vertex = -1;
  double depth = 0.0;  // [m]
};
BodyInside DeepestBodyInside(const Simulation& sim, const PairSummary& p, const std::vector<MeshStats>& rest) {
  BodyInside out;
  for (int body : {p.a, p.b}) {
    if (sim.engine().model(body).rigid) continue;
    const int obstacle = body == p.a ? p.b : p.a;
    // out of the deformable body toward the other: against the impulse the other gave it
    const Vec3 toward = body == p.a ? Vec3(-p.direction) : p.direction;
    const ObstacleInside deepest = DeepestObstacleVertexInside(sim, body, obstacle, toward, rest[body]);
    if (deepest.depth > sim.scenario().contact.toofar_maximum && deepest.depth > out.depth)
      out = {body, obstacle, deepest.vertex, deepest.depth};
  }
  return out;
}

// an impulse this much horizontal (its horizontal part's length, unit impulse) is judged in plan
constexpr double kMostlyHorizontal = 0.5;

// whether a pair still closing along its impulse at the end went into each other: one body inside the
// other (obstacle_inside), or its rest plan outline farther into the other's along the impulse than the
// two crushed plus the search's reach. A glancing contact slides the bodies past each other, so along a
// sideways impulse they still close as they part (the p406 and the stock car brushing at 30 deg ended at
// -0.98, 7.5 in into each other for 8.8 in of crush; coarse boxes head-on, gone through each other
// with their corners 6-46 in over, 194-330 in for 25 in)
bool WentThrough(const Simulation& sim, const Summary& s, const PairSummary& p, const BodyInside& inside) {
  if (inside.vertex >= 0) return true;
  // an impulse within 30 deg of the vertical: the plan cannot tell
  if (std::hypot(p.direction.x(), p.direction.y()) < kMostlyHorizontal) return true;
  const double crushed = s.bodies[p.a].max_dynamic_crush + s.bodies[p.b].max_dynamic_crush;
  return DeepestPlanOverlap(sim, p.a, p.b, p.direction) > crushed + sim.scenario().contact.toofar_maximum;
}

// the first of the samples over the run's last separation window, by their times (in force-provider
// mode each step is the host's dt, not the scenario's), at least one step back; -1 when the run is
// shorter than the window
long WindowStart(const std::vector<Sample>& h) {
  const double end = h.back().time, slack = 1e-9 * kSeparationWindow;  // the times' round-off
  if (end - h.front().time < kSeparationWindow - slack) return -1;
  long k = static_cast<long>(h.size()) - 1;
  while (k > 0 && end - h[k - 1].time <= kSeparationWindow + slack) --k;
  return std::min(k, static_cast<long>(h.size()) - 2);
}

// in contact at the end but at rest: every pair's relative speed small and the load not growing
// over the last separation window
bool AtRestInContact(const Simulation& sim) {
  const auto& h = sim.history();
  const int n = sim.engine().body_count();
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if ((sim.engine().state(a).rigid.velocity - sim.engine().state(b).rigid.velocity).norm() > kRestSpeed)
        return false;
  const long start = WindowStart(h);
  if (start < 0) return false;
  return TotalLoad(h.back()) <= TotalLoad(h[start]) * (1.0 + 1e-9);
}

// kinetic energy of the bodies' motion relative to each other at the first recorded step [J]: in the
// free bodies' centre-of-mass frame, or the ground's when a body is fixed (the most a collision can absorb)
double RelativeKineticEnergyBefore(const Simulation& sim) {
  const ContactEngine& engine = sim.engine();
  const Sample& first = sim.history().front();
  double mass = 0.0;
  Vec3 momentum(0, 0, 0);
  bool any_fixed = false;
  for (int i = 0; i < engine.body_count(); ++i) {
    if (sim.scenario().bodies[i].motion == MotionModel::kFixed) { any_fixed = true; continue; }
    mass += engine.model(i).mass;
    momentum += engine.model(i).mass * first.bodies[i].rigid.velocity;
  }
  const Vec3 frame_velocity = any_fixed || !(mass > 0.0) ? Vec3(0, 0, 0) : Vec3(momentum / mass);
  double energy = 0.0;
  for (int i = 0; i < engine.body_count(); ++i) {
    if (sim.scenario().bodies[i].motion == MotionModel::kFixed) continue;
    RigidState relative = first.bodies[i].rigid;
    relative.velocity -= frame_velocity;
    energy += KineticEnergy(engine.model(i), relative);
  }
  return energy;
}

// the crush work the contact absorbed and gave back over the run [J] (its steps of positive and
// negative normal work, all bodies summed), and the most its laws give back: e^2 of what they took,
// e the largest of the deformable bodies' (-1 with the literal rebound law, whose share is not e^2)
struct ReboundWork {
  double absorbed = 0.0, returned = 0.0, e_squared = -1.0;
};
ReboundWork ReboundWorkOf(const Simulation& sim) {
  ReboundWork r;
  if (sim.scenario().contact.rebound_law != ReboundLaw::kScaled) return r;
  r.e_squared = 0.0;
  for (int i = 0; i < sim.engine().body_count(); ++i)
    if (!sim.engine().model(i).rigid) r.e_squared = std::max(r.e_squared, std::pow(sim.engine().model(i).restitution, 2));
  double before = 0.0;
  for (const Sample& sample : sim.history()) {
    double work = 0.0;
    for (const BodySample& b : sample.bodies) work += b.crush_energy;
    (work > before ? r.absorbed : r.returned) += std::abs(work - before);
    before = work;
  }
  return r;
}

// the vertex farthest outside the body's undamaged bounds `rest` (body frame) and how far [m]
struct NodeOutside {
  int vertex = -1;
  double distance = 0.0;
};
NodeOutside FarthestOutsideRestBounds(const MeshStats& rest, const BodyState& state) {
  NodeOutside out;
  for (std::size_t v = 0; v < state.vertices.size(); ++v) {
    const Vec3& p = state.vertices[v];
    const double beyond = std::max((rest.min - p).maxCoeff(), (p - rest.max).maxCoeff());
    if (beyond > out.distance) out = {static_cast<int>(v), beyond};
  }
  return out;
}

// in contact over the whole last separation window with at most kLightContactShare of the peak load:
// the touch after the collision of bodies that no longer push each other (a box stopped against a round
// pole 1.5 in off its axis with e = 0 slid past it at 0.13 mph, turning at 1.7 deg/s, with 0.003 lbf of
// its 20,000). A touch that began within the window may be a new impact's start: not light
bool LightContactAtEnd(const Simulation& sim) {
  const auto& h = sim.history();
  const long start = WindowStart(h);
  if (start < 0) return false;
  double peak = 0.0;
  for (const Sample& sample : h) peak = std::max(peak, TotalLoad(sample));
  for (std::size_t k = start; k < h.size(); ++k)
    if (!(TotalLoad(h[k]) > 0.0 && TotalLoad(h[k]) <= kLightContactShare * peak)) return false;
  return true;
}

RunStatus StatusOf(const Simulation& sim, const Summary& summary) {
  if (sim.failed_numerics() || !SummaryFinite(summary)) return RunStatus::kFailedNumerics;
  if (!sim.finished()) return RunStatus::kInterrupted;
  if (sim.in_contact_at_end() && !AtRestInContact(sim) && !LightContactAtEnd(sim))
    return RunStatus::kEndedInContact;
  return RunStatus::kComplete;
}

// the pairs that can carry a load (not two rigid bodies) and carried none
std::vector<std::pair<int, int>> PairsWithoutContact(const Simulation& sim) {
  std::vector<std::pair<int, int>> pairs;
  const int n = sim.engine().body_count();
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (!(sim.engine().model(a).rigid && sim.engine().model(b).rigid) && !sim.PairTouched(a, b))
        pairs.emplace_back(a, b);
    }
  return pairs;
}

// warnings on how the run went (after the scenario's own)
void AddRunWarnings(const Simulation& sim, const Summary& s, RunStatus status, std::vector<RunWarning>* w) {
  const Scenario& sc = sim.scenario();
  if (status == RunStatus::kFailedNumerics)
    w->push_back({"non_finite", "", Text("a pose or velocity went non-finite at t = %.4f s; the results stop at the "
                                         "last finite step and are not usable", s.end_time)});
  // pairs that carried no force yet went into each other past the search's reach, in plan and in
  // height: the search never found the other's surface (a specified direction pointing away from
  // it), they passed through
  bool unseen = false;
  for (const auto& [a, b] : PairsWithoutContact(sim)) {
    const double depth = DeepestPlanInterpenetration(sim, a, b, sc.contact.toofar_maximum);
    if (!(depth > sc.contact.toofar_maximum)) continue;
    unseen = true;
    w->push_back({"passed_through", "",
                  Text("\"%s\" and \"%s\" went %.3g m into each other (their outlines in plan) with no contact "
                       "force: the contact search never found the other's surface (check contact.search_direction "
                       "and specified_direction); they passed through each other, and delta-V, crush and energies "
                       "are not physical",
                       s.bodies[a].name.c_str(), s.bodies[b].name.c_str(), depth)});
  }
  if (s.contact_start < 0.0 && !unseen)
    w->push_back({"no_contact", "", "the bodies never touched: check the initial positions, headings and speeds"});
  if (sim.finished() && !sim.failed_numerics() && sc.stop_at_separation && !sim.separated() && s.contact_start >= 0.0)
    w->push_back({"ran_to_duration", "time.duration",
                  Text("the run reached its duration (%g s) before the bodies separated: results depend on the "
                       "duration; lengthen time.duration", sc.duration)});
  if (status == RunStatus::kComplete && sim.in_contact_at_end() && AtRestInContact(sim))
    w->push_back({"at_rest_in_contact", "", "the bodies came to rest in contact; the contact force is not growing"});
  else if (status == RunStatus::kComplete && sim.in_contact_at_end())
    w->push_back({"light_contact_at_end", "",
                  "the run ended with the bodies touching at under 1e-4 of their peak contact force (a touch after "
                  "the collision: delta-V and crush are the collision's)"});
  if (sim.separated() && std::isfinite(sim.later_meeting_time()))
    w->push_back({"may_meet_again", "time.stop_at_separation",
                  Text("the run stopped at separation, but moving on freely (no tyre or ground forces) the bodies "
                       "may meet again before the duration (their plan outlines from t = %.3f s): a secondary "
                       "impact this run does not include (delta-V and crush are the first collision's); run "
                       "without stop_at_separation to follow it", sim.later_meeting_time())});
  if (std::abs(s.energy_balance_error) > kEnergyBalanceTolerance)
    w->push_back({"energy_balance", "",
                  Text("energy balance error %.2f %% exceeds %.0f %%: kinetic energy lost and contact work disagree",
                       100.0 * s.energy_balance_error, 100.0 * kEnergyBalanceTolerance)});
  // contact that gave back more energy than it absorbed: restitution above 1 (a law too stiff for the step)
  const double absorbed = s.crush_energy + s.friction_energy;
  const double available = RelativeKineticEnergyBefore(sim);
  if (absorbed < -kEnergyCreatedTolerance * available)
    w->push_back({"energy_created", "",
                  Text("the contact returned %.3g J more than it absorbed (%.0f %% of the %.3g J of relative motion "
                       "before it): a restitution above 1, not physical; the crush law is too stiff for the time "
                       "step (check C3, D3 and Kv) or the masses are wrong",
                       -absorbed, -100.0 * absorbed / available, available)});
  // contact that gave back more of the crush work it absorbed than restitution allows (spec §6: e^2)
  if (const ReboundWork r = ReboundWorkOf(sim); r.e_squared >= 0.0 &&
      r.returned > (kReboundMarginOfESquared * r.e_squared + kReboundMarginOfAbsorbed) * r.absorbed +
                       kReboundMarginOfEnergy * available)
    w->push_back({"rebound_beyond_restitution", "",
                  Text("the contact gave back %.1f %% of the crush work it absorbed (%.3g J of %.3g J), where "
                       "restitution e = %.2f gives back at most e^2 = %.1f %%: the rebound and delta-V are not "
                       "physical (the node laws and the forces applied parted; a coarse mesh against a round "
                       "pole, or a law too stiff for the step)",
                       100.0 * r.returned / r.absorbed, r.returned, r.absorbed, std::sqrt(r.e_squared),
                       100.0 * r.e_squared)});
  // the longest step taken: the scenario's, or the longest dt a host gave
  const TimeStepGuide& g = sim.time_step_guide();
  const double step = sim.largest_step();
  if (g.bounded && step > g.recommended_step)
    w->push_back({"time_step_coarse", "time.step",
                  Text("step %g s resolves the contact period %.3g s of \"%s\" against \"%s\" with %.0f steps "
                       "(fewer than %d); use at most %.3g s",
                       step, g.contact_period, sc.bodies[g.body_a].name.c_str(),
                       sc.bodies[g.body_b].name.c_str(), g.contact_period / step, kMinStepsPerContact,
                       g.recommended_step)});
  if (g.fastest_a >= 0 && step > g.reach_step)
    w->push_back({"step_beyond_search_reach", "time.step",
                  Text("\"%s\" and \"%s\" close %.3g m per step at their initial relative speed, farther than the "
                       "contact search reaches (contact.toofar_maximum %.3g m): a node can cross a surface in one "
                       "step unseen and the contact be missed; use at most %.3g s",
                       sc.bodies[g.fastest_a].name.c_str(), sc.bodies[g.fastest_b].name.c_str(),
                       g.relative_speed * step, sc.contact.toofar_maximum, g.reach_step)});
  // force-provider mode: a host that moved a body other than its velocities say
  if (const HostMotionMismatch& m = sim.host_motion_mismatch(); m.body >= 0)
    w->push_back({"host_motion_inconsistent", "",
                  Text("the host moved \"%s\" %.3g m (its farthest point) over the host step ending at t = %.4f s, where "
                       "its velocities and angular rates account for %.3g m: poses and velocities disagree (a "
                       "teleport, or positions or angles not integrated from the velocities); the contact work "
                       "is booked from the velocities, so the energy account and the crush energies do not hold",
                       sc.bodies[m.body].name.c_str(), m.moved, m.time, m.accounted)});
  // each body's rest mesh: its extent, and whether it is closed
  std::vector<MeshStats> rest_stats;
  for (int i = 0; i < sim.engine().body_count(); ++i) rest_stats.push_back(ComputeStats(sim.engine().model(i).mesh));
  for (int i = 0; i < sim.engine().body_count(); ++i) {
    // crush deeper than the body is long (x extent): the mesh was pushed through itself
    const MeshStats& rest = rest_stats[i];
    const double length = rest.max.x() - rest.min.x();
    if (s.bodies[i].max_crush > length)
      w->push_back({"crush_beyond_length", "bodies[" + std::to_string(i) + "]",
                    Text("\"%s\": maximum crush %.3g m exceeds the body's length %.3g m: the mesh was pushed "
                         "through itself; the crush law or the stiffness does not fit this body",
                         s.bodies[i].name.c_str(), s.bodies[i].max_crush, length)});
    // a node ended beyond the body's undamaged bounds by more than the search reach: crush moves a node
    // into its body, so the contact pushed it out (through the body, or dragged outward), spec §2-§5.
    // The contact's forces acted, so delta-V stands; the crush there does not
    const NodeOutside out = FarthestOutsideRestBounds(rest, sim.engine().state(i));
    if (out.distance > sc.contact.toofar_maximum)
      w->push_back({"crush_outside_outline", "bodies[" + std::to_string(i) + "]",
                    Text("\"%s\": node %d ended %.3g m outside the body's undamaged bounds, farther than the contact "
                         "search reaches (%.3g m): the contact moved it out of the body instead of crushing it "
                         "in; the crush depths and profile there are not physical",
                         s.bodies[i].name.c_str(), out.vertex, out.distance, sc.contact.toofar_maximum)});
    // spec §5: the other bodies' nodes left this body an equal-pressure share its own nodes never took
    // (its faces there crush only at corners outside the contact); a share within the null band, where
    // the law does not yet harden, is not judged
    const BodySummary& b = s.bodies[i];
    if (b.untaken_crush > std::max(b.max_dynamic_crush, sc.contact.null_band))
      w->push_back({"crush_not_in_mesh", "bodies[" + std::to_string(i) + "]",
                    Text("\"%s\": where the other body met it, its faces stood %.3g m inside that body's crushed "
                         "surface (its equal-pressure share of the crush there, at its loaded steps), more than its "
                         "own nodes ever crushed (%.3g m): its faces there are larger than the contact and their "
                         "corners, outside it, never crushed; its crush depths, profile and deformed mesh under-report "
                         "the crush (delta-V and the crush energies less: the faces press at the equal pressure) and "
                         "the other body's inner layers can be met early; refine its mesh where the contact is",
                         b.name.c_str(), b.untaken_crush, b.max_dynamic_crush)});
    // a node crushed deeper along its crush than any other body came (spec §2: no push beyond the
    // step's relative motion plus TOOFAR_MARGIN, so the margin is what a node may lie beyond it)
    const NodeBeyondReach beyond = DeepestNodeBeyondReach(sim, i, rest_stats);
    if (beyond.vertex >= 0 && beyond.crush - beyond.reach > sc.contact.toofar_margin)
      w->push_back({"crush_beyond_reach", "bodies[" + std::to_string(i) + "]",
                    Text("\"%s\": node %d is crushed %.3g m, %.3g m farther along its crush than any other body "
                         "came (%.3g m): the contact pushed it there, not a body; the crush depths and profile "
                         "there are not physical",
                         s.bodies[i].name.c_str(), beyond.vertex, beyond.crush, beyond.crush - beyond.reach,
                         beyond.reach)});
  }
  for (const PairSummary& p : s.pairs) {
    // a body that went deeper inside a deformable one than it crushed, past the search's reach
    const BodyInside inside = DeepestBodyInside(sim, p, rest_stats);
    if (inside.vertex >= 0)
      w->push_back({"obstacle_inside", "",
                    Text("\"%s\" (its vertex %d) went inside \"%s\" %.3g m deeper than \"%s\" was crushed there, "
                         "more than the contact search reaches (%.3g m): it went in between the nodes, which slid aside "
                         "or never met it, and was never pushed out; the crush, its profile and the energies there are "
                         "not physical",
                         s.bodies[inside.obstacle].name.c_str(), inside.vertex, s.bodies[inside.body].name.c_str(),
                         inside.depth, s.bodies[inside.body].name.c_str(), sc.contact.toofar_maximum)});
    // the pair's contact left it closing along its impulse at over half its closing speed, or at over
    // a quarter with one body gone inside the other, once the run is over (still in contact, or stopped early,
    // the bodies may yet be stopped: the status says so)
    const bool closing =
        p.restitution() < (inside.vertex >= 0 ? kPassThroughWithObstacleInside : kPassThroughSeparation);
    if (status == RunStatus::kComplete && p.closing_speed > 0.0 && closing && WentThrough(sim, s, p, inside))
      w->push_back({"passed_through", "",
                    Text("\"%s\" and \"%s\" still closed at %.0f %% of their closing speed when the run ended: "
                         "they passed through each other instead of crushing (coarse meshes whose faces meet "
                         "between their nodes); delta-V, crush and energies are not physical",
                         s.bodies[p.a].name.c_str(), s.bodies[p.b].name.c_str(),
                         -100.0 * p.restitution())});
  }
  if (s.diagnostics.non_finite > 0)
    w->push_back({"non_finite_nodes", "",
                  Text("%lld node updates were skipped as non-finite", s.diagnostics.non_finite)});
}

}  // namespace

bool WarningVoidsResults(std::string_view code) {
  return code == "passed_through" || code == "crush_beyond_length" || code == "energy_balance" ||
         code == "energy_created" || code == "rebound_beyond_restitution";
}

RunAssessment AssessRun(const Simulation& sim, const Summary& summary) {
  RunAssessment a;
  a.status = StatusOf(sim, summary);
  a.warnings = sim.scenario().warnings;
  AddRunWarnings(sim, summary, a.status, &a.warnings);
  return a;
}

}  // namespace dymesh
