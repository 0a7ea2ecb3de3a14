// Finite but hostile values: sizes, coordinates and soft weights past the core's limits (size_limits.h) are refused
// with a message naming the field and bone; goal weights are relative; and every value accepted at the edge of those
// limits still gives a result that obeys SolverSummary's rules, a reachable goal reached.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../small_rigs.h"
#include "registered_methods.h"
#include "rig.h"
#include "size_limits.h"
#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// The rules every finished summary obeys: no NaN, converged_E exactly when reached.
void expect_clean(const SolverSummary& s, const std::string& what) {
  EXPECT_FALSE(std::isnan(s.E) || std::isnan(s.initial_E) || std::isnan(s.gradient_norm) || std::isnan(s.tip_distance))
      << what;
  EXPECT_TRUE(s.angles.allFinite()) << what;
  EXPECT_EQ(s.reached, s.stop_reason == StopReason::converged_E) << what << ": " << stop_reason_name(s.stop_reason);
}

std::string rig_error(const Rig& rig) {
  try {
    validate_rig(rig);
  } catch (const RigError& e) {
    return e.what();
  }
  return "";
}

// The two-bone limb with its tip goal at `target` (rig units) of weight `weight`.
Goals limb_goals(const Eigen::Vector3d& target, double weight = 1) {
  Goals goals;
  goals.effectors.resize(1);
  goals.effectors[0].position_target = target;
  goals.effectors[0].position_weight = weight;
  return goals;
}

TEST(HostileValues, RigSizesPastTheCoordinateCapAreRefusedNamingBoneAndField) {
  Rig rig = test::two_bones();
  rig.bones[1].length = 1e9;
  rig.bones[1].rest(0, 3) = -1e9;
  EXPECT_EQ(rig_error(rig), "");
  rig.bones[1].length = 1e200;
  EXPECT_EQ(rig_error(rig),
            "bone 1 \"lower\": length is 1e+200, more than 1e9 rig units (the largest size the core takes)");
  rig.bones[1].length = 1;
  rig.bones[1].rest(2, 3) = 2e9;
  EXPECT_EQ(rig_error(rig),
            "bone 1 \"lower\": rest_T translation[2] is 2e+09, past +-1e9 rig units (the largest coordinate the core "
            "takes)");
}

TEST(HostileValues, GoalValuesPastTheirCapsAreRefusedNamingTheField) {
  Kinematics kin(test::two_bones());
  GoalSet set;
  Goals goals = limb_goals({1, 1, 0});
  goals.effectors[0].position_target.x() = -1e10;
  EXPECT_EQ(set.set(kin, goals),
            "the position target of the goal of end effector 0 has a coordinate past +-1e9 rig units (the largest "
            "coordinate the core takes)");
  goals = limb_goals({1, 1, 0});
  goals.length_scale = 1e200;
  EXPECT_NE(set.set(kin, goals).find("length scale must be a number in 0..1e9"), std::string::npos);
  goals = limb_goals({1, 1, 0});
  goals.poles.push_back(PoleGoal{1, Eigen::Vector3d::Constant(1e308), 1});
  EXPECT_EQ(set.set(kin, goals),
            "the point of pole 0 has a coordinate past +-1e9 rig units (the largest coordinate the core takes)");
  goals.poles[0] = PoleGoal{1, Eigen::Vector3d(0, 1, 0), 1e100};
  EXPECT_EQ(set.set(kin, goals), "the weight of pole 0 must be a number in 0..1000 (a soft pull's largest weight)");
  goals.poles[0].weight = 1000;
  EXPECT_EQ(set.set(kin, goals), "");
  goals.poles.assign(kMaxPoles, goals.poles[0]);
  EXPECT_EQ(set.set(kin, goals), "");
  goals.poles.push_back(goals.poles[0]);
  EXPECT_EQ(set.set(kin, goals), "goals has 65 poles, more than 64 (one per two-bone limb is what a body needs)");
  goals.poles.resize(1);
  goals.stiffness = {1, 1e308};
  EXPECT_EQ(set.set(kin, goals),
            "the stiffness of bone 1 \"lower\" must be a number in 0..1000 (a soft pull's largest weight)");
}

TEST(HostileValues, TargetsPastTheCoordinateCapAreRefused) {
  Kinematics kin(test::two_bones());
  auto solver = make_solver("lm", kin);
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(6);
  EXPECT_EQ(solver->start(angles, Eigen::Vector3d(1e150, 0, 0)), StopReason::invalid_input);
  EXPECT_EQ(solver->summary().message,
            "target[0] is 1e+150, past +-1e9 rig units (the largest coordinate the core takes)");
}

TEST(HostileValues, GoalWeightsAreRelative) {
  Kinematics kin(test::straight_chain(4, {1, 3}));
  Goals goals;
  goals.effectors.resize(2);
  goals.effectors[0].position_weight = goals.effectors[1].position_weight = 1e10;
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  EXPECT_TRUE(set.plain());  // the same weight on every goal: the plain objective
  goals.effectors[0].position_weight = 4e300;
  goals.effectors[1].position_weight = 1e300;
  ASSERT_EQ(set.set(kin, goals), "");
  EXPECT_EQ(set.block(0).scale, 1);
  EXPECT_EQ(set.block(1).scale, 0.25);
}

// Every method, from a bent pose of the two-bone limb towards a reachable target, with `goals`
// and the default tolerances (no time budget): reached, a clean summary.
void expect_reached(const Goals& goals, const SolverOptions& options, const std::string& what) {
  const double tip_tolerance = std::sqrt(2 * options.error_tolerance);  // the E test of one goal of weight 1
  for (const std::string& method : test::kMethods) {
    Kinematics kin(test::two_bones());
    auto solver = make_solver(method, kin, options);
    const SolverSummary& s = solver->solve(Eigen::VectorXd::Constant(6, 10), goals);
    const std::string label = method + ", " + what;
    expect_clean(s, label);
    EXPECT_TRUE(s.reached) << label << ": " << stop_reason_name(s.stop_reason) << " " << s.message << " tip "
                           << s.tip_distance;
    EXPECT_LT(s.tip_distance, tip_tolerance) << label;
  }
}

SolverOptions no_budget() {
  SolverOptions o;
  o.time_budget_s = 0;
  return o;
}

TEST(HostileValues, HugeGoalWeightsStillReachAReachableGoal) {
  expect_reached(limb_goals({0.5, 1.2, 0.3}, 1e10), no_budget(), "goal weight 1e10");
  expect_reached(limb_goals({0.5, 1.2, 0.3}, 1e-10), no_budget(), "goal weight 1e-10");
}

TEST(HostileValues, SoftWeightsAtTheirCapNeverCostAReachableGoal) {
  SolverOptions options = no_budget();
  options.rest_weight = kMaxSoftWeight;
  Goals goals = limb_goals({0.5, 1.2, 0.3});
  goals.stiffness = {kMaxSoftWeight, kMaxSoftWeight};
  expect_reached(goals, options, "rest weight and stiffness at the cap");
  options.rest_from_start = true;
  expect_reached(goals, options, "rest weight and stiffness at the cap, from the start");
  options = no_budget();
  goals = limb_goals({0.5, 1.2, 0.3});
  goals.poles.push_back(PoleGoal{1, Eigen::Vector3d::Constant(kMaxCoordinate), kMaxSoftWeight});
  expect_reached(goals, options, "a pole at the coordinate cap, of the largest weight");
}

TEST(HostileValues, ATargetAtTheCoordinateCapEndsNearTheClosestPoint) {
  for (const std::string& method : test::kMethods) {
    Kinematics kin(test::two_bones());
    SolverOptions options;
    options.time_budget_s = 0;
    auto solver = make_solver(method, kin, options);
    const SolverSummary& s = solver->solve(Eigen::VectorXd::Constant(6, 10), Eigen::Vector3d(0, kMaxCoordinate, 0));
    expect_clean(s, method);
    EXPECT_TRUE(s.stop_reason == StopReason::converged_grad || s.stop_reason == StopReason::zero_step)
        << method << ": " << stop_reason_name(s.stop_reason) << " " << s.message;
    // Near the closest point, the limb straight towards the target with its tip at (0, 2, 0): lm's
    // and newton's damping, which grows with |r|^2, leaves it a few degrees bent.
    EXPECT_GE(s.tip_distance, kMaxCoordinate - 2 - 1e-6) << method;
    EXPECT_LT(s.tip_distance, kMaxCoordinate - 2 + 0.1) << method;
  }
}

}  // namespace
}  // namespace ik
