#include "dymesh/core/simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dymesh/core/physical_ranges.h"
#include "dymesh/core/units.h"

namespace dymesh {

Simulation::Simulation(const Scenario& scenario, std::vector<std::shared_ptr<const BodyModel>> models,
                       const LocatorFactory& make_locator)
    : scenario_(scenario) {
  // bodies placed at contact; a fixed body given motion, a deep overlap or an unstable step refused
  const RunStart start = CheckRunStart(&scenario_, models);
  placements_ = start.placements;
  guide_ = start.guide;
  std::vector<RigidState> initial;
  for (const BodySpec& b : scenario_.bodies) {
    initial.push_back(b.initial);
    rest_height_.push_back(b.initial.position.z());
  }
  support_work_.assign(scenario_.bodies.size(), 0.0);
  for (const auto& m : models) farthest_vertex_.push_back(FarthestFromOrigin(m->mesh.vertices));
  engine_ = std::make_unique<ContactEngine>(std::move(models), initial, scenario_.contact, make_locator);
  for (std::size_t i = 0; i < scenario_.bodies.size(); ++i)
    engine_->SetMotion(static_cast<int>(i), scenario_.bodies[i].motion);
  Record(nullptr);
}

bool Simulation::Run(const std::function<bool(double)>& on_step) {
  // the caller may stop between steps (e.g. on Ctrl-C); the state stays consistent
  while (Advance()) {
    if (on_step && !on_step(time_)) return false;
  }
  return finished_;
}

bool Simulation::Advance() {
  if (finished_) throw std::logic_error("the run is finished (at " + std::to_string(time_) + " s)");
  // one run, one integrator: the host's steps and this one's would each miss the other's motion
  if (host_driven_) throw std::logic_error("the run is host-driven (HostStep): it takes no step of its own");
  const double dt = scenario_.time_step;
  // contact step at the current poses, then the rigid-body host integrates every body
  const StepResult step = engine_->Step(dt);
  if (!Integrate(step, dt)) {
    // a non-finite pose or velocity: keep the last finite state and stop
    failed_numerics_ = true;
    finished_ = true;
    return false;
  }
  // the energy ledger books the step's contact work on the motion just integrated
  engine_->AccountWork();
  diagnostics_.Add(step.diagnostics);
  ++steps_;
  time_ = steps_ * dt;
  NoteContact(step, dt);
  Record(&step, dt);
  // stop at the duration, or once contact has been over for the separation window and no two bodies
  // can meet again within the slap horizon (a car turning off a wall slaps it with its tail; spec §1:
  // the collision is over once its forces have separated the bodies): asked again when they could
  // first meet
  if (scenario_.stop_at_separation && last_contact_time_ >= 0.0 && time_ - last_contact_time_ >= kSeparationWindow &&
      time_ >= recheck_separation_) {
    const double remaining = scenario_.duration - time_;
    const std::vector<PlanMotion> plans = PlanMotions(remaining);
    const double soonest = SoonestPairMeeting(plans, std::min(remaining, kSlapHorizon), remaining);
    separated_ = soonest == INFINITY;
    recheck_separation_ = time_ + soonest;
    // a later meeting before the duration is noted, not simulated (a secondary impact)
    if (separated_ && remaining > kSlapHorizon) later_meeting_ = time_ + SoonestPairMeeting(plans, remaining, remaining);
  }
  finished_ = time_ >= scenario_.duration - 0.5 * dt || separated_;
  return !finished_;
}

std::vector<PlanMotion> Simulation::PlanMotions(double horizon) const {
  // every body seen in plan; one that does not hold its height with how fast it rolls and pitches
  // away from its outline over the horizon
  std::vector<PlanMotion> plans;
  for (int i = 0; i < engine_->body_count(); ++i) {
    plans.push_back(PlanMotionOf(engine_->state(i)));
    plans.back().wobble_speed =
        WobbleSpeed(engine_->model(i), scenario_.bodies[i].motion, engine_->state(i), horizon, scenario_.time_step);
  }
  return plans;
}

double Simulation::SoonestPairMeeting(const std::vector<PlanMotion>& plans, double touched_horizon, double remaining) const {
  // every pair that can carry a load (two rigid bodies pass through each other), in free motion: a
  // pair that has touched over `touched_horizon`, one yet to meet (the next car of a chain) to the end.
  // A corner inside the other outline may go a pass's restore margin deeper (TOOFAR_MARGIN: an
  // overlap the contact can leave between nodes without load)
  double soonest = INFINITY;
  const int n = static_cast<int>(plans.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (engine_->model(a).rigid && engine_->model(b).rigid) continue;
      soonest = std::min(soonest, dymesh::SoonestMeeting(plans[a], plans[b], PairTouched(a, b) ? touched_horizon : remaining,
                                                          scenario_.contact.toofar_margin));
    }
  return soonest;
}

bool Simulation::Integrate(const StepResult& step, double dt) {
  // every body's new state first; none is set unless all are finite
  std::vector<RigidState> next;
  std::vector<double> support_work;
  for (int i = 0; i < engine_->body_count(); ++i) {
    const BodyModel& model = engine_->model(i);
    const MotionModel motion = scenario_.bodies[i].motion;
    RigidState rigid = engine_->state(i).rigid;
    const ExternalLoads extra = MotionModelLoads(motion, model, rigid, rest_height_[i]);
    const CgLoads& loads = step.loads[i];
    IntegrateRigidBody(model, motion, loads.force_earth + extra.force_earth, loads.moment_body + extra.moment_body,
                       dt, &rigid);
    const bool finite = rigid.position.allFinite() && rigid.velocity.allFinite() && rigid.omega.allFinite() &&
                        std::isfinite(rigid.roll + rigid.pitch + rigid.yaw) && loads.force_earth.allFinite();
    if (!finite) return false;
    // the motion model's loads' work at the step's mean velocity: with the semi-implicit update, exactly
    // their part of the kinetic energy's change (they carry no moment)
    const Vec3 mean_velocity = 0.5 * (engine_->state(i).rigid.velocity + rigid.velocity);
    support_work.push_back(extra.force_earth.dot(mean_velocity) * dt);
    next.push_back(rigid);
  }
  for (int i = 0; i < engine_->body_count(); ++i) {
    engine_->SetRigidState(i, next[i]);
    support_work_[i] += support_work[i];
  }
  return true;
}

StepResult Simulation::HostStep(const std::vector<RigidState>& states, double dt) {
  if (finished_) throw std::logic_error("HostStep: the run is finished");
  if (steps_ > 0 && !host_driven_) throw std::logic_error("HostStep: the run was stepped by its own integrator");
  // a step no longer than a run may last (README Physical ranges)
  if (!(dt > 0.0 && dt <= kDurationRange.hard_hi))
    throw std::invalid_argument("HostStep: dt must be finite and > 0, at most 1e4 s (a run's longest duration)");
  AcceptHostStates(states);
  host_driven_ = true;
  host_pending_step_ = dt;
  // the contact step at the host's poses; the host integrates its loads
  StepResult step = engine_->Step(dt);
  diagnostics_.Add(step.diagnostics);
  // time as the engine's own host counts it while the step stays the same (no round-off drift)
  if (steps_ == 0) host_step_ = dt;
  if (dt != host_step_) host_step_ = 0.0;
  ++steps_;
  time_ = host_step_ > 0.0 ? steps_ * dt : time_ + dt;
  NoteContact(step, dt);
  host_pending_ = std::make_unique<StepResult>(step);
  return step;
}

void Simulation::FinishHostRun(const std::vector<RigidState>& states) {
  if (finished_) throw std::logic_error("FinishHostRun: the run is finished");
  if (steps_ > 0 && !host_driven_) throw std::logic_error("FinishHostRun: the run was stepped by its own integrator");
  AcceptHostStates(states);
  finished_ = true;
}

void Simulation::AcceptHostStates(const std::vector<RigidState>& states) {
  if (static_cast<int>(states.size()) != engine_->body_count())
    throw std::invalid_argument("expected " + std::to_string(engine_->body_count()) + " body states, got " +
                                std::to_string(states.size()));
  for (std::size_t i = 0; i < states.size(); ++i) RefuseImpossibleHostState(static_cast<int>(i), states[i]);
  if (host_pending_) CompareHostMotion(states, host_pending_step_);
  for (int i = 0; i < engine_->body_count(); ++i) engine_->SetRigidState(i, states[i]);
  // before the first step the run starts where the host has the bodies, not where construction put
  // them (delta-V and a contact that begins in the first step are measured from here)
  if (steps_ == 0)
    for (int i = 0; i < engine_->body_count(); ++i) history_.front().bodies[i].rigid = states[i];
  // the previous step ends here: book its work and record it
  if (host_pending_) {
    engine_->AccountWork();
    Record(host_pending_.get(), host_pending_step_);
    host_pending_.reset();
  }
}

double Simulation::largest_step() const {
  // each recorded step's own length (0 for the start): the scenario's before any
  double largest = 0.0;
  for (const Sample& s : history_) largest = std::max(largest, s.step);
  return largest > 0.0 ? largest : scenario_.time_step;
}

void Simulation::RefuseImpossibleHostState(int body, const RigidState& r) const {
  // finite, and within the physical ranges a scenario's initial state has (README Physical ranges);
  // angles may wind (a spinning body's yaw), but not past where their sines lose digits
  const auto refuse = [&](const std::string& what) {
    throw std::invalid_argument("body " + std::to_string(body) + ": " + what);
  };
  if (!r.position.allFinite() || !r.velocity.allFinite() || !r.omega.allFinite() || !std::isfinite(r.roll + r.pitch + r.yaw))
    refuse("non-finite pose or velocity");
  if (r.position.cwiseAbs().maxCoeff() > kPositionRange.hard_hi) refuse("position beyond 1e5 m");
  if (r.velocity.norm() > kSpeedRange.hard_hi) refuse("speed beyond the speed of sound (343 m/s)");
  if (r.omega.norm() > kYawRateRange.hard_hi * units::kDegree) refuse("angular rate beyond 36000 deg/s");
  if (std::max({std::abs(r.roll), std::abs(r.pitch), std::abs(r.yaw)}) > kMaxHostAngle)
    refuse("roll, pitch or yaw beyond 1e4 rad");
}

void Simulation::CompareHostMotion(const std::vector<RigidState>& states, double dt) {
  // the contact work of a host step is booked from the velocities and angular rates (at the contact
  // points): a host that moves or turns a body other than they say (a teleport, positions or angles
  // not integrated) leaves work unbooked. A host that integrates them moves a body by their mean over
  // the step times dt to within their change times dt (semi-implicit Euler: half of it). Each body is
  // judged at its farthest point: its CG's motion plus its turn times the farthest vertex's distance
  for (std::size_t i = 0; i < states.size(); ++i) {
    const RigidState& before = engine_->state(static_cast<int>(i)).rigid;
    const RigidState& after = states[i];
    const double r = farthest_vertex_[i];
    const Vec3 moved = after.position - before.position;
    const Vec3 accounted = 0.5 * (before.velocity + after.velocity) * dt;
    // the turn over the step and the one the rates account for, as rotation vectors in the body frame
    const Eigen::AngleAxisd turn(Mat3(before.Rotation().transpose() * after.Rotation()));
    const Vec3 turned = turn.angle() * turn.axis();
    const Vec3 turn_accounted = 0.5 * (before.omega + after.omega) * dt;
    const double accounted_reach = accounted.norm() + turn_accounted.norm() * r;
    const double allowed = kHostMotionSlack + kHostMotionRelativeSlack * accounted_reach +
                           ((after.velocity - before.velocity).norm() + (after.omega - before.omega).norm() * r) * dt;
    const double excess = (moved - accounted).norm() + (turned - turn_accounted).norm() * r - allowed;
    if (excess > 0.0 && excess > host_motion_.excess)
      host_motion_ = HostMotionMismatch{static_cast<int>(i), time_, moved.norm() + turned.norm() * r, accounted_reach,
                                        excess};
  }
}

void Simulation::NoteContact(const StepResult& step, double dt) {
  // each loaded pair's impulse; its contact began at the state the last sample holds
  for (const PairLoads& p : step.pairs) {
    const Vec3 on_a = p.normal_force[0] + p.friction_force[0];
    if (on_a.squaredNorm() == 0.0) continue;
    auto known = std::find_if(pair_contacts_.begin(), pair_contacts_.end(),
                              [&](const PairContact& c) { return c.a == p.body[0] && c.b == p.body[1]; });
    if (known == pair_contacts_.end()) {
      PairContact fresh;
      fresh.a = p.body[0];
      fresh.b = p.body[1];
      fresh.first_sample = history_.size() - 1;
      known = pair_contacts_.insert(pair_contacts_.end(), fresh);
    }
    known->impulse_on_a += on_a * dt;
    known->normal_impulse_on_a += p.normal_force[0] * dt;
    known->angular_impulse_on_a += (p.normal_moment[0] + p.friction_moment[0]) * dt;
    known->angular_impulse_on_b += (p.normal_moment[1] + p.friction_moment[1]) * dt;
    known->friction_angular_impulse_on_a += p.friction_moment[0] * dt;
    known->friction_angular_impulse_on_b += p.friction_moment[1] * dt;
  }
  bool in_contact = false;
  for (const CgLoads& loads : step.loads) in_contact = in_contact || loads.force_earth.squaredNorm() > 0.0;
  if (!in_contact) return;
  if (first_contact_time_ < 0.0) first_contact_time_ = time_ - dt;
  last_contact_time_ = time_;
  recheck_separation_ = 0.0;  // the contact changed the motion: a free-motion forecast no longer holds
}

void Simulation::Record(const StepResult* step, double dt) {
  Sample sample;
  sample.time = time_;
  sample.step = dt;
  for (int i = 0; i < engine_->body_count(); ++i) {
    const BodyState& s = engine_->state(i);
    BodySample b;
    b.rigid = s.rigid;
    if (step) {
      b.loads = step->loads[i];
      const double mass = engine_->model(i).mass;
      if (mass > 0.0) b.accel_body = b.loads.force_body / mass;
      for (const PairLoads& p : step->pairs)
        for (int k = 0; k < 2; ++k)
          if (p.body[k] == i) {
            b.contact_area += p.contact_area[k];
            b.untaken_share = std::max(b.untaken_share, p.untaken_share[k]);
          }
    }
    b.law_energy = s.law_energy;
    b.crush_energy = s.crush_energy;
    b.friction_energy = s.friction_energy;
    b.support_work = support_work_[i];
    sample.bodies.push_back(b);
  }
  history_.push_back(std::move(sample));
}

}  // namespace dymesh
