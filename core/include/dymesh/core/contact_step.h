#pragma once
#include <array>
#include <memory>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/crush_sharing.h"
#include "dymesh/core/locator.h"
#include "dymesh/core/options.h"
#include "dymesh/core/rigid_body.h"

/// The DyMESH contact step (spec §2, §3, §5, §6, §7, §8): Location, Restoration, node forces,
/// friction and sums to each CG, for every pair of bodies whose bounds overlap.
namespace dymesh {

/// Collision force and moment on one body at its CG (spec §8, SumForcesMoments).
struct CgLoads {
  Vec3 force_earth{0, 0, 0};   ///< [N] earth frame
  Vec3 force_body{0, 0, 0};    ///< [N] body frame (SumForce)
  Vec3 moment_body{0, 0, 0};   ///< [N m] about the CG, body frame (SumMoment)
};

/// Per-step counts of what Location and Restoration met (reported, never thrown).
struct ContactDiagnostics {
  long long candidates = 0;        ///< slave nodes inside the master's bounds
  long long located = 0;           ///< slave nodes matched to a master triangle
  long long touching = 0;          ///< located nodes carrying force
  long long too_far_limited = 0;   ///< restorations cut by the TOOFAR margin
  long long max_crush_limited = 0; ///< restorations cut by the maximum crush
  long long growth_limited = 0;    ///< reloads cut by MAX_GROW_UNLOAD
  long long held_unfound = 0;      ///< crushed nodes held (no force, no spring) while a deformable master closed on them
  long long reduced = 0;           ///< restorations reduced by PushbackReduction (version 4)
  long long non_finite = 0;        ///< node updates skipped by the NaN guard
  long long faces_pushed = 0;      ///< rigid nodes that pushed a deformable face they crossed
  int pairs_in_contact = 0;        ///< pairs whose bounds overlapped

  void Add(const ContactDiagnostics& o);
};

/// Contact loads one pair put on its two bodies over a step, split into the normal (crush) part and
/// the friction part; both act at the same points on both bodies (equal and opposite).
struct PairLoads {
  int body[2] = {0, 0};
  Vec3 normal_force[2] = {Vec3::Zero(), Vec3::Zero()};     ///< [N] earth frame, on body[k]
  Vec3 normal_moment[2] = {Vec3::Zero(), Vec3::Zero()};    ///< [N m] about body[k]'s CG, earth frame
  Vec3 friction_force[2] = {Vec3::Zero(), Vec3::Zero()};   ///< [N] earth frame
  Vec3 friction_moment[2] = {Vec3::Zero(), Vec3::Zero()};  ///< [N m] earth frame
  double law_energy[2] = {0.0, 0.0};  ///< [J] node-law work on body[k]'s nodes over the step
  /// [J] the interface's work over the step on body[k]'s layer (spec §5, layers in series): at each
  /// touching node, force times the step's approach there, times body[k]'s part of a closure shared
  /// at equal pressure
  double share_work[2] = {0.0, 0.0};
  /// [m^2] contact area of body[k]'s own nodes carrying force against the other (spec §3 A_v summed),
  /// the mean over the step's passes in which body[k] was the slave; 0 for a rigid body (never a slave)
  double contact_area[2] = {0.0, 0.0};
  /// [m] body[k]'s equal-pressure share (spec §5) of the penetrations the other body's touching nodes
  /// found in body[k]'s faces, weighted by their node forces, over the step's passes in which body[k]
  /// was a deformable master: the crush its own nodes still have to take there. Where body[k]'s nodes
  /// meet the other's faces they take it in the sibling pass (a fraction of its crush stays between
  /// the two meshes' nodes); on a face whose corners lie outside the contact, the crush body[k]'s mesh
  /// cannot take. 0 for a rigid body
  double untaken_share[2] = {0.0, 0.0};
};

/// What one contact step produced.
struct StepResult {
  std::vector<CgLoads> loads;      ///< per body
  std::vector<PairLoads> pairs;    ///< per pair in contact, in pair order
  ContactDiagnostics diagnostics;
};

/// Owns the bodies' states and one locator per body; the seam a host calls every collision step.
class ContactEngine {
 public:
  ContactEngine(std::vector<std::shared_ptr<const BodyModel>> models, std::vector<RigidState> initial,
                ContactOptions options, const LocatorFactory& make_locator);

  int body_count() const { return static_cast<int>(models_.size()); }
  const BodyModel& model(int i) const { return *models_[i]; }
  const BodyState& state(int i) const { return states_[i]; }
  const ContactOptions& options() const { return options_; }

  /// Host input: pose and velocities of body i for the coming step.
  /// Throws std::invalid_argument for an index out of range or a non-finite state.
  void SetRigidState(int i, const RigidState& rigid);

  /// Host input: how the host moves body i (default: free 6-DOF; a body without mass is held
  /// fixed). Friction uses it to stop, not reverse, a slide within a step (spec §7).
  /// Throws std::invalid_argument for an index out of range.
  void SetMotion(int i, MotionModel motion);

  /// Energy ledger (LS-DYNA-style contact energy): books the work that the last step's contact loads
  /// did on the motion the host integrated, at the mean of the velocities before and after the step
  /// (exact for the semi-implicit Euler host), into each body's crush and friction energy. Call once
  /// the host has set the states reached at the end of the step; Step() books a pending step itself.
  void AccountWork();

  /// One collision time step of length dt [s] at the current poses: updates crush and returns the
  /// collision loads at each CG. Call from one thread at a time (one engine per run).
  /// Threading: each pass's slave nodes run on oneTBB in fixed chunks of 256.
  /// Determinism: chunk partials fold in chunk order; results are bit-identical at any thread count.
  StepResult Step(double dt);

 private:
  struct PassFrame;
  struct Located;
  // forces on the slave (earth frame; the master takes the opposite at the same points) and their
  // moments about each CG
  struct Wrench {
    Vec3 force_slave{0, 0, 0};    // [N]
    Vec3 moment_slave{0, 0, 0};   // [N m] about the slave's CG
    Vec3 moment_master{0, 0, 0};  // [N m] about the master's CG
    void Add(const Vec3& force, const Vec3& arm_slave, const Vec3& arm_master);
    void operator+=(const Wrench& o);
    // this wrench times `weight` on a pair's two bodies: on body `slave_side` (0 or 1) as summed, on
    // the other the opposite force at the same points (its moment about its own CG)
    void AddToPair(double weight, int slave_side, Vec3 (&force)[2], Vec3 (&moment)[2]) const;
  };
  // a touching slave node: the point both bodies are loaded at, the master's outward normal there
  // (earth frame), its normal force, the force it keeps once the approach ends (its turn force), and
  // the part of the step it closes, over which the rest loads (EndApproachWithinStep); friction acts
  // at it (spec §7)
  struct ContactPoint {
    Vec3 arm_slave, arm_master;  // [m] from each body's CG
    Vec3 normal;
    double force = 0.0;       // [N]
    double turn_force = 0.0;  // [N]
    double closing_part = 1.0;
    // [N] over the step
    double Carried() const { return closing_part < 1.0 ? turn_force + closing_part * (force - turn_force) : force; }
  };
  // one pass's sums: normal loads of its slave's nodes, and the points they act at
  struct PassSums {
    int master = 0, slave = 0;
    Wrench normal;
    double touching_area = 0.0;   // [m^2] of slave nodes carrying force
    double law_energy = 0.0;      // [J] node-law work on the slave's nodes
    double slave_share_work = 0.0, master_share_work = 0.0;  // [J] interface work at its nodes, split
    double master_share_force = 0.0;  // [N] node forces at the nodes that touched a deformable master
    double master_share_moment = 0.0;  // [N m] the same times the master's share of each one's penetration
    std::vector<ContactPoint> points;  // its touching nodes (with friction or the turn on), ascending node order
  };
  // what one chunk of slave nodes produced (folded in chunk order); buffers reused across passes
  struct ChunkSums {
    PassSums sums;
    ContactDiagnostics diag;
    std::vector<int> touching, holding, located, moved;  // ascending node indices
    std::vector<ContactPoint> points;                    // ascending node order
    std::vector<Candidate> scratch;                      // candidate triangles of one node
    void Clear() {
      sums = PassSums{};
      points.clear();
      diag = ContactDiagnostics{};
      touching.clear();
      holding.clear();
      located.clear();
      moved.clear();
    }
  };
  // how a slave node met the master at its last update: carrying force, or held with a spring the
  // master closed on (spec §6), or neither
  enum class Engagement : char { kNone, kTouching, kHolding };
  // the slave nodes of one side of a pair that stay in the pass's candidates (both ascending), and
  // those that met a rigid master at their last update (ascending: its nodes leave the faces round
  // them to their own contact)
  struct EngagedNodes {
    std::vector<int> touching, holding, located;
  };
  // the frame of a pass of `slave`'s nodes against `master`
  PassFrame FrameOf(int master, int slave);
  PassSums RunPass(int master, int slave, bool stage, EngagedNodes* engaged, double dt, ContactDiagnostics* diag);
  std::vector<int> CullCandidates(const PassFrame& f, int master, int slave, const EngagedNodes& engaged);
  // writes slave node v's own state (through RestoreNode), its contact normal and its pending Delta
  // (f.pending[v]); nothing of any other node (the parallel loop relies on it), sums into *out
  void ProcessNode(const PassFrame& f, int v, Engagement engagement, double dt, ChunkSums* out);
  // each pass's weight in the pair's estimate: the share of the contact area its slave saw
  static std::vector<double> PassWeights(const std::vector<PassSums>& sums);
  // the passes' estimates of the interface's normal load, plus the rigid nodes' pushes whole
  PairLoads CombinePasses(int a, int b, const std::vector<PassSums>& sums, const std::vector<double>& weights,
                          const PassSums& rigid_nodes) const;
  // spec §7 the pair's friction (contact_friction.cpp): at its passes' friction points, weighted like
  // its normal load, against each point's slide at the step's end, at most mu N, fading under the null
  // band
  void PairFriction(const std::vector<PassSums>& sums, const std::vector<double>& weights, double dt,
                    PairLoads* pair) const;
  // the pair's two bodies moved over dt by its normal loads alone
  std::array<RigidState, 2> TrialMotion(const PairLoads& pair, double dt) const;
  // spec §6 (contact_turn.cpp): in the step in which the approach at a touching node ends, its loading
  // force acts over the part of the step it closes, its turn force throughout (each point's
  // closing_part, from its normal velocity at the step's start and on the pair's trial motion under
  // every load); a rigid body's nodes, pushing only while the faces' crush grows, likewise as a whole
  void EndApproachWithinStep(std::vector<PassSums>* sums, const std::vector<double>& weights,
                             const PassSums& rigid_nodes, double dt, PairLoads* pair) const;
  // a pair's two bodies' velocities and spins on a trial motion, earth frame of the step's start
  struct PairRates {
    Vec3 velocity[2], spin[2];
  };
  PairRates RatesOf(const PairLoads& pair, const std::array<RigidState, 2>& trial) const;
  // the velocity of the slave's point q relative to the master's (q from a pass whose slave is the
  // pair's body slave_side)
  static Vec3 RelativeVelocityAt(const PairRates& rates, int slave_side, const ContactPoint& q);
  // the power of loads on a pair's bodies on the trial motion [W] (rates at the step's start pose)
  double PairPower(const PairLoads& pair, const Vec3 (&force)[2], const Vec3 (&moment)[2],
                   const std::array<RigidState, 2>& trial) const;
  // spec §7 (contact_friction.cpp) a friction point's damper [N s/m]: mu N over its slide on the
  // `reference` rates, read at no less than the null band
  double PointDamping(double mu, const PairRates& reference, int slave_side, const ContactPoint& q) const;
  // the pair's friction points' dampers on its rates (slot 0 the body `lead_side`, each slot's velocity
  // then spin), each pass's weighted like its normal loads
  Eigen::Matrix<double, 12, 12> FrictionDampers(const std::vector<PassSums>& sums, const std::vector<double>& weights,
                                                const PairLoads& pair, double mu, const PairRates& reference,
                                                int lead_side) const;
  // each point's damper times its slide on the rates `after`, at most mu N, onto the pair's friction
  void AddDamperFriction(const std::vector<PassSums>& sums, const std::vector<double>& weights, double mu,
                         const PairRates& reference, const PairRates& after, PairLoads* pair) const;
  Vec3 SearchLine(const PassFrame& f, int v, const Vec3& v_rel, const Vec3& inward) const;
  // `along`: a search direction (master frame) instead of the method's, or null
  bool LocateNode(const PassFrame& f, int v, bool was_touching, const Vec3* along, std::vector<Candidate>* scratch,
                  Located* out) const;
  // master triangle `candidate` for the node at p (master frame): taken when the node lies behind it along
  // ray_dir, its normal points along `facing` (the way the node faces) or, for `faces_of` >= 0, that slave
  // node meets it by a corner face (CornerMeetsFace), and not against `previous` (its last contact normal)
  // or `parting` (the pair's impulse while the node withdraws), and it is nearer than `best`
  bool ExamineTriangle(const PassFrame& f, const Candidate& candidate, const Vec3& p, const Vec3& ray_dir,
                       const Vec3& facing, int faces_of, const Vec3& previous, const Vec3& parting,
                       bool poly_normal, const Located* best, Located* out) const;
  // contact.contact_normal conforming: of master triangle t's crushed normal and its rest normal (both
  // master frame), the one that meets deformable slave node v's own faces more squarely
  Vec3 ConformingNormal(const PassFrame& f, int v, int t, const Vec3& crushed) const;
  // of deformable pair (a, b), whatever their order: the slave of an odd last pass on even steps, whose
  // passes are also combined first
  int LeadSlave(int a, int b) const;
  // whether slave node v, on an edge or a corner, meets master triangle t (larger than v's faces) by one
  // of its own faces turned toward it
  bool CornerMeetsFace(const PassFrame& f, int v, int t) const;
  // distance from slave node v to the master's nearest surface within `radius`, else infinity
  double DistanceToMaster(const PassFrame& f, int v, double radius, std::vector<Candidate>* scratch) const;
  // writes slave node v's law state: unload, delta_max, node_force, node_area, update_step,
  // step_start_deflection; the new Delta goes to *new_delta (committed later). Without a hit:
  // `closing_unfound`, the bodies still close on the node (along its last contact normal, or its crush
  // while it holds a spring), and `free_gap`, how far the node may spring back (the distance to a
  // rigid master's surface). *holding: the node was held with a spring still stored (spec §6);
  // *layers: where it touches a deformable master, the two layers' equal-pressure split (spec §5);
  // *turn_force: the force it carries once the surfaces stop approaching (with turn_within_step, its
  // rebound force from the peak it reached while it loads; else its force)
  double RestoreNode(const PassFrame& f, int v, const Located* hit, bool closing_unfound, double free_gap, double dt,
                     ContactDiagnostics* diag, double* law_energy, Vec3* new_delta, bool* holding,
                     LayerShare* layers, double* turn_force);
  void CommitPending(int body);
  // slave node v's layer and a deformable master's at `hit`, sharing its penetration at equal pressure
  // (spec §5), from the node's crush at the step's start
  LayerShare LayersAtNode(const PassFrame& f, int v, const Located& hit) const;
  // spec §1 swapping against a rigid body: its nodes, as slaves, push the deformable body's faces they
  // crossed between the nodes that `engaged` holds on it (a pole meeting a coarse panel between its
  // nodes); the deformable body's face corners take the crush. Returns the loads with the rigid body as
  // the slave and the node-law work on the deformable body
  PassSums PushFacesOffRigidNodes(int rigid, int deformable, const EngagedNodes& engaged, double dt,
                                  ContactDiagnostics* diag);
  bool BoundsOverlap(int a, int b) const;
  void InitBounds(int body);
  void GrowBounds(int body, const std::vector<int>& moved);

  std::vector<std::shared_ptr<const BodyModel>> models_;
  std::vector<BodyState> states_;
  std::vector<MotionModel> motions_;  // how the host moves each body
  std::vector<std::unique_ptr<Locator>> locators_;
  std::vector<Vec3> bounds_min_, bounds_max_;  // [m] body-frame box holding every vertex so far, per body
  std::vector<std::vector<Vec3>> chunk_min_, chunk_max_;  // [m] the same per fixed chunk of vertices
  std::vector<std::array<int, 2>> pair_order_;  // every pair (a < b) in the order a step visits them
  std::vector<std::array<EngagedNodes, 2>> engaged_;  // per pair (a<b): nodes of a, of b engaged with the other
  // per ordered pair (slave * n + master): the normal impulse the master gave the slave in this
  // contact, master frame [N s]; cleared when the pair's bounds part
  std::vector<Vec3> pushed_;
  std::vector<ChunkSums> chunks_;  // per-chunk scratch of the pass loop
  std::vector<std::vector<Vec3>> pending_delta_;  // [m] per body: new Delta awaiting commit (n_vertices)
  std::vector<std::vector<int>> moved_;           // per body: nodes whose pending Delta awaits commit
  std::vector<std::vector<Engagement>> engaged_mark_;  // per body: its nodes' engagement with the current master
  ContactOptions options_;
  int step_index_ = 0;
  // the last step's pair loads and the states they were applied at, until AccountWork books them
  std::vector<PairLoads> unbooked_;
  std::vector<RigidState> step_start_;
  double unbooked_dt_ = 0.0;
};

}  // namespace dymesh
