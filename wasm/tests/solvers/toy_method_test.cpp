// "A new method is one file plus one line": this file is the one file, a complete IK method (the
// Jacobian-transpose method with Buss's step length), and the register_solver() call below is the
// one line (a built-in method's line is its entry in solver_registry.cpp). Nothing else learns of
// it, yet it is made by name, listed after the built-in methods, and solved through the shared
// loop (limits, stop tests, restarts) like them. It registers when a test here first runs, not at
// static initialisation, so the suites parametrised over solver_names() see the built-in methods.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include "../small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// Jacobian transpose (Buss 2004): the step -g = -J^T r scaled by alpha = |J^T r|^2 / |J J^T r|^2,
// the exact minimiser of the linearised E along it, then the shared projected backtracking.
class JacobianTranspose final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "jt"; }

 private:
  void resize(int residuals, int angles) override {
    direction_.resize(angles);
    image_.resize(residuals);
  }

  Progress iterate() override {
    direction_ = -g_.cwiseProduct(free_mask_);
    image_.noalias() = J_ * direction_;
    const double along = direction_.squaredNorm(), across = image_.squaredNorm();
    const double step = across > 0 ? along / across : 1;
    return backtrack(direction_, step, 1e-4) ? Progress::moved : Progress::stuck;
  }

  Eigen::VectorXd direction_, image_;
};

std::unique_ptr<Solver> make_jt_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<JacobianTranspose>(kin, options);
}

// Registers the toy method once per process.
bool registered() {
  static const bool done =
      (register_solver({"jt", "Jacobian transpose", "Jacobian transpose with Buss's step", make_jt_solver}), true);
  return done;
}

TEST(ToyMethod, IsListedAfterTheBuiltInMethodsAndMadeByName) {
  ASSERT_TRUE(registered());
  const std::vector<std::string> names = solver_names();
  ASSERT_GE(names.size(), 6u);
  EXPECT_EQ(names.front(), "lm");
  EXPECT_EQ(names.back(), "jt");
  EXPECT_STREQ(solver_registry().back().label, "Jacobian transpose");
  Kinematics kin(test::two_bones());
  EXPECT_STREQ(make_solver("jt", kin)->name(), "jt");
}

TEST(ToyMethod, ReachesATargetThroughTheSharedLoopInsideTheLimits) {
  ASSERT_TRUE(registered());
  Kinematics kin(test::straight_chain(3, {2}));
  auto solver = make_solver("jt", kin);
  SolverOptions o;
  o.time_budget_s = 0;
  o.tip_tolerance = 1e-4;
  o.gradient_tolerance = 1e-14;
  o.max_iterations = 20000;
  solver->set_options(o);
  const Eigen::VectorXd goal = (Eigen::VectorXd(9) << 0, 30, 0, 10, -40, 5, 0, 20, 0).finished();
  Eigen::VectorXd target(3);
  kin.tips(goal, target);
  const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(9), target);
  EXPECT_EQ(s.stop_reason, StopReason::converged_E);
  EXPECT_TRUE(s.reached);
  EXPECT_LE(s.tip_distance, 1e-4);
  EXPECT_LE(s.angles.maxCoeff(), 90);
  EXPECT_GE(s.angles.minCoeff(), -90);
  Eigen::VectorXd tips(3);
  kin.tips(s.angles, tips);
  EXPECT_LE((tips - target).norm(), 1e-4);  // the reported point is the one forward kinematics gives
}

TEST(ToyMethod, ANameIsRegisteredOnce) {
  ASSERT_TRUE(registered());
  EXPECT_THROW(register_solver({"jt", "again", "", make_jt_solver}), RigError);
  EXPECT_THROW(register_solver({"lm", "again", "", make_jt_solver}), RigError);
  EXPECT_THROW(register_solver({"", "nameless", "", make_jt_solver}), RigError);
  EXPECT_THROW(register_solver({"none", "no factory", "", nullptr}), RigError);
}

}  // namespace
}  // namespace ik
