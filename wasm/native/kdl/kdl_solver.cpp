#include "kdl_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <kdl/jacobian.hpp>
#include <kdl/treefksolverpos_recursive.hpp>
#include <kdl/treeiksolvervel_wdls.hpp>
#include <kdl/treejnttojacsolver.hpp>
#include <limits>

#include "../../src/goals.h"
#include "../../src/kinematics.h"
#include "../../src/solvers/restarts.h"
#include "kdl_rig.h"

namespace ik::kdl {

namespace {

using Clock = std::chrono::steady_clock;

// Largest step of one joint per iteration, radians: a full Newton-Raphson step from a straight
// limb can swing a joint by many turns (KDL's NR_JL takes it whole; the clamp then pins it).
constexpr double kMaxStepRad = 0.5;
// A step whose largest joint change (radians) is below this moves nothing: the run is stuck.
constexpr double kZeroStepRad = 1e-12;
// Damping of KDL's wdls velocity solver (its singular values are rig units per radian), as a
// fraction of the rig's reach: each run starts at kInitialDamping; a step that lowers E divides it
// by kDampingFactor (down to kMinDamping), one that does not is tried again with it multiplied,
// up to kMaxRejections times (Levenberg-Marquardt's rule); then the run has stalled.
constexpr double kInitialDamping = 0.1;
constexpr double kMinDamping = 1e-3;
constexpr double kDampingFactor = 3;
constexpr int kMaxRejections = 10;

// The longest chain from the root to an effector's tip, rig units (bone lengths plus the offsets
// between joints).
double reach(const Rig& rig) {
  double longest = 0;
  for (int e : rig.effectors) {
    double length = 0;
    for (int b = e; b != -1; b = rig.bones[b].parent) {
      length += rig.bones[b].length;
      const int p = rig.bones[b].parent;
      if (p != -1) length += (rig.bones[b].rest.block<3, 1>(0, 3) - rig.bones[p].rest.block<3, 1>(0, 3)).norm();
    }
    longest = std::max(longest, length);
  }
  return longest > 0 ? longest : 1;
}

}  // namespace

struct KdlSolver::State {
  KdlRig rig;
  KDL::TreeFkSolverPos_recursive fk;
  KDL::TreeIkSolverVel_wdls vel;
  KDL::TreeJntToJacSolver jac_solver;
  KDL::JntArray q, q_next, qdot;
  KDL::Twists twists;
  KDL::Jacobian jac;
  Eigen::VectorXd lower, upper, angles, best, r, tips;
  Eigen::VectorXd r_q;  // the residual at q, which step() moves from
  Restarts restarts;
  double reach_ = 1, damping = 0, min_damping = 0;
  // Pose goals: per effector its target rotation; the rotation vectors (world, radians) that turn
  // each frame onto its target, at the last evaluate() and at q; their rows' weight L (rig units
  // per radian, the core's length scale rig_reach). Empty `goal_rotations`: positions only.
  std::vector<KDL::Rotation> goal_rotations;
  Eigen::VectorXd rot, rot_q;
  double length_scale = 1;
  Eigen::MatrixXd position_weights, pose_weights;
  bool pose_weighted = false;

  // Sets the damping of KDL's velocity solver (rig units).
  void set_damping(double lambda) {
    damping = lambda;
    vel.setLambda(lambda);
  }

  explicit State(const Rig& r_in)
      : rig(make_kdl_rig(r_in)), fk(rig.tree), vel(rig.tree, rig.tip_segments), jac_solver(rig.tree) {
    const int n = rig.num_angles(), m = 3 * static_cast<int>(rig.tip_segments.size());
    lower.resize(n);
    upper.resize(n);
    for (size_t i = 0; i < r_in.bones.size(); ++i) {
      lower.segment<3>(3 * i) = r_in.bones[i].min_deg;
      upper.segment<3>(3 * i) = r_in.bones[i].max_deg;
    }
    angles.resize(n);
    best.resize(n);
    r.resize(m);
    r_q.resize(m);
    tips.resize(m);
    q.resize(rig.num_joints());
    q_next.resize(rig.num_joints());
    qdot.resize(rig.num_joints());
    jac.resize(rig.num_joints());
    Eigen::MatrixXd weights = Eigen::MatrixXd::Zero(2 * m, 2 * m);                    // 6 rows per effector
    for (int e = 0; e < m / 3; ++e) weights.block<3, 3>(6 * e, 6 * e).setIdentity();  // rotation rows: 0
    vel.setWeightTS(weights);
    position_weights = weights;
    length_scale = rig_reach(Kinematics(r_in));
    pose_weights = weights;
    for (int e = 0; e < m / 3; ++e)
      pose_weights.block<3, 3>(6 * e + 3, 6 * e + 3) = length_scale * Eigen::Matrix3d::Identity();
    rot = Eigen::VectorXd::Zero(m);
    rot_q = Eigen::VectorXd::Zero(m);
    reach_ = reach(r_in);
    min_damping = kMinDamping * reach_;
    for (const std::string& t : rig.tip_segments) twists[t] = KDL::Twist::Zero();
  }

  // Sets the goals' rotations (empty: positions only) and the task-space weights they need.
  void set_orientations(const std::vector<Eigen::Matrix3d>& orientations) {
    goal_rotations.clear();
    for (const Eigen::Matrix3d& R : orientations)
      goal_rotations.emplace_back(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
    const bool pose = !goal_rotations.empty();
    if (pose != pose_weighted) vel.setWeightTS(pose ? pose_weights : position_weights);
    pose_weighted = pose;
    rot.setZero();
    rot_q.setZero();
  }

  // Tips at `q` into `tips`, residual r = tips - targets; returns E = 1/2 |r|^2. With pose goals
  // also the rotation vectors `rot` and E += 1/2 L^2 |rot|^2.
  double evaluate(const KDL::JntArray& at, const Eigen::VectorXd& targets) {
    KDL::Frame f;
    for (size_t e = 0; e < rig.tip_segments.size(); ++e) {
      fk.JntToCart(at, f, rig.tip_segments[e]);
      tips.segment<3>(3 * e) << f.p.x(), f.p.y(), f.p.z();
      if (!goal_rotations.empty()) {
        const KDL::Vector w = KDL::diff(f.M, goal_rotations[e]);  // world rotation vector onto the target
        rot.segment<3>(3 * e) << w.x(), w.y(), w.z();
      }
    }
    r = tips - targets;
    if (goal_rotations.empty()) return 0.5 * r.squaredNorm();
    return 0.5 * r.squaredNorm() + 0.5 * length_scale * length_scale * rot.squaredNorm();
  }

  // Largest angle of a frame from its target after evaluate(), degrees (0 without pose goals).
  double rotation_error_deg() const {
    double worst = 0;
    for (int e = 0; e < rot.size() / 3; ++e) worst = std::max(worst, rot.segment<3>(3 * e).norm());
    return worst / kRadPerDeg;
  }

  // Largest distance of a tip from its target after evaluate().
  double tip_distance() const {
    double worst = 0;
    for (int e = 0; e < r.size() / 3; ++e) worst = std::max(worst, r.segment<3>(3 * e).norm());
    return worst;
  }

  // |J^T r| in rig units^2 per degree over the free angles at `at` (after evaluate(at)).
  double gradient_norm(const KDL::JntArray& at) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(rig.num_joints());
    for (size_t e = 0; e < rig.tip_segments.size(); ++e) {
      jac_solver.JntToJac(at, jac, rig.tip_segments[e]);
      g += jac.data.topRows<3>().transpose() * r.segment<3>(3 * e);
    }
    return g.norm() * kRadPerDeg;
  }

  // Newton-Raphson step from q by the residual r_q into q_next, clamped to the limits; returns
  // the largest joint change (radians).
  double step() {
    for (size_t e = 0; e < rig.tip_segments.size(); ++e)
      twists[rig.tip_segments[e]] = KDL::Twist(
          KDL::Vector(-r_q[3 * e], -r_q[3 * e + 1], -r_q[3 * e + 2]),
          goal_rotations.empty() ? KDL::Vector::Zero() : KDL::Vector(rot_q[3 * e], rot_q[3 * e + 1], rot_q[3 * e + 2]));
    vel.CartToJnt(q, twists, qdot);
    const double largest = qdot.data.size() ? qdot.data.cwiseAbs().maxCoeff() : 0.0;
    if (!std::isfinite(largest)) return 0;  // a failed solve moves nothing
    const double scale = largest > kMaxStepRad ? kMaxStepRad / largest : 1.0;
    q_next.data = (q.data + scale * qdot.data).cwiseMax(rig.q_min.data).cwiseMin(rig.q_max.data);
    return (q_next.data - q.data).cwiseAbs().maxCoeff();
  }
};

KdlSolver::KdlSolver(const Rig& rig, const SolverOptions& options)
    : s_(std::make_unique<State>(rig)), options_(options) {}

KdlSolver::~KdlSolver() = default;

const KdlSummary& KdlSolver::solve(const Eigen::VectorXd& start, const Eigen::VectorXd& targets,
                                   const std::function<void(const Eigen::VectorXd&)>& on_iterate) {
  static const std::vector<Eigen::Matrix3d> none;
  return solve(start, targets, none, on_iterate);
}

// One solve call: what it runs with, the best point met so far, and its runs (one per start
// point), each ending with a stop reason.
struct KdlSolver::Call {
  State& s;
  const SolverOptions& o;
  const Eigen::VectorXd& targets;  // #effectors x 3, rig units
  const std::function<void(const Eigen::VectorXd&)>& on_iterate;
  KdlSummary& out;
  const Clock::time_point t0;
  const bool pose;  // with orientation goals
  double best_E = std::numeric_limits<double>::infinity();
  bool best_on_target = false;

  // The time budget (options.time_budget_s, seconds from t0) has run out.
  bool out_of_time() const {
    const bool timed = o.time_budget_s > 0 && std::isfinite(o.time_budget_s);
    return timed && std::chrono::duration<double>(Clock::now() - t0).count() >= o.time_budget_s;
  }

  // The point whose residual s.r holds, of error `E`, is on target. With pose goals: the position
  // rows' E (or the tip test), and every frame within the tolerance.
  bool on_target(double E) const {
    if (pose) E = 0.5 * s.r.squaredNorm();
    const bool position = o.tip_tolerance > 0 ? s.tip_distance() < o.tip_tolerance : E < o.error_tolerance;
    return pose ? position && s.rotation_error_deg() < o.orientation_tolerance_deg : position;
  }

  // Keeps the point s.q of error `E` if it is the best: the lowest E; with pose goals an on-target
  // point before any other (E mixes positions and orientations there, so a lower E need not be on
  // target).
  void consider(double E) {
    const bool on = pose && on_target(E);
    if ((on && !best_on_target) || (on == best_on_target && E < best_E)) {
      best_E = E;
      best_on_target = on;
      joints_to_angles(s.rig, s.q, s.best);
    }
  }

  // One run from s.angles (degrees): damped Newton-Raphson steps until on target, out of
  // iterations or time, or stalled. Returns its stop reason.
  std::string run() {
    angles_to_joints(s.rig, s.angles, s.q);
    s.set_damping(kInitialDamping * s.reach_);
    double E = s.evaluate(s.q, targets);
    s.r_q = s.r;
    s.rot_q = s.rot;
    ++out.function_evaluations;
    consider(E);
    while (true) {
      if (on_target(E)) return "converged_E";
      if (out.iterations >= o.max_iterations) return "max_iterations";
      if (out_of_time()) return "timeout";
      if (!step(E)) return "zero_step";
      if (s.restarts.stalls(E, o.stall_iterations)) return "zero_step";  // no lower E for a while
    }
  }

  // One iteration from s.q of error `E`: a step, tried again with more damping while it does not
  // lower E. Returns false if no step lowered it (s.q and its residual kept); else moves to the
  // new point and sets `E` to its error.
  bool step(double& E) {
    const double moved = s.step();
    ++out.jacobian_evaluations;
    if (moved < kZeroStepRad) return false;
    double E_next = s.evaluate(s.q_next, targets);
    ++out.function_evaluations;
    for (int tries = 0; E_next >= E && tries < kMaxRejections; ++tries) {  // more damping, shorter step
      s.set_damping(s.damping * kDampingFactor);
      if (s.step() < kZeroStepRad) break;
      ++out.jacobian_evaluations;
      E_next = s.evaluate(s.q_next, targets);
      ++out.function_evaluations;
    }
    if (E_next >= E) {
      s.r = s.r_q;  // the residual of the point kept
      s.rot = s.rot_q;
      return false;
    }
    s.set_damping(std::max(s.damping / kDampingFactor, s.min_damping));
    std::swap(s.q, s.q_next);
    s.r_q = s.r;
    s.rot_q = s.rot;
    E = E_next;
    ++out.iterations;
    consider(E);
    if (on_iterate) {
      joints_to_angles(s.rig, s.q, s.angles);
      on_iterate(s.angles);
    }
    return true;
  }

  // Fills `out` with the best point; `reason`: the last run's stop reason.
  void describe(const std::string& reason) {
    out.angles = s.best;
    angles_to_joints(s.rig, s.best, s.q);
    out.E = s.evaluate(s.q, targets);
    out.tip_distance = s.tip_distance();
    out.rotation_error_deg = s.rotation_error_deg();
    out.gradient_norm = s.gradient_norm(s.q);
    out.reached = on_target(out.E);
    out.stop_reason = out.reached ? "converged_E" : reason == "converged_E" ? "zero_step" : reason;
  }
};

const KdlSummary& KdlSolver::solve(const Eigen::VectorXd& start, const Eigen::VectorXd& targets,
                                   const std::vector<Eigen::Matrix3d>& orientations,
                                   const std::function<void(const Eigen::VectorXd&)>& on_iterate) {
  State& s = *s_;
  const SolverOptions& o = options_;
  const auto t0 = Clock::now();
  KdlSummary& out = summary_;
  out = KdlSummary();
  bool bad_orientations = !orientations.empty() && orientations.size() != s.rig.tip_segments.size();
  for (const Eigen::Matrix3d& R : orientations) bad_orientations = bad_orientations || !R.allFinite();
  if (start.size() != s.rig.num_angles() || targets.size() != s.r.size() || !start.allFinite() ||
      !targets.allFinite() || bad_orientations) {
    out.stop_reason = "invalid_input";
    out.message = "start, targets or orientations: wrong length or not finite";
    out.angles = start;
    return out;
  }
  s.set_orientations(orientations);
  Call call{s, o, targets, on_iterate, out, t0, !orientations.empty()};
  s.angles = start.cwiseMax(s.lower).cwiseMin(s.upper);
  s.restarts.begin_solve(s.rig.num_angles(), o.seed);
  const long restarts = o.paper_mode ? 0 : o.restarts;  // as the core: none in paper mode
  while (true) {
    const std::string reason = call.run();
    const bool again = reason == "zero_step" && s.restarts.used() < restarts && !call.out_of_time() &&
                       out.iterations < o.max_iterations;
    if (!again) {
      call.describe(reason);
      return out;
    }
    s.restarts.next_start(s.lower, s.upper, s.angles);
    ++out.restarts;
    ++out.iterations;
  }
}

}  // namespace ik::kdl
