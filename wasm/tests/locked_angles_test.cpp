// Locked angles cost nothing and change nothing (kinematics.h): on an arm of one-angle joints as
// the URDF importer builds them (a0 free, a1 and a2 locked at 0, docs/urdf.md), forward
// kinematics that skips the locked rotations gives the pose of the three rotations, the
// solvers' Jacobian (Columns::movable) equals the full one on the movable columns and leaves the
// fixed ones at 0, and every method reaches its targets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <string>

#include "goal_residual.h"
#include "goals.h"
#include "kinematics.h"
#include "solvers/registered_methods.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// A 7-joint arm shaped like a URDF import: each bone's rest frame turns its x axis onto a joint
// axis drawn at random, a0 within +-limits, a1 and a2 locked at 0; an eighth bone (the flange)
// has all three angles locked.
Rig one_angle_arm(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  Rig rig;
  for (int i = 0; i < 8; ++i) {
    Bone b;
    b.name = "link" + std::to_string(i);
    b.parent = i - 1;
    const Eigen::Quaterniond q = Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    b.rest.setIdentity();
    b.rest.block<3, 3>(0, 0) = q.toRotationMatrix();
    b.rest.block<3, 1>(0, 3) = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) * 0.2;
    b.length = 0.1 + 0.05 * (unit(rng) + 1);
    b.min_deg = Eigen::Vector3d(-160 + 20 * unit(rng), 0, 0);
    b.max_deg = Eigen::Vector3d(160 + 20 * unit(rng), 0, 0);
    if (i == 7) b.max_deg[0] = b.min_deg[0] = 0;
    rig.bones.push_back(b);
  }
  rig.effectors = {7};
  return rig;
}

// The pose as kinematics.h defines it, with all three rotations, in forward()'s arithmetic.
struct ReferencePose {
  std::vector<Eigen::Isometry3d> frame;  // T_parent * rest_i * Rx Rz Rx
  std::vector<Eigen::Matrix3d> axes;
};

void rotate_columns(Eigen::Matrix3d& m, int i, int j, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  const Eigen::Vector3d a = m.col(i), b = m.col(j);
  m.col(i) = c * a + s * b;
  m.col(j) = c * b - s * a;
}

ReferencePose reference_pose(const Rig& rig, const Eigen::VectorXd& angles) {
  const int n = static_cast<int>(rig.bones.size());
  ReferencePose out{std::vector<Eigen::Isometry3d>(n), std::vector<Eigen::Matrix3d>(n)};
  for (int i = 0; i < n; ++i) {  // parents first in one_angle_arm()
    Eigen::Isometry3d rest;
    rest.matrix() = rig.bones[i].rest;
    const int p = rig.bones[i].parent;
    Eigen::Isometry3d from_parent = rest;
    if (p != -1) {
      Eigen::Isometry3d rest_p;
      rest_p.matrix() = rig.bones[p].rest;
      from_parent = rest_p.inverse(Eigen::Isometry) * rest;
    }
    const Eigen::Isometry3d joint = p == -1 ? from_parent : out.frame[p] * from_parent;
    Eigen::Matrix3d r = joint.linear();
    out.axes[i].col(0) = r.col(0);
    rotate_columns(r, 1, 2, angles[3 * i] * kRadPerDeg);
    out.axes[i].col(1) = r.col(2);
    rotate_columns(r, 0, 1, angles[3 * i + 1] * kRadPerDeg);
    out.axes[i].col(2) = r.col(0);
    rotate_columns(r, 1, 2, angles[3 * i + 2] * kRadPerDeg);
    out.frame[i].linear() = r;
    out.frame[i].translation() = joint.translation();
  }
  return out;
}

// Equal as numbers (+0 == -0), or both NaN.
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

template <class A, class B>
bool same_matrix(const A& a, const B& b) {
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      if (!same(a(i, j), b(i, j))) return false;
  return true;
}

Eigen::VectorXd random_angles(const Kinematics& kin, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  Eigen::VectorXd a(kin.num_angles());
  for (int i = 0; i < a.size(); ++i) a[i] = kin.lower()[i] + unit(rng) * (kin.upper()[i] - kin.lower()[i]);
  return a;
}

TEST(LockedAngles, ForwardKinematicsEqualsTheThreeRotations) {
  const Rig rig = one_angle_arm(3);
  Kinematics kin(rig);
  std::mt19937 rng(11);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd a = random_angles(kin, rng);
    if (trial % 4 == 1) a[4] = a[23] = -0.0;      // a locked angle at -0 skips too
    if (trial % 4 == 2) a[1] = 12.5, a[8] = -40;  // unprojected values on locked angles still turn
    if (trial == 3) a[5] = nan;                   // so does NaN: the pose is NaN as before
    kin.forward(a);
    const ReferencePose ref = reference_pose(rig, a);
    for (int i = 0; i < kin.num_bones(); ++i) {
      EXPECT_TRUE(same_matrix(kin.tip_rotation(i), ref.frame[i].linear())) << "trial " << trial << " bone " << i;
      EXPECT_TRUE(same_matrix(kin.joint_origin(i), ref.frame[i].translation())) << "trial " << trial;
      EXPECT_TRUE(same_matrix(kin.tip(i), ref.frame[i] * Eigen::Vector3d(rig.bones[i].length, 0, 0)));
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_matrix(kin.joint_axis(i, k), ref.axes[i].col(k)));
    }
    if (trial == 3) {
      EXPECT_TRUE(std::isnan(kin.tip(7).x()));
    }
  }
}

TEST(LockedAngles, SolverJacobianHasTheMovableColumnsOnly) {
  const Rig rig = one_angle_arm(5);
  Kinematics kin(rig);
  std::mt19937 rng(7);
  Goals goals;
  goals.effectors.resize(1);
  goals.effectors[0].orientation = true;
  GoalSet pose_goals;
  Eigen::MatrixXd all(6, kin.num_angles()), movable(6, kin.num_angles());
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd a = random_angles(kin, rng), b = random_angles(kin, rng);
    kin.forward(b);
    goals.effectors[0].position_target = kin.tip(7);
    goals.effectors[0].orientation_target = kin.tip_rotation(7);
    ASSERT_EQ(pose_goals.set(kin, goals), "");
    kin.forward(a);
    for (int plain = 0; plain < 2; ++plain) {
      const auto rows = plain ? 3 : 6;
      all.setConstant(1.5);
      movable.setConstant(1.5);
      if (plain) {
        kin.current_jacobian(all.topRows(3));
        kin.current_jacobian(movable.topRows(3), Kinematics::Columns::movable);
      } else {
        goal_jacobian(kin, pose_goals, all);
        goal_jacobian(kin, pose_goals, movable, Kinematics::Columns::movable);
      }
      for (int j = 0; j < kin.num_angles(); ++j) {
        const bool moves = kin.lower()[j] < kin.upper()[j];
        for (int r = 0; r < rows; ++r) {
          if (moves) {
            EXPECT_EQ(movable(r, j), all(r, j)) << "angle " << j;  // bit for bit
          } else {
            EXPECT_EQ(movable(r, j), 0.0) << "angle " << j;
          }
        }
        if (!moves && j < 3 * 7) {
          EXPECT_GT(all.col(j).head(rows).norm(), 0) << "angle " << j;  // the full one has them
        }
      }
    }
  }
}

// FNV-1a over the bits of the numbers (a zero of either sign counts as +0).
struct Fingerprint {
  std::uint64_t hash = 1469598103934665603ull;
  void add(double x) {
    x += 0.0;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i) hash = (hash ^ ((bits >> (8 * i)) & 0xff)) * 1099511628211ull;
  }
};

// Every method reaches full-pose targets on the arm from the mid-limit seed (TRAC-IK's protocol),
// deterministically (no time budget). The fingerprint of the answers and counts is printed so
// that builds can be compared: the code before locked angles were skipped printed the same five.
TEST(LockedAngles, EveryMethodReachesPoseTargets) {
  const Rig rig = one_angle_arm(9);
  Kinematics kin(rig);
  std::mt19937 rng(13);
  const Eigen::VectorXd seed = 0.5 * (kin.lower() + kin.upper());
  std::vector<Goals> targets(60);
  for (Goals& g : targets) {
    kin.forward(random_angles(kin, rng));
    g.effectors.resize(1);
    g.effectors[0].position_target = kin.tip(7);
    g.effectors[0].orientation = true;
    g.effectors[0].orientation_target = kin.tip_rotation(7);
  }
  for (const std::string& method : test::kMethods) {
    SolverOptions options;
    options.time_budget_s = 0;
    options.max_iterations = 3000;
    const auto solver = make_solver(method, kin, options);
    Fingerprint print;
    int reached = 0;
    long iterations = 0;
    for (const Goals& g : targets) {
      const SolverSummary& s = solver->solve(seed, g);
      reached += s.reached;
      iterations += s.iterations;
      for (int i = 0; i < s.angles.size(); ++i) print.add(s.angles[i]);
      print.add(s.iterations);
      print.add(s.function_evaluations);
      for (int i = 0; i < s.angles.size(); ++i)
        if (!(kin.lower()[i] < kin.upper()[i])) {
          EXPECT_EQ(s.angles[i], 0.0) << method;
        }
    }
    std::cout << "[ locked   ] " << method << " reached " << reached << "/" << targets.size() << " in " << iterations
              << " iterations, fingerprint " << std::hex << print.hash << std::dec << "\n";
    if (method != "gd") {
      EXPECT_GE(reached, 57) << method;
    }
  }
}

}  // namespace
}  // namespace ik
