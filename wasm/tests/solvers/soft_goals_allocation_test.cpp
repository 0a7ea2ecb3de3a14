// Stepping with soft terms (bend hints and the rest pull) allocates nothing, for every method:
// restarts, escapes, chain restarts and the dropping of the soft rows included; neither does a
// second start with goals of the same layout.
#include <gtest/gtest.h>

#include "../allocation_counter.h"
#include "registered_methods.h"
#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// Position goals at the tips of `angles`, a pole on every effector bone with a parent (above its
// elbow), stiffness 1 and 2 alternating.
Goals soft_pose_goals(Kinematics& kin, const Eigen::VectorXd& angles) {
  kin.forward(angles);
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  for (int e = 0; e < kin.num_effectors(); ++e) {
    const int bone = kin.rig().effectors[e];
    goals.effectors[e].position_target = kin.tip(bone);
    if (kin.rig().bones[bone].parent >= 0)
      goals.poles.push_back({bone, kin.joint_origin(bone) + Eigen::Vector3d(0, 0, 1), 1});
  }
  for (int b = 0; b < kin.num_bones(); ++b) goals.stiffness.push_back(1 + b % 2);
  return goals;
}

TEST(SoftGoalsAllocation, NothingIsAllocatedWhileStepping) {
  for (const std::string& method : test::kMethods) {
    for (const test::TestRig& r : test::rigs_like("beast")) {
      SCOPED_TRACE(method + " " + r.label());
      Kinematics kin(r.rig);
      SolverOptions options = test::report_options(r);
      options.max_iterations = 40;
      options.restarts = 3;
      options.stall_iterations = 5;
      options.rest_weight = 0.05;
      auto solver = make_solver(method, kin, options);
      for (const test::TargetCase& c : test::random_targets(kin, 2, 63)) {
        const Goals goals = soft_pose_goals(kin, c.goal);
        solver->start(c.start, goals);
        ASSERT_EQ(solver->summary().message, "");
        const long before = test::heap_allocations();
        while (solver->step()) {
        }
        EXPECT_EQ(test::heap_allocations() - before, 0) << stop_reason_name(solver->summary().stop_reason);
        EXPECT_GT(solver->summary().iterations, 0);
        const long again = test::heap_allocations();
        solver->start(c.start, goals);
        EXPECT_EQ(test::heap_allocations() - again, 0);
      }
    }
  }
}

}  // namespace
}  // namespace ik
