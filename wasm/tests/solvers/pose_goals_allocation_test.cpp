// Stepping towards orientation goals allocates nothing, for every method (restarts, escapes and
// chain restarts included), and neither does a second start with goals of the same layout.
#include <gtest/gtest.h>

#include "../allocation_counter.h"
#include "registered_methods.h"
#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// Mixed goals at the tip frames of `angles`: both (e % 3 == 0), orientation only (1), position only (2).
Goals mixed_pose_goals(Kinematics& kin, const Eigen::VectorXd& angles) {
  kin.forward(angles);
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  for (int e = 0; e < kin.num_effectors(); ++e) {
    const int bone = kin.rig().effectors[e];
    goals.effectors[e].position = e % 3 != 1;
    goals.effectors[e].orientation = e % 3 != 2;
    goals.effectors[e].position_target = kin.tip(bone);
    goals.effectors[e].orientation_target = kin.tip_rotation(bone);
    goals.effectors[e].orientation_weight = 0.5;
  }
  return goals;
}

TEST(PoseGoalsAllocation, NothingIsAllocatedWhileStepping) {
  for (const std::string& method : test::kMethods) {
    for (const test::TestRig& r : test::rigs_like("beast")) {
      SCOPED_TRACE(method + " " + r.label());
      Kinematics kin(r.rig);
      SolverOptions options = test::report_options(r);
      options.max_iterations = 40;
      options.restarts = 3;
      options.stall_iterations = 5;
      auto solver = make_solver(method, kin, options);
      for (const test::TargetCase& c : test::random_targets(kin, 2, 63)) {
        const Goals goals = mixed_pose_goals(kin, c.goal);
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
