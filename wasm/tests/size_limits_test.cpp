// The core's size limits (size_limits.h) and the linear-time rig build: a huge input gets a
// clear error, a deep chain builds, and a solver refuses a rig its dense matrices cannot hold.
#include <gtest/gtest.h>

#include <string>

#include "kinematics.h"
#include "size_limits.h"
#include "small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

using test::straight_chain;

std::string error_of(const Rig& rig) {
  try {
    Kinematics kin(rig);
  } catch (const RigError& e) {
    return e.what();
  }
  return "";
}

TEST(SizeLimits, ATenThousandBoneChainBuildsAndPoses) {
  Kinematics kin(straight_chain(10000, {9999, 4999}));
  kin.forward(Eigen::VectorXd::Zero(kin.num_angles()));
  EXPECT_NEAR(kin.tip(9999).x(), 10000, 1e-9);
  EXPECT_NEAR(kin.tip(4999).x(), 5000, 1e-9);
  EXPECT_EQ(kin.effector_chain(0).size(), 10000u);
  EXPECT_EQ(kin.effector_chain(0).front(), 0);
  EXPECT_EQ(kin.effector_chain(1).back(), 4999);
}

TEST(SizeLimits, ParentsComeFirstInAnyIndexOrder) {
  Rig rig = straight_chain(4, {0});
  // Bone 0 is the tip now: parents point to higher indices.
  for (int i = 0; i < 4; ++i) {
    rig.bones[i].parent = i == 3 ? -1 : i + 1;
    rig.bones[i].rest = test::translation(3 - i, 0, 0);
  }
  const std::vector<int> order = parents_first(rig);
  EXPECT_EQ(order, (std::vector<int>{3, 2, 1, 0}));
  Kinematics kin(rig);
  kin.forward(Eigen::VectorXd::Zero(kin.num_angles()));
  EXPECT_NEAR(kin.tip(0).x(), 4, 1e-12);
}

TEST(SizeLimits, ACycleDeepInALongChainIsNamed) {
  Rig rig = straight_chain(5000, {4999});
  rig.bones[2000].parent = 4000;  // 2000..4000 loop, cut off from the root
  EXPECT_NE(error_of(rig).find("bone 2000: parent chain has a cycle"), std::string::npos) << error_of(rig);
}

TEST(SizeLimits, TooManyBonesOrEffectorsAreRefused) {
  EXPECT_NE(error_of(straight_chain(kMaxBones + 1, {0})).find("bones; the core takes at most 16384"),
            std::string::npos);
  std::vector<int> effectors;
  for (int i = 0; i <= kMaxEffectors; ++i) effectors.push_back(i);
  EXPECT_NE(error_of(straight_chain(100, effectors)).find("65 end effectors; the core takes at most 64"),
            std::string::npos);
  Kinematics kin(straight_chain(100, {99}));
  EXPECT_THROW(kin.set_effectors(effectors), RigError);
  EXPECT_EQ(kin.rig().effectors, std::vector<int>{99});
}

TEST(SizeLimits, AJacobianPastTheLimitIsRefused) {
  std::vector<int> effectors;
  for (int i = 0; i < 60; ++i) effectors.push_back(9999 - i);
  EXPECT_NE(error_of(straight_chain(10000, effectors)).find("make a Jacobian of 5400000 numbers"), std::string::npos);
}

TEST(SizeLimits, ALimitRangeLeavingNoAngleIsRefusedButAHugeBoundMeansNone) {
  Rig rig = straight_chain(2, {1});
  rig.bones[1].min_deg[0] = rig.bones[1].max_deg[0] = 1e9;
  EXPECT_NE(error_of(rig).find("bone 1: limit xzx_min/xzx_max[0] is [1e+09, 1e+09] degrees, which leaves no angle"),
            std::string::npos)
      << error_of(rig);
  rig.bones[1].min_deg[0] = -1e10;  // as the report's robot arm writes "no limit"
  rig.bones[1].max_deg[0] = 1e10;
  EXPECT_EQ(error_of(rig), "");
}

TEST(SizeLimits, BoneLabelsNameABoneOnce) {
  Rig rig = straight_chain(2, {1});
  rig.bones[0].name = "bone 0";
  rig.bones[1].name = "forearm";
  EXPECT_EQ(bone_label(rig, 0), "bone 0");
  EXPECT_EQ(bone_label(rig, 1), "bone 1 \"forearm\"");
}

TEST(SizeLimits, DenseMethodsRefuseRigsTheirMatricesCannotHold) {
  Kinematics kin(straight_chain(300, {299}));
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(kin.num_angles());
  const Eigen::Vector3d target(100, 100, 0);
  for (const char* method : {"newton", "bfgs"}) {
    auto solver = make_solver(method, kin, SolverOptions());
    EXPECT_EQ(solver->start(angles, target), StopReason::invalid_input) << method;
    EXPECT_NE(solver->summary().message.find("takes rigs of at most 384 angles (128 bones); this one has 900"),
              std::string::npos)
        << solver->summary().message;
  }
  SolverOptions paper;
  paper.paper_mode = true;
  EXPECT_EQ(make_solver("gd", kin, paper)->start(angles, target), StopReason::invalid_input);
  for (const char* method : {"lm", "gd", "gn"})
    EXPECT_NE(make_solver(method, kin, SolverOptions())->start(angles, target), StopReason::invalid_input) << method;
}

TEST(SizeLimits, OptionsThatWouldHoldMemoryOrTimeAreCapped) {
  Kinematics kin(test::two_bones());
  SolverOptions o;
  o.history_capacity = kMaxHistory + 1;
  auto solver = make_solver("lm", kin, o);
  EXPECT_EQ(solver->start(Eigen::VectorXd::Zero(6), Eigen::Vector3d(1, 1, 0)), StopReason::invalid_input);
  EXPECT_EQ(solver->summary().message, "option history_capacity must be in 1..1000000");
  o = SolverOptions();
  o.max_backtracks = kMaxBacktracks + 1;
  solver = make_solver("gd", kin, o);
  EXPECT_EQ(solver->start(Eigen::VectorXd::Zero(6), Eigen::Vector3d(1, 1, 0)), StopReason::invalid_input);
  EXPECT_EQ(solver->summary().message, "option max_backtracks must be in 1..1000");
}

// The time budget holds inside an iteration: lm building its normal matrix over 6,000 angles
// gives up there once the budget is spent, and says timeout (not zero_step: nothing was stuck).
TEST(SizeLimits, AnIterationCutShortByTheBudgetReportsTimeout) {
  Kinematics kin(straight_chain(2000, {1999, 1000}));
  SolverOptions o;
  o.time_budget_s = 1e-9;  // spent before the first 64 columns are summed
  o.restarts = 0;
  auto solver = make_solver("lm", kin, o);
  const Eigen::VectorXd target = (Eigen::VectorXd(6) << 900, 900, 0, 500, 500, 0).finished();
  const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(kin.num_angles()), target);
  EXPECT_EQ(s.stop_reason, StopReason::timeout);
  EXPECT_EQ(s.iterations, 0);
}

// With steps_before_budget (the page's per-frame solve takes 1), the same budget lets that many
// steps finish before it stops the solve: a frame on a machine too slow for its budget still moves.
TEST(SizeLimits, StepsBeforeBudgetFinishBeforeTheBudgetHolds) {
  Kinematics kin(straight_chain(2000, {1999, 1000}));
  const Eigen::VectorXd target = (Eigen::VectorXd(6) << 900, 900, 0, 500, 500, 0).finished();
  for (int steps : {1, 3}) {
    SolverOptions o;
    o.time_budget_s = 1e-9;
    o.restarts = 0;
    o.steps_before_budget = steps;
    auto solver = make_solver("lm", kin, o);
    const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(kin.num_angles()), target);
    EXPECT_EQ(s.stop_reason, StopReason::timeout) << steps;
    EXPECT_EQ(s.iterations, steps);
    EXPECT_LT(s.E, s.initial_E);
  }
}

}  // namespace
}  // namespace ik
