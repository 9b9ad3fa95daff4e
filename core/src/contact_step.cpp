#include "dymesh/core/contact_step.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "contact_pass_frame.h"
#include "dymesh/core/contact_stick.h"
#include "dymesh/core/crush_sharing.h"
#include "dymesh/core/parallel.h"

namespace dymesh {
namespace {

// a host's pose and velocities must be finite
void RequireFiniteState(const RigidState& r, int body) {
  if (!r.position.allFinite() || !r.velocity.allFinite() || !r.omega.allFinite() ||
      !std::isfinite(r.roll + r.pitch + r.yaw))
    throw std::invalid_argument("body " + std::to_string(body) + ": non-finite pose or velocity");
}

// a pushback direction this close to parallel with a face (cosine) does not leave through it
constexpr double kMinFacing = 1e-9;
// [m/s] relative speed below which the velocity search direction falls back to the local normal
constexpr double kStillSpeed = 1e-9;
// cosine of 1 deg: a face this close in direction to the one a node was pressed on is on its plane
// (the velocity search's look back: without it the centred frictionless pole let the car on, 11.7 mph
// of 20 by 0.7 s)
const double kSamePlane = std::cos(1.0 * M_PI / 180.0);

// a host's body index must name a body
void RequireBodyIndex(int i, int count, const char* call) {
  if (i < 0 || i >= count)
    throw std::invalid_argument(std::string(call) + ": body " + std::to_string(i) + " is out of range 0.." +
                                std::to_string(count - 1));
}

}  // namespace

void ContactEngine::Wrench::Add(const Vec3& force, const Vec3& arm_slave, const Vec3& arm_master) {
  force_slave += force;
  moment_slave += arm_slave.cross(force);
  moment_master -= arm_master.cross(force);
}

void ContactEngine::Wrench::AddToPair(double weight, int slave_side, Vec3 (&force)[2], Vec3 (&moment)[2]) const {
  force[slave_side] += weight * force_slave;
  moment[slave_side] += weight * moment_slave;
  force[1 - slave_side] -= weight * force_slave;
  moment[1 - slave_side] += weight * moment_master;
}

void ContactEngine::Wrench::operator+=(const Wrench& o) {
  force_slave += o.force_slave;
  moment_slave += o.moment_slave;
  moment_master += o.moment_master;
}

void ContactDiagnostics::Add(const ContactDiagnostics& o) {
  candidates += o.candidates;
  located += o.located;
  touching += o.touching;
  too_far_limited += o.too_far_limited;
  max_crush_limited += o.max_crush_limited;
  growth_limited += o.growth_limited;
  held_unfound += o.held_unfound;
  reduced += o.reduced;
  non_finite += o.non_finite;
  faces_pushed += o.faces_pushed;
  pairs_in_contact += o.pairs_in_contact;
}

ContactEngine::ContactEngine(std::vector<std::shared_ptr<const BodyModel>> models, std::vector<RigidState> initial,
                             ContactOptions options, const LocatorFactory& make_locator)
    : models_(std::move(models)), options_(options) {
  // one pose per model, every one finite, every model present
  if (initial.size() != models_.size())
    throw std::invalid_argument("ContactEngine: " + std::to_string(models_.size()) + " models but " +
                                std::to_string(initial.size()) + " initial states");
  for (std::size_t i = 0; i < models_.size(); ++i) {
    if (!models_[i]) throw std::invalid_argument("ContactEngine: model " + std::to_string(i) + " is null");
    RequireFiniteState(initial[i], static_cast<int>(i));
  }
  const int n = body_count();
  // one state, one locator and one bounds box per body; one touching list pair per body pair
  for (int i = 0; i < n; ++i) {
    states_.push_back(MakeBodyState(*models_[i], initial[i]));
    motions_.push_back(MotionModel::kFree6Dof);
    locators_.push_back(make_locator(models_[i]->mesh));
  }
  bounds_min_.resize(n);
  bounds_max_.resize(n);
  chunk_min_.resize(n);
  chunk_max_.resize(n);
  for (int i = 0; i < n; ++i) InitBounds(i);
  engaged_.resize(static_cast<size_t>(n) * n);
  pushed_.assign(static_cast<size_t>(n) * n, Vec3::Zero());
  pending_delta_.resize(n);
  moved_.resize(n);
  for (int i = 0; i < n; ++i) pending_delta_[i].resize(models_[i]->mesh.vertices.size());
  engaged_mark_.resize(n);
  // determinism: every pair (a < b), in an order the bodies set, not their listing (a car between two
  // poles took the poles' crush in listing order: swapping the poles moved its yaw rate 3e-4, a box's
  // between closer poles 17 %), by the pair's names, then by index where names repeat
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) pair_order_.push_back({a, b});
  const auto key = [&](const std::array<int, 2>& p) {
    const std::string &x = models_[p[0]]->name, &y = models_[p[1]]->name;
    return std::make_pair(std::min(x, y), std::max(x, y));
  };
  std::stable_sort(pair_order_.begin(), pair_order_.end(),
                   [&](const std::array<int, 2>& p, const std::array<int, 2>& q) { return key(p) < key(q); });
}

void ContactEngine::InitBounds(int body) {
  // one box per fixed chunk of vertices (mesh order is spatially coherent) and one for the body
  const std::vector<Vec3>& vertices = states_[body].vertices;
  const std::size_t chunks = ChunkCount(vertices.size());
  chunk_min_[body].assign(chunks, Vec3::Constant(INFINITY));
  chunk_max_[body].assign(chunks, Vec3::Constant(-INFINITY));
  std::vector<int> all(vertices.size());
  for (std::size_t v = 0; v < all.size(); ++v) all[v] = static_cast<int>(v);
  bounds_min_[body] = Vec3::Constant(INFINITY);
  bounds_max_[body] = Vec3::Constant(-INFINITY);
  GrowBounds(body, all);
}

void ContactEngine::GrowBounds(int body, const std::vector<int>& moved) {
  // boxes only grow: after crush they still hold every vertex (a conservative cull)
  const std::vector<Vec3>& vertices = states_[body].vertices;
  for (int v : moved) {
    const std::size_t c = static_cast<std::size_t>(v) / kChunkSize;
    chunk_min_[body][c] = chunk_min_[body][c].cwiseMin(vertices[v]);
    chunk_max_[body][c] = chunk_max_[body][c].cwiseMax(vertices[v]);
    bounds_min_[body] = bounds_min_[body].cwiseMin(vertices[v]);
    bounds_max_[body] = bounds_max_[body].cwiseMax(vertices[v]);
  }
}

bool ContactEngine::BoundsOverlap(int a, int b) const {
  // earth-frame boxes around each body's rotated body-frame box, grown by the search reach
  auto earth_box = [&](int i, Vec3* lo, Vec3* hi) {
    const Vec3 centre = 0.5 * (bounds_min_[i] + bounds_max_[i]);
    const Vec3 half = 0.5 * (bounds_max_[i] - bounds_min_[i]);
    const Mat3 r = states_[i].rigid.Rotation();
    const Vec3 c = states_[i].rigid.position + r * centre;
    const Vec3 h = r.cwiseAbs() * half;
    *lo = c - h;
    *hi = c + h;
  };
  Vec3 alo, ahi, blo, bhi;
  earth_box(a, &alo, &ahi);
  earth_box(b, &blo, &bhi);
  const double reach = options_.search_backoff + options_.toofar_maximum;
  return (alo.array() <= bhi.array() + reach).all() && (blo.array() <= ahi.array() + reach).all();
}

void ContactEngine::SetRigidState(int i, const RigidState& rigid) {
  RequireBodyIndex(i, body_count(), "SetRigidState");
  RequireFiniteState(rigid, i);
  states_[i].rigid = rigid;
}

void ContactEngine::SetMotion(int i, MotionModel motion) {
  RequireBodyIndex(i, body_count(), "SetMotion");
  motions_[i] = motion;
}

StepResult ContactEngine::Step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("Step: dt must be finite and > 0");
  FloatModeScope float_mode;
  AccountWork();  // a step the host did not book itself
  const int n = body_count();
  StepResult result;
  // every pair whose bounds overlap, in the bodies' own order (determinism: fixed pair order)
  for (const auto& [a, b] : pair_order_) {
    const size_t ab = static_cast<size_t>(a) * n + b, ba = static_cast<size_t>(b) * n + a;
    if ((models_[a]->rigid && models_[b]->rigid) || !BoundsOverlap(a, b)) {
      pushed_[ab] = pushed_[ba] = Vec3::Zero();
      continue;
    }
    ++result.diagnostics.pairs_in_contact;
    auto& engaged = engaged_[ab];
    const int passes = options_.passes_per_step;
    std::vector<PassSums> sums(passes);
    PassSums rigid_nodes;  // a rigid body's nodes pushing the faces they crossed
    auto run = [&](int pass, int master, bool stage) {
      const int slave = master == a ? b : a;
      sums[pass] = RunPass(master, slave, stage, &engaged[slave == a ? 0 : 1], dt, &result.diagnostics);
    };
    if (models_[a]->rigid || models_[b]->rigid) {
      // a rigid body is always the master and takes none of the crush
      const int master = models_[a]->rigid ? a : b;
      for (int pass = 0; pass < passes; ++pass) run(pass, master, false);
      const int slave = master == a ? b : a;
      rigid_nodes = PushFacesOffRigidNodes(master, slave, engaged[slave == a ? 0 : 1], dt, &result.diagnostics);
    } else {
      // spec §1 swapping, simultaneously: each pair of passes lets both bodies, as slaves, find the
      // overlap against the other's surface as it was before the pair, each taking its
      // equal-pressure share (spec §5); both shares are committed together, so an overlap is
      // absorbed once and neither body's order or role is favoured
      int pass = 0;
      for (; pass + 1 < passes; pass += 2) {
        run(pass, b, true);
        run(pass + 1, a, true);
        CommitPending(a);
        CommitPending(b);
      }
      // an odd last pass: one side, alternating between steps (its master's share waits for the next)
      const int lead = LeadSlave(a, b);
      if (pass < passes) run(pass, (step_index_ % 2 == 0) == (lead == a) ? b : a, false);
      // determinism: the passes combined in an order the bodies set, not their listing (four passes
      // as [b, a, b, a] and [a, b, a, b] rounded their sums differently)
      std::stable_partition(sums.begin(), sums.end(), [&](const PassSums& p) { return p.slave == lead; });
    }
    const std::vector<double> weights = PassWeights(sums);
    result.pairs.push_back(CombinePasses(a, b, sums, weights, rigid_nodes));
    EndApproachWithinStep(&sums, weights, rigid_nodes, dt, &result.pairs.back());
    // the pair's normal impulse, each side in the other's frame
    const Vec3 on_a = result.pairs.back().normal_force[0] * dt;
    pushed_[ab] += states_[b].rigid.Rotation().transpose() * on_a;
    pushed_[ba] -= states_[a].rigid.Rotation().transpose() * on_a;
    PairFriction(sums, weights, dt, &result.pairs.back());
  }
  // spec §8 SumForcesMoments: resultants at each CG in the body frame
  std::vector<Vec3> force_earth(n, Vec3::Zero()), moment_earth(n, Vec3::Zero());
  for (const PairLoads& p : result.pairs) {
    for (int k = 0; k < 2; ++k) {
      force_earth[p.body[k]] += p.normal_force[k] + p.friction_force[k];
      moment_earth[p.body[k]] += p.normal_moment[k] + p.friction_moment[k];
    }
  }
  result.loads.resize(n);
  step_start_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Mat3 rt = states_[i].rigid.Rotation().transpose();
    result.loads[i].force_earth = force_earth[i];
    result.loads[i].force_body = rt * force_earth[i];
    result.loads[i].moment_body = rt * moment_earth[i];
    step_start_[i] = states_[i].rigid;
  }
  // the ledger books these loads once the host has moved the bodies
  unbooked_ = result.pairs;
  unbooked_dt_ = dt;
  ++step_index_;
  return result;
}

int ContactEngine::LeadSlave(int a, int b) const {
  // spec §1 swapping: the body that is the slave of an odd last pass on even steps, and whose passes
  // are combined first, chosen by the bodies, not by where they are listed (by list position, one
  // pass per step moved a side impact's delta-V 2 % when the two boxes were swapped in the file, an
  // 80 mph one 26 %): the finer mesh (more vertices: node-to-surface contact slaves the finer
  // surface), then the heavier body, then the name
  const BodyModel &ma = *models_[a], &mb = *models_[b];
  if (ma.mesh.vertices.size() != mb.mesh.vertices.size())
    return ma.mesh.vertices.size() > mb.mesh.vertices.size() ? a : b;
  if (ma.mass != mb.mass) return ma.mass > mb.mass ? a : b;
  return ma.name <= mb.name ? a : b;
}

void ContactEngine::AccountWork() {
  for (const PairLoads& p : unbooked_) {
    // work taken out of the rigid motion by the normal and the friction loads: power at the mean
    // velocities (the moment acted in the body axes of the step start)
    double normal = 0.0, friction = 0.0;  // [J]
    for (int k = 0; k < 2; ++k) {
      const RigidState& before = step_start_[p.body[k]];
      const RigidState& after = states_[p.body[k]].rigid;
      const Vec3 v = 0.5 * (before.velocity + after.velocity);
      const Vec3 w = before.Rotation() * (0.5 * (before.omega + after.omega));
      normal -= (p.normal_force[k].dot(v) + p.normal_moment[k].dot(w)) * unbooked_dt_;
      friction -= (p.friction_force[k].dot(v) + p.friction_moment[k].dot(w)) * unbooked_dt_;
    }
    // each side's share: a rigid side takes none; two deformable sides share the crush work as their
    // layers gave way at equal pressure over the step (spec §5, share_work: not as their node laws
    // booked it, which follows how finely each mesh's nodes resolve the other's share), and the
    // friction work evenly (heat at the common interface)
    // (each share from its own side's numbers, so listing the bodies the other way round books the same bits)
    const bool rigid[2] = {models_[p.body[0]]->rigid, models_[p.body[1]]->rigid};
    const double s0 = p.share_work[0], s1 = p.share_work[1];
    const bool by_share = !rigid[0] && !rigid[1] && s0 + s1 > 0.0;
    for (int k = 0; k < 2; ++k) {
      const double even = rigid[k] ? 0.0 : rigid[1 - k] ? 1.0 : 0.5;
      const double crush = by_share ? p.share_work[k] / (s0 + s1) : even;
      states_[p.body[k]].crush_energy += crush * normal;
      states_[p.body[k]].friction_energy += even * friction;
    }
  }
  unbooked_.clear();
}

std::vector<int> ContactEngine::CullCandidates(const PassFrame& f, int master, int slave_index,
                                               const EngagedNodes& engaged) {
  // slave nodes inside the master's bounds grown by the search reach, in chunks, in index order
  const double reach = options_.search_backoff + options_.toofar_maximum;
  const Vec3 lo = bounds_min_[master].array() - reach, hi = bounds_max_[master].array() + reach;
  const std::size_t nv = f.slave->vertices.size();
  const Mat3 abs_rotation = f.r_slave_to_master.cwiseAbs();
  const std::vector<Vec3>& box_min = chunk_min_[slave_index];
  const std::vector<Vec3>& box_max = chunk_max_[slave_index];
  std::vector<std::vector<int>> inside(ChunkCount(nv));
  ForEachChunk(nv, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    // a chunk whose box misses the master's is skipped whole
    const Vec3 centre = f.ToMaster(0.5 * (box_min[chunk] + box_max[chunk]));
    const Vec3 half = abs_rotation * (0.5 * (box_max[chunk] - box_min[chunk]));
    if (((centre + half).array() < lo.array()).any() || ((centre - half).array() > hi.array()).any()) return;
    for (std::size_t v = begin; v < end; ++v) {
      const Vec3 p = f.ToMaster(f.slave->vertices[v]);
      if ((p.array() >= lo.array()).all() && (p.array() <= hi.array()).all()) {
        inside[chunk].push_back(static_cast<int>(v));
      }
    }
  });
  // plus the nodes engaged with the master at their last update (they may have left the bounds)
  std::vector<int> culled, with_touching, merged;
  for (const auto& list : inside) culled.insert(culled.end(), list.begin(), list.end());
  std::set_union(culled.begin(), culled.end(), engaged.touching.begin(), engaged.touching.end(),
                 std::back_inserter(with_touching));
  std::set_union(with_touching.begin(), with_touching.end(), engaged.holding.begin(), engaged.holding.end(),
                 std::back_inserter(merged));
  return merged;
}

void ContactEngine::ProcessNode(const PassFrame& f, int v, Engagement engagement, double dt, ChunkSums* out) {
  // locate, then restore and evaluate the node law
  const bool was_touching = engagement == Engagement::kTouching;
  Located hit;
  bool found = LocateNode(f, v, was_touching, nullptr, &out->scratch, &hit);
  // spec §2 Location, velocity search: a node in contact with a rigid master whose line found nothing
  // also looks along the line turned the other way, for a face on the plane it was pressed on. The
  // line is turned to point into the slave by the node's own normal, which on a yawing body's
  // unevenly crushed front tilts past the motion and turned it out of the wall: the eccentric box lost
  // its rebound (impact-point restitution 0.035 for 0.3)
  if (!found && was_touching && f.master_model->rigid && options_.search_direction == SearchDirection::kVelocity) {
    const Vec3 reverse = -SearchLine(f, v, hit.rel_velocity, -(f.r_slave_to_master * f.slave->vertex_normal[v]));
    const Vec3 pressed_on = f.r_slave_to_master * f.slave->contact_normal[v];
    Located again;
    if (reverse.squaredNorm() > 0.0 && LocateNode(f, v, was_touching, &reverse, &out->scratch, &again) &&
        again.normal.dot(pressed_on) > kSamePlane) {
      found = true;
      hit = again;
    }
  }
  // spec §2 Location: against a rigid master (its surface does not move in its frame) a node in
  // contact entered through the face it is pressed on; the method's line can cross another face past
  // a corner (a pole's side, behind a node pressed on its front) and load the node sideways with its
  // whole crush. It also searches along the normal of the face it was pressed on and takes the
  // shallower find, the shorter way out. (A deformable master moves its own nodes in the sibling
  // pass: tried there, it moved the car-to-car results by up to 5 %.)
  if (f.master_model->rigid && found && was_touching && options_.search_direction != SearchDirection::kPolyNormal) {
    const Vec3 pressed_on = f.r_slave_to_master * f.slave->contact_normal[v];
    Located again;
    if (LocateNode(f, v, was_touching, &pressed_on, &out->scratch, &again) && again.depth < hit.depth) hit = again;
  }
  if (found) ++out->diag.located;
  // a node that found a rigid master closing on it, or lies behind its surface: its own contact takes
  // the faces round it from the master's nodes (PushFacesOffRigidNodes; no other pass reads it)
  if (f.master_model->rigid && found && (hit.rel_velocity.dot(hit.normal) < 0.0 || hit.depth > 0.0))
    out->located.push_back(v);
  if (!found && engagement == Engagement::kNone) return;
  // whether the bodies still close on a node that found no face: along its last contact normal, or,
  // holding a spring, along its crush (the line the master pressed it along). spec §6: a held node
  // keeps its spring only while the master still comes at it; once it moves away from the master
  // along that line the load is gone and it springs back freely, as a touching node does when the
  // bodies part. (Kept stored, the spring pushed on whatever face came near it later: the offset
  // frontal's crushed fronts rubbed for 1.4 s after the main pulse and turned the p406's yaw rate
  // from 42 to 23 deg/s. The pair's normal impulse as the line released nodes that rotation carried
  // away during the main pulse: 2.0 % on the offset's delta-V with the p406 mesh 1:4)
  const Vec3& line = engagement == Engagement::kHolding ? f.slave->delta[v] : f.slave->contact_normal[v];
  const bool closing_unfound = !found && hit.rel_velocity.dot(f.r_slave_to_master * line) < 0.0;
  // spec §6: such a node pressed on a rigid master (whose surface does not move in its frame) slid
  // past the face's edge: it springs back at most to the master's nearest surface; it cannot spring
  // away from a surface that approaches it. (Springing its whole e delta_max at once left it up to
  // 0.65 in outside a surface still closing on it.) Bodies that part let it spring freely
  double free_gap = INFINITY;
  if (closing_unfound && f.master_model->rigid)
    free_gap = DistanceToMaster(f, v, f.slave_model->restitution * f.slave->delta_max[v], &out->scratch);
  Vec3 delta;
  bool holding = false;
  LayerShare layers;
  double turn_force = 0.0;
  const double node_force = RestoreNode(f, v, found ? &hit : nullptr, closing_unfound, free_gap, dt, &out->diag,
                                        &out->sums.law_energy, &delta, &holding, &layers, &turn_force);
  if (delta != f.slave->delta[v]) {
    // the new crush waits in pending_delta_ until committed (with the sibling pass, or at once)
    (*f.pending)[v] = delta;
    out->moved.push_back(v);
  }
  // the contact normal a touching node keeps (slave frame); none once it lets go
  f.slave->contact_normal[v] = node_force > 0.0 ? Vec3(f.r_slave_to_master.transpose() * hit.normal) : Vec3::Zero();
  if (holding) out->holding.push_back(v);
  if (node_force <= 0.0) return;
  out->touching.push_back(v);
  ++out->diag.touching;

  // both bodies are loaded at the same point, the slave node where it now is (momentum and angular
  // momentum conserved to round-off)
  const Vec3 node = f.slave_model->mesh.vertices[v] + delta;
  const Vec3 arm_slave = f.r_slave * node;
  const Vec3 arm_master = f.r_master * f.ToMaster(node);
  // determinism: within a chunk, sums run in ascending node order
  out->sums.touching_area += f.slave->node_area[v];
  // normal force along the master surface normal: without friction there is no tangential force
  const Vec3 normal_earth = f.r_master * hit.normal;
  out->sums.normal.Add(node_force * normal_earth, arm_slave, arm_master);
  // spec §7 SlaveNodeFriction acts here, mu times the normal force (its direction once the pair's
  // normal loads are known: PairFriction); spec §6 the loading force ends where the approach does
  // (EndApproachWithinStep)
  if (f.mu > 0.0 || options_.turn_within_step)
    out->points.push_back({arm_slave, arm_master, normal_earth, node_force, turn_force});
  // spec §5, two crushable layers in series: the interface's work over the step, force times the
  // approach, splits as the layers share a closure at equal pressure (the master's part is its crush
  // at the node, whether or not its own nodes reach the point)
  if (!f.master_model->rigid) {
    const double work = node_force * std::abs(hit.rel_velocity.dot(hit.normal)) * dt;
    out->sums.slave_share_work += layers.slave_part * work;
    out->sums.master_share_work += (1.0 - layers.slave_part) * work;
    // the master's share of the node's penetration, the crush its own nodes have to take there
    out->sums.master_share_force += node_force;
    out->sums.master_share_moment += node_force * (std::max(hit.depth, 0.0) - layers.slave_push);
  }
}

LayerShare ContactEngine::LayersAtNode(const PassFrame& f, int v, const Located& hit) const {
  // the node's law and its crush at the step's start, the face's corners' law and mean crush
  const MasterLayer m = MasterLayerAt(*f.master_model, *f.master, f.master_model->mesh.triangles[hit.triangle]);
  return ShareAtEqualPressure(f.slave_model->VertexStiffness(v), f.slave->delta[v].norm(), m.k, m.deflection,
                              std::max(hit.depth, 0.0), options_.null_band);
}

ContactEngine::PassFrame ContactEngine::FrameOf(int master, int slave) {
  PassFrame f{models_[master].get(), models_[slave].get(), &states_[master], &states_[slave],
              locators_[master].get(), states_[master].rigid.Rotation(), states_[slave].rigid.Rotation(),
              Mat3::Identity(), Vec3::Zero(), &pending_delta_[slave],
              0.5 * (models_[master]->friction + models_[slave]->friction),
              pushed_[static_cast<size_t>(slave) * body_count() + master].normalized()};
  f.r_slave_to_master = f.r_master.transpose() * f.r_slave;
  f.t_slave_to_master = f.r_master.transpose() * (f.slave->rigid.position - f.master->rigid.position);
  return f;
}

ContactEngine::PassSums ContactEngine::RunPass(int master, int slave, bool stage, EngagedNodes* engaged, double dt,
                                              ContactDiagnostics* diag) {
  const PassFrame f = FrameOf(master, slave);

  const std::vector<int> candidates = CullCandidates(f, master, slave, *engaged);
  diag->candidates += static_cast<long long>(candidates.size());
  locators_[master]->Prepare(slave, step_index_, candidates,
                             [&](int v) { return f.ToMaster(f.slave->vertices[v]); });

  // one parallel loop over fixed chunks of candidates; each chunk writes its own nodes and partials
  chunks_.resize(std::max(chunks_.size(), ChunkCount(candidates.size())));
  // nodes engaged at their last update, marked for constant-time look-up
  std::vector<Engagement>& mark = engaged_mark_[slave];
  mark.resize(f.slave->vertices.size(), Engagement::kNone);
  for (int v : engaged->touching) mark[v] = Engagement::kTouching;
  for (int v : engaged->holding) mark[v] = Engagement::kHolding;
  ForEachChunk(candidates.size(), [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    ChunkSums& out = chunks_[chunk];
    out.Clear();
    for (std::size_t i = begin; i < end; ++i) ProcessNode(f, candidates[i], mark[candidates[i]], dt, &out);
  });
  for (int v : engaged->touching) mark[v] = Engagement::kNone;
  for (int v : engaged->holding) mark[v] = Engagement::kNone;

  // determinism: partial sums and node lists folded serially in chunk order
  PassSums sums;
  sums.master = master;
  sums.slave = slave;
  std::vector<int> now_touching, now_holding, now_located, moved;
  // each list sized once (the chunks' points run to tens of thousands on a car's front)
  std::size_t points = 0, touching = 0, holding = 0, located = 0, moved_count = 0;
  for (std::size_t c = 0; c < ChunkCount(candidates.size()); ++c) {
    points += chunks_[c].points.size();
    touching += chunks_[c].touching.size();
    holding += chunks_[c].holding.size();
    located += chunks_[c].located.size();
    moved_count += chunks_[c].moved.size();
  }
  sums.points.reserve(points);
  now_touching.reserve(touching);
  now_holding.reserve(holding);
  now_located.reserve(located);
  moved.reserve(moved_count);
  for (std::size_t c = 0; c < ChunkCount(candidates.size()); ++c) {
    const ChunkSums& part = chunks_[c];
    sums.normal += part.sums.normal;
    sums.points.insert(sums.points.end(), part.points.begin(), part.points.end());
    sums.touching_area += part.sums.touching_area;
    sums.law_energy += part.sums.law_energy;
    sums.slave_share_work += part.sums.slave_share_work;
    sums.master_share_work += part.sums.master_share_work;
    sums.master_share_force += part.sums.master_share_force;
    sums.master_share_moment += part.sums.master_share_moment;
    diag->Add(part.diag);
    now_touching.insert(now_touching.end(), part.touching.begin(), part.touching.end());
    now_holding.insert(now_holding.end(), part.holding.begin(), part.holding.end());
    now_located.insert(now_located.end(), part.located.begin(), part.located.end());
    moved.insert(moved.end(), part.moved.begin(), part.moved.end());
  }
  engaged->touching = std::move(now_touching);
  engaged->holding = std::move(now_holding);
  engaged->located = std::move(now_located);
  f.slave->law_energy += sums.law_energy;

  // crushed nodes change the slave's triangles, bounds and search structure (refit), now or after
  // the sibling pass
  moved_[slave] = std::move(moved);
  if (!stage) CommitPending(slave);
  return sums;
}

void ContactEngine::CommitPending(int body) {
  BodyState& s = states_[body];
  const std::vector<int>& moved = moved_[body];
  if (moved.empty()) return;
  for (int v : moved) {
    s.delta[v] = pending_delta_[body][v];
    s.vertices[v] = models_[body]->mesh.vertices[v] + s.delta[v];
  }
  UpdateTriangles(*models_[body], moved, &s);
  GrowBounds(body, moved);
  locators_[body]->Update(s.vertices, moved);
  moved_[body].clear();
}

std::vector<double> ContactEngine::PassWeights(const std::vector<PassSums>& sums) {
  // each pass estimates the whole interface load from its slave's nodes; estimates are weighted by
  // the contact area the slave saw, so a side whose mesh cannot resolve the contact counts less
  double area = 0.0;
  for (const PassSums& p : sums) area += p.touching_area;
  std::vector<double> weights(sums.size(), 0.0);
  if (area <= 0.0) return weights;
  for (std::size_t i = 0; i < sums.size(); ++i) weights[i] = sums[i].touching_area / area;
  return weights;
}

PairLoads ContactEngine::CombinePasses(int a, int b, const std::vector<PassSums>& sums,
                                       const std::vector<double>& weights, const PassSums& rigid_nodes) const {
  PairLoads out;
  out.body[0] = a;
  out.body[1] = b;
  int slave_passes[2] = {0, 0};
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const PassSums& p = sums[i];
    const int ks = p.slave == a ? 0 : 1, km = 1 - ks;
    out.law_energy[ks] += p.law_energy;
    out.contact_area[ks] += p.touching_area;
    ++slave_passes[ks];
    const double w = weights[i];
    out.share_work[ks] += w * p.slave_share_work;
    out.share_work[km] += w * p.master_share_work;
    p.normal.AddToPair(w, ks, out.normal_force, out.normal_moment);
  }
  // a rigid body's nodes loaded faces no pass's nodes held: their loads add whole; the node-law work
  // is on the deformable side (the master of those pushes)
  const int ks = rigid_nodes.slave == a ? 0 : 1, km = 1 - ks;
  out.law_energy[km] += rigid_nodes.law_energy;
  rigid_nodes.normal.AddToPair(1.0, ks, out.normal_force, out.normal_moment);
  // each side's own view of the contact area: what its nodes met, per pass
  for (int k = 0; k < 2; ++k)
    if (slave_passes[k] > 0) out.contact_area[k] /= slave_passes[k];
  // each deformable master's share of the other's penetrations, over the passes it was the master in
  double share_force[2] = {0.0, 0.0}, share_moment[2] = {0.0, 0.0};
  for (const PassSums& p : sums) {
    const int km = p.master == a ? 0 : 1;
    share_force[km] += p.master_share_force;
    share_moment[km] += p.master_share_moment;
  }
  for (int k = 0; k < 2; ++k)
    if (share_force[k] > 0.0) out.untaken_share[k] = share_moment[k] / share_force[k];
  return out;
}

bool ContactEngine::ExamineTriangle(const PassFrame& f, const Candidate& candidate, const Vec3& p,
                                    const Vec3& ray_dir, const Vec3& facing, int faces_of,
                                    const Vec3& previous, const Vec3& parting, bool poly_normal,
                                    const Located* best, Located* out) const {
  const int t = candidate.triangle;
  const auto& tri = f.master_model->mesh.triangles[t];
  const Vec3& a = f.master->vertices[tri[0]];
  const Vec3& b = f.master->vertices[tri[1]];
  const Vec3& c = f.master->vertices[tri[2]];
  const Vec3& n = f.master->tri_normal[t];
  const Vec3 d = poly_normal ? n : ray_dir;
  // the node must lie behind the face: the pushback leaves the master through it
  if (d.dot(n) <= kMinFacing) return false;
  // the two surfaces face each other: the master's outward normal points into the slave
  const bool faces = n.dot(facing) > kMinFacing || (faces_of >= 0 && CornerMeetsFace(f, faces_of, t));
  if (!faces || n.dot(previous) < 0.0 || n.dot(parting) < 0.0) return false;
  // the depth along the ray and the spec §2 inside test, unless the locator proved it with margin
  double depth = 0.0;
  if (!CandidateCrossing(p, d, -options_.search_backoff, options_.toofar_maximum, a, b, c, n,
                         candidate.inside && !poly_normal, &depth))
    return false;
  // best = smallest |depth| along the ray; ties keep the earlier (lower-index) triangle
  if (best == nullptr || std::abs(depth) < std::abs(best->ray_depth)) {
    out->triangle = t;
    out->ray_depth = depth;
    out->depth = (a - p).dot(n);
    out->normal = n;
  }
  return true;
}

bool ContactEngine::CornerMeetsFace(const PassFrame& f, int v, int t) const {
  // spec §2 Location, the surfaces face each other: a node on an edge or a corner meets a face that any
  // one of its own faces turns toward (those faces carry its area: ContactNodeArea), though its mean
  // normal, leaning toward its larger faces, may turn away from it. Only a face longer than the slave's
  // node spacing (its mesh's median edge) and the node's own faces: a finer master's own nodes push the
  // faces they cross at the corner (the rigid body as slave, spec §1 swapping), and taking such faces
  // too, the car's crease nodes met the 1.7 in facets of a frictionless round pole and slid round it
  // (5 in off its axis 15.9 mph delta-V of 20, under the test's 19.8; centred, 28 % of the relative
  // motion's energy created)
  const auto longest_edge = [](const Vec3& x, const Vec3& y, const Vec3& z) {
    return std::max({(x - y).norm(), (y - z).norm(), (z - x).norm()});
  };
  const auto& tri = f.master_model->mesh.triangles[t];
  const std::vector<Vec3>& at = f.master->vertices;
  const double face_size = longest_edge(at[tri[0]], at[tri[1]], at[tri[2]]);
  if (face_size <= f.slave_model->median_edge) return false;
  const Vec3 n_slave = f.r_slave_to_master.transpose() * f.master->tri_normal[t];
  const auto& adj = f.slave_model->vertex_triangles;
  bool turned_toward = false;
  for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k) {
    const auto& own = f.slave_model->mesh.triangles[adj.ids[k]];
    if (longest_edge(f.slave->vertices[own[0]], f.slave->vertices[own[1]], f.slave->vertices[own[2]]) >= face_size)
      return false;
    turned_toward = turned_toward || -f.slave->tri_normal[adj.ids[k]].dot(n_slave) > kMinFacing;
  }
  return turned_toward;
}

Vec3 ContactEngine::SearchLine(const PassFrame& f, int v, const Vec3& v_rel, const Vec3& inward) const {
  // the search method's direction (spec §2), master frame, pointing into the slave; none for the
  // polygon normal (it searches along each triangle's own)
  switch (options_.search_direction) {
    case SearchDirection::kVelocity:
      // along the line of relative motion, turned to point into the slave (also while separating)
      if (const double speed = v_rel.norm(); speed > kStillSpeed) {
        const Vec3 dir = v_rel / speed;  // v_rel.normalized(), its norm taken once
        return dir.dot(inward) < 0.0 ? Vec3(-dir) : dir;
      }
      [[fallthrough]];  // no relative motion: fall back to the local normal
    case SearchDirection::kLocalAverageNormal:
      return -(f.r_slave_to_master * LocalAverageNormal(*f.slave_model, *f.slave, v));
    case SearchDirection::kSpecified:
      return f.r_slave_to_master * options_.specified_direction.normalized();
    case SearchDirection::kPolyNormal:
      break;
  }
  return Vec3::Zero();
}

bool ContactEngine::LocateNode(const PassFrame& f, int v, bool was_touching, const Vec3* along,
                               std::vector<Candidate>* tris, Located* out) const {
  const Vec3& p_slave = f.slave->vertices[v];
  const Vec3 p = f.ToMaster(p_slave);
  const Vec3 v_rel = f.RelativeVelocity(p_slave, p);
  out->rel_velocity = v_rel;  // also when nothing is found (the spring-back asks whether the bodies close)
  const double backoff = options_.search_backoff, reach = options_.toofar_maximum;

  // the slave's inward side at the node, master frame (the surfaces must face each other)
  const Vec3 inward = -(f.r_slave_to_master * f.slave->vertex_normal[v]);
  // a node in contact keeps meeting faces turned the same way (it left the last one through its
  // outside): a crushed-through panel's inner face does not take over and pull it in
  const Vec3 previous = was_touching ? Vec3(f.r_slave_to_master * f.slave->contact_normal[v]) : Vec3::Zero();
  // spec §2 Location: against a deformable master, such a node is held to the faces turned like the
  // one it was pressed on, not to its own normal, which the crush turns: the faces round a crushed
  // node fold, and a node on a ledge or a curve faces the master at a grazing angle to begin with (on
  // a 40 mph rear-end the p406's grille nodes, 1 in inside the stock car's bumper panel, tipped to face
  // along it and were dropped, 7-9 % of the touching nodes' updates on the demos: the cars closed 62 in
  // for 36 in of crush). Not with the local-average-normal search, whose line is the node's own
  // normal (the two would disagree on which way the node faces), nor against a rigid master, which the
  // node also meets along the face it was pressed on (ProcessNode; held there too, the frictionless
  // round pole let the car through: 17.3 mph of 20)
  const bool keeps_face = was_touching && !f.master_model->rigid &&
                          options_.search_direction != SearchDirection::kLocalAverageNormal;
  const Vec3 facing = keeps_face ? previous : inward;
  // spec §2 Location: a node's corner faces may meet a rigid face its mean normal turns away from
  // (CornerMeetsFace). Before, a box's front corner, its side faces larger than its front ones, went
  // into a block turned 45 deg unfound, and the box passed the block (3.4-3.6 of 8 mph delta-V).
  // For nodes not yet in contact, whose crush has not turned their faces, and where a line chooses the
  // face (velocity, specified): the local-average-normal search's line is the node's mean normal, and
  // the polygon-normal search, trying each face near the node along the face's own normal, pushed the
  // corner out through the block's far side (README known limits). Not against deformable masters:
  // there the car pair's peak force rose 19 %, inner panels meeting the other car's faces
  const bool line_search = options_.search_direction == SearchDirection::kVelocity ||
                           options_.search_direction == SearchDirection::kSpecified;
  const int faces_of = !was_touching && f.master_model->rigid && line_search ? v : -1;
  // spec §2 Location: while the node moves out along the normal impulse this contact has given its
  // body, a face that would push it back in is the far side of material it went through (a door's
  // inner panel, left standing while the outer one was crushed past it, caught the withdrawing car
  // and held the bodies together: 600 lbf of pull for 0.3 s on the 45 deg demo). Approaching nodes
  // keep every face: a crushed zone's folds turn faces against the impulse
  const Vec3 parting = v_rel.dot(f.pushed) > 0.0 ? f.pushed : Vec3::Zero();
  // search direction (spec §2), pointing into the slave: it chooses the face; the push follows the face normal
  const Vec3 dir = along ? *along : SearchLine(f, v, v_rel, inward);
  const bool poly_normal = !along && options_.search_direction == SearchDirection::kPolyNormal;
  if (!poly_normal && dir.squaredNorm() == 0.0) return false;

  // candidate master triangles from the locator, examined in triangle order (DyMESH surface lists)
  tris->clear();
  const Vec3 origin = p - backoff * dir;
  if (poly_normal) {
    f.master_locator->TrianglesNearPoint(v, p, std::max(backoff, reach), tris);
  } else {
    f.master_locator->TrianglesAlongSegment(v, origin, dir, backoff + reach, tris);
  }
  // determinism: by triangle index, each triangle once (kept as proven inside if any copy was)
  if (tris->size() > 1) {
    std::sort(tris->begin(), tris->end(), [](const Candidate& x, const Candidate& y) {
      return x.triangle != y.triangle ? x.triangle < y.triangle : x.inside > y.inside;
    });
    tris->erase(std::unique(tris->begin(), tris->end(),
                            [](const Candidate& x, const Candidate& y) { return x.triangle == y.triangle; }),
                tris->end());
  }

  // exact test of each candidate in triangle order, with the stop rule
  const int wanted = options_.stop_rule == StopRule::kAfterOne ? 1
                     : options_.stop_rule == StopRule::kBestOfTwo ? 2 : INT32_MAX;
  int accepted = 0;
  for (const Candidate& c : *tris) {
    const Located* best = accepted == 0 ? nullptr : out;
    if (ExamineTriangle(f, c, p, dir, facing, faces_of, previous, parting, poly_normal, best, out) &&
        ++accepted >= wanted)
      break;
  }
  // between two deformable bodies, the face's rest normal where the crush tipped it (contact_normal
  // conforming, the default)
  if (accepted > 0 && options_.contact_normal == ContactNormal::kConforming && !f.master_model->rigid &&
      !f.slave_model->rigid)
    out->normal = ConformingNormal(f, v, out->triangle, out->normal);
  return accepted > 0;
}

double ContactEngine::DistanceToMaster(const PassFrame& f, int v, double radius,
                                       std::vector<Candidate>* scratch) const {
  // the nearest point of the master's triangles that come within the radius (master frame)
  const Vec3 p = f.ToMaster(f.slave->vertices[v]);
  scratch->clear();
  f.master_locator->TrianglesNearPoint(v, p, radius, scratch);
  double nearest = INFINITY;
  for (const Candidate& c : *scratch) {
    const auto& tri = f.master_model->mesh.triangles[c.triangle];
    const Vec3 q = ClosestPointOnTriangle(p, f.master->vertices[tri[0]], f.master->vertices[tri[1]],
                                          f.master->vertices[tri[2]]);
    nearest = std::min(nearest, (q - p).norm());
  }
  return nearest <= radius ? nearest : INFINITY;
}

double ContactEngine::RestoreNode(const PassFrame& f, int v, const Located* hit, bool closing_unfound,
                                  double free_gap, double dt,
                                  ContactDiagnostics* diag, double* law_energy, Vec3* new_delta, bool* holding,
                                  LayerShare* layers_out, double* turn_force) {
  BodyState& s = *f.slave;
  const BodyModel& m = *f.slave_model;
  const Stiffness& k = m.VertexStiffness(v);
  const double e = m.restitution;
  const UnloadState state = s.unload[v];
  const bool can_spring = state == UnloadState::kStartUnload || state == UnloadState::kCanUnload ||
                          state == UnloadState::kNowUnloading;
  if (s.update_step[v] != step_index_) {
    s.update_step[v] = step_index_;
    s.step_start_deflection[v] = s.delta[v].norm();
  }
  const double deflection = s.delta[v].norm();
  Vec3 delta = s.delta[v];
  *new_delta = delta;
  bool touching = false;
  bool held = false;
  std::optional<LayerShare> layers;       // the node's and a deformable master's layers, solved once
  double interface_pressure = INFINITY;  // the most the node presses against a deformable master
  // the master's outward normal in the slave frame: the node is pushed out of the master along it,
  // the way a frictionless surface pushes (no sideways drag whatever the search direction)
  const Vec3 normal_slave = hit ? Vec3(f.r_slave_to_master.transpose() * hit->normal) : Vec3::Zero();

  // the surfaces' relative motion along the normal over the step (> 0: the slave node leaves the master)
  // spec §1 swapping: a node an earlier pass pair of this step pushed onto a deformable master's face,
  // found again in front of it by less than that push, still touches it. The bodies have not moved
  // since; the gap is the pair's interpolation (the face's corners took their own nodes' shares), not
  // a parting. (Held there, a second pair saw only the nodes the gap happened to miss: two boxes of A
  // 300 and 600 lb/in crushed 23 % deeper with four passes than with two, their node laws 17 % over
  // the contact work)
  const double pushed_this_step = deflection - s.step_start_deflection[v];
  const double touch_gap = f.master_model->rigid ? 0.0 : std::max(pushed_this_step, 0.0);
  const bool inside = hit && hit->depth >= -std::max(options_.contact_tolerance, touch_gap);
  const double receding = hit ? hit->rel_velocity.dot(hit->normal) * dt : 0.0;  // [m]
  if (inside && receding <= 0.0) {
    // spec §5: two deformable sides split the penetration so their law pressures are equal (theta
    // is the first estimate); the master triangle's stiffness and deflection are its corners'
    // averages; the master's share is taken by its own nodes in the sibling pass; a rigid master
    // takes none
    const double depth = std::max(hit->depth, 0.0);
    double push = depth;
    if (!f.master_model->rigid) {
      layers = LayersAtNode(f, v, *hit);
      push = layers->slave_push;
      // spec §5's purpose, one force through two layers in series: a node whose law is flat where the
      // share leaves it (null band, saturation) holds and carries the master layer's pressure, not its
      // own (pressing with its own A, a box ten times stiffer than the one striking it made the pair
      // twice as stiff: the striking box kept 2.5 in of crush where against a wall it keeps 6.95)
      interface_pressure = layers->max_pressure;
    }
    // spec §2 PushbackReduction (version 4 only): withhold a fraction, at most PUSHBACK_REDUCE_LIMIT
    if (options_.version == 4 && push > 0.0) {
      push -= std::min(push * options_.pushback_reduction, options_.pushback_reduce_limit);
      ++diag->reduced;
    }
    // spec §2 TOOFAR_MARGIN: no restoring farther than the relative motion of a step plus the margin
    const double too_far = hit->TooFar(dt, options_.toofar_margin);
    if (push > too_far) {
      push = too_far;
      ++diag->too_far_limited;
    }
    // Maximum Crush (spec §4 dialog): the node bottoms out
    if (k.max_crush > 0.0 && deflection + push > k.max_crush) {
      push = std::max(k.max_crush - deflection, 0.0);
      ++diag->max_crush_limited;
    }
    // spec §6 MAX_GROW_UNLOAD: a node reloading below its peak grows per step at most by the surfaces'
    // approach along the normal plus this allowance, as TOOFAR bounds a push by the step's motion plus
    // a margin (a bare 0.25 in per step is a reload speed that halves when the step doubles: coarse
    // steps left reloading nodes lagging inside the master on their weak rebound curve)
    if (state == UnloadState::kNowUnloading || state == UnloadState::kFinishedUnloading) {
      const double approach = -receding;  // >= 0 here: the surfaces close
      const double cap =
          std::max(s.step_start_deflection[v] + approach + options_.max_grow_unload - deflection, 0.0);
      if (push > cap) {
        push = cap;
        ++diag->growth_limited;
      }
    }
    // spec §7 in the node's motion: the node also sticks where it touched, within the friction cone,
    // taking back its share (push / depth) of the step's slide over the face. Against a rigid master
    // (which takes the whole push) pushed only along the normal, nodes slid round an off-centre round
    // pole with the car: the p406 at 20 mph lost 0.35 mph to a pole 5 in off its axis, 21 mph centred.
    // Between two deformable bodies each side's nodes take back their share, so the crushing fronts
    // grip as a whole: pushed along the faces' normals alone, they slid over each other's crushed
    // faces, tilted differently on each mesh: the side demo's yaw rates after the contact moved -24 %
    // (the p406) and +4 % (the struck car) under dt/2 over 16 starts; with the stick within 3 %
    const Vec3 stick =
        StickingCorrection(AlongSurface(hit->rel_velocity, hit->normal) * dt, push, depth, f.mu);
    delta += push * normal_slave + f.r_slave_to_master.transpose() * stick;
    touching = true;
  } else if ((hit ? receding < 0.0 : closing_unfound) && !f.master_model->rigid) {
    // spec §6: a node before a deformable master's face that still closes on it, or that found no
    // face while the bodies close on it (along its last contact normal, or its crush while it holds
    // a spring: ProcessNode), is held: the master's own crush moved the face, or the node lies over a
    // gap between the display mesh's panels. No force, no spring, its branch of the law kept until the
    // face reaches it; it springs back when the surfaces part. (Unloading it put it on the rebound
    // curve, 10 % of the loading force at e = 0.1, reloaded from below its peak: on a 30 mph rear-end
    // the real car meshes closed 47.8 in for 28.6 in of crush along the line of centres)
    held = true;
    if (can_spring && deflection > 0.0) ++diag->held_unfound;  // counted where it keeps a crush from springing
  } else if (can_spring && deflection > 0.0) {
    // spec §6 unloading: the node springs back toward the receding surface, at most to (1-e) delta_max;
    // a node still inside a receding surface (an overlap a step left over) follows it by its motion,
    // and one in front of a face springs at most to the face's plane, once per step however many passes
    // meet it (a second pass against the same master used to spring it again: twice the surface's
    // motion, or twice the gap when the spring, along the crush, did not close it)
    const double sprung = std::max(s.step_start_deflection[v] - deflection, 0.0);
    const double gap = !hit ? free_gap : std::max((inside ? receding : -hit->depth) - sprung, 0.0);
    const double available = std::max(deflection - (1.0 - e) * s.delta_max[v], 0.0);
    const double spring = std::min(gap, available);
    // spec §6: the spring runs back along the crush; it meets the face only if it runs toward it (the
    // crush has a part along the face's outward normal): a node springing along a face 0.2 in beside
    // it stays off it and carries no rebound force
    const bool toward = hit && delta.dot(normal_slave) > kMinFacing * deflection;
    delta *= (deflection - spring) / deflection;
    touching = toward && gap <= available;
  }

  // NaN guard: a non-finite update is counted and dropped
  const double new_deflection = delta.norm();
  if (!std::isfinite(new_deflection)) {
    ++diag->non_finite;
    return 0.0;
  }

  // spec §6: DeltaMaxTotal, the unloading state machine and the node law
  const double peak = s.delta_max[v];
  s.delta_max[v] = std::max(s.delta_max[v], new_deflection);
  if (!held) s.unload[v] = NextUnloadState(state, touching, new_deflection, s.delta_max[v], e, options_);
  // spec §3 A_v: a touching node's faces are measured from the master's plane at least the contact
  // tolerance beyond the node, so a face pressed flush on the master (rest corners on its plane to
  // round-off, as a layer held in its null band is after the sibling pass took the overlap) counts
  // whole. (Measured at the node's own depth, such faces counted by the sign of 1e-14 in: with three
  // or four passes the later passes of a pair where one side held saw a tenth of the interface and
  // the softer box, its force underestimated, crushed up to 6 % deeper, its node law up to 6 % over
  // the work; with the polygon-normal search 40 % and 52 %)
  const double area_depth = std::max(hit ? hit->depth : 0.0, options_.contact_tolerance);
  const double area = touching ? ContactNodeArea(m, s, v, normal_slave, area_depth) : s.node_area[v];
  const double force =
      touching ? area * std::min(NodePressure(s.unload[v], true, k, new_deflection, s.delta_max[v], e, options_),
                                 interface_pressure)
               : 0.0;
  // spec §6: a node on its loading curve carries that force while the surfaces approach; once they
  // stop, its rebound force from the peak it reached (none while it cannot unload yet). The pair turns
  // it there (EndApproachWithinStep)
  *turn_force = force;
  const UnloadState now = s.unload[v];
  if (options_.turn_within_step && force > 0.0 &&
      (now == UnloadState::kCannotUnload || now == UnloadState::kStartUnload || now == UnloadState::kCanUnload)) {
    const double rebound = now == UnloadState::kCannotUnload
                               ? 0.0
                               : ReboundPressure(k, new_deflection, s.delta_max[v], e, options_.null_band,
                                                 options_.rebound_law);
    *turn_force = std::min(force, area * std::min(rebound, interface_pressure));
  }
  // spec §5: the slave's part of the interface's work where it touches a deformable master
  if (touching && !f.master_model->rigid) *layers_out = layers ? *layers : LayersAtNode(f, v, *hit);

  // work of the node law over the deflection change, then commit the new position
  *law_energy += area * NodeLawWork(k, deflection, new_deflection, peak, e, options_);
  s.node_force[v] = force;
  s.node_area[v] = area;
  *new_delta = delta;
  *holding = held && can_spring && new_deflection > (1.0 - e) * s.delta_max[v];
  return force;
}

}  // namespace dymesh
