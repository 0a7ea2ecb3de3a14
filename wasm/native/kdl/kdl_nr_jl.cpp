#include "kdl_nr_jl.h"

#include <chrono>
#include <cmath>
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <memory>
#include <stdexcept>
#include <string>

#include "../../src/goals.h"
#include "../../src/kinematics.h"
#include "kdl_rig.h"

namespace ik::kdl {

namespace {

using Clock = std::chrono::steady_clock;

// TRAC-IK's tolerance, used when the options give no tip tolerance (rig units and radians).
constexpr double kTracIkEps = 1e-5;

// The rig's chain from its root to effector 0's tip segment.
KDL::Chain chain_of(const KdlRig& k) {
  KDL::Chain chain;
  if (k.tip_segments.size() != 1 || !k.tree.getChain("root", k.tip_segments[0], chain))
    throw std::invalid_argument("method kdl_nr_jl: the rig needs exactly one end effector (a serial chain), not " +
                                std::to_string(k.tip_segments.size()));
  return chain;
}

}  // namespace

struct KdlNrJl::State {
  KdlRig rig;
  KDL::Chain chain;
  std::vector<int> angle_of_joint;  // per chain joint: its angle (index into the rig's angles)
  // Per chain joint: the limits of a full-turn joint (degrees; lower NaN for the others).
  std::vector<double> wrap_from, wrap_to;
  KDL::JntArray q_min, q_max, q, result;
  Eigen::VectorXd angles;
  double length_scale = 1;  // L of the core's E with orientation goals (rig_reach, goals.h)
  // KDL's solvers of the chain, made once: a query only runs them.
  KDL::ChainFkSolverPos_recursive fk;
  KDL::ChainIkSolverVel_pinv velocity;
  KDL::ChainJntToJacSolver jacobian;
  std::unique_ptr<KDL::ChainIkSolverPos_NR_JL> nr_jl;  // made once the limits are known

  // `eps`: KDL's tolerance on each twist component (rig units and radians).
  State(const Rig& r, double eps)
      : rig(make_kdl_rig(r)), chain(chain_of(rig)), fk(chain), velocity(chain), jacobian(chain) {
    // Segment "b<i>.x0", "b<i>.z1" or "b<i>.x2" turns angle 3i + 0, 1 or 2 (kdl_rig.h).
    for (const KDL::Segment& seg : chain.segments) {
      if (seg.getJoint().getType() == KDL::Joint::Fixed) continue;
      const std::string& name = seg.getName();
      const size_t dot = name.find('.');
      angle_of_joint.push_back(3 * std::stoi(name.substr(1, dot - 1)) + (name[dot + 2] - '0'));
    }
    length_scale = rig_reach(Kinematics(r));
    const unsigned n = chain.getNrOfJoints();
    q_min.resize(n);
    q_max.resize(n);
    q.resize(n);
    result.resize(n);
    for (unsigned j = 0; j < n; ++j) {
      const int a = angle_of_joint[j];
      const double lo = r.bones[a / 3].min_deg[a % 3], hi = r.bones[a / 3].max_deg[a % 3];
      // A joint that turns a full circle (a continuous one) has no limits in TRAC-IK's chain
      // (getKDLLimits), so NR_JL never clamps it: its angle is wrapped back when it comes out.
      const bool turns = hi - lo >= 360;
      q_min(j) = turns ? -INFINITY : lo * kRadPerDeg;
      q_max(j) = turns ? INFINITY : hi * kRadPerDeg;
      wrap_from.push_back(turns ? lo : NAN);
      wrap_to.push_back(hi);
    }
    nr_jl = std::make_unique<KDL::ChainIkSolverPos_NR_JL>(chain, q_min, q_max, fk, velocity, 1, eps);
  }

  // The chain's joints at `from` (#angles, degrees), in radians.
  void to_joints(const Eigen::VectorXd& from, KDL::JntArray& out) const {
    for (size_t j = 0; j < angle_of_joint.size(); ++j) out(j) = from[angle_of_joint[j]] * kRadPerDeg;
  }
  // `angles` = `base` with the chain's joints set from `joints` (radians); a full-turn joint's
  // angle outside its limits wrapped into [lower, lower + 360).
  void to_angles(const Eigen::VectorXd& base, const KDL::JntArray& joints) {
    angles = base;
    for (size_t j = 0; j < angle_of_joint.size(); ++j) {
      double deg = joints(j) / kRadPerDeg;
      const double lo = wrap_from[j];
      if (!std::isnan(lo) && (deg < lo || deg > wrap_to[j]))
        deg = lo + std::fmod(std::fmod(deg - lo, 360.0) + 360.0, 360.0);
      angles[angle_of_joint[j]] = deg;
    }
  }
};

KdlNrJl::KdlNrJl(const Rig& rig, const SolverOptions& options)
    : s_(std::make_unique<State>(rig, options.tip_tolerance > 0 ? options.tip_tolerance : kTracIkEps)),
      options_(options) {}

KdlNrJl::~KdlNrJl() = default;

const KdlSummary& KdlNrJl::solve(const Eigen::VectorXd& start, const Eigen::VectorXd& target,
                                 const std::vector<Eigen::Matrix3d>& orientations) {
  State& s = *s_;
  const SolverOptions& o = options_;
  KdlSummary& out = summary_;
  out = KdlSummary();
  out.angles = start;
  if (start.size() != s.rig.num_angles() || target.size() != 3 || !start.allFinite() || !target.allFinite() ||
      orientations.size() != 1 || !orientations[0].allFinite()) {
    out.stop_reason = "invalid_input";
    out.message = orientations.empty() ? "kdl_nr_jl takes whole poses (--goals pose): KDL's test is on the whole twist"
                                       : "start, target or orientation: wrong length or not finite";
    return out;
  }
  const Eigen::Matrix3d& R = orientations[0];
  const KDL::Frame goal(KDL::Rotation(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)),
                        KDL::Vector(target[0], target[1], target[2]));

  const auto t0 = Clock::now();
  const bool timed = o.time_budget_s > 0 && std::isfinite(o.time_budget_s);
  s.to_joints(start, s.result);
  int rc = -1;
  std::string reason = "max_iterations";
  while (out.iterations < o.max_iterations) {
    s.q = s.result;  // each call from the last one's result
    rc = s.nr_jl->CartToJnt(s.q, goal, s.result);
    ++out.iterations;
    if (rc >= 0) {
      reason = "converged_E";
      break;
    }
    if (timed && std::chrono::duration<double>(Clock::now() - t0).count() >= o.time_budget_s) {
      reason = "timeout";
      break;
    }
  }
  s.to_angles(start, s.result);
  out.angles = s.angles;
  KDL::Frame at;
  s.fk.JntToCart(s.result, at);
  const Eigen::Vector3d r(at.p.x() - target[0], at.p.y() - target[1], at.p.z() - target[2]);
  const KDL::Vector w = KDL::diff(at.M, goal.M);
  out.tip_distance = r.norm();
  out.rotation_error_deg = w.Norm() / kRadPerDeg;
  const Eigen::Vector3d rot(w.x(), w.y(), w.z());
  out.E = 0.5 * r.squaredNorm() + 0.5 * s.length_scale * s.length_scale * rot.squaredNorm();
  KDL::Jacobian J(s.chain.getNrOfJoints());
  s.jacobian.JntToJac(s.result, J);
  out.gradient_norm = (J.data.topRows<3>().transpose() * r).norm() * kRadPerDeg;
  out.reached = rc >= 0;
  out.stop_reason = reason;
  out.function_evaluations = out.jacobian_evaluations = out.iterations;
  return out;
}

}  // namespace ik::kdl
