// Newton reaches E < 1e-10 on incremental targets and converges quadratically at the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "../sanitizers.h"
#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

TEST(Newton, ReachesTinyErrorsQuadraticallyOnIncrementalTargets) {
  for (const test::TestRig& r : test::test_rigs()) {
    const std::string name = r.label();
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.error_tolerance = 1e-300;  // run until no step helps (the rounding floor)
    options.strict_priority = false;   // no goal given up for missing so fine a tolerance
    options.gradient_tolerance = 0;
    options.max_iterations = 100;
    options.restarts = 0;  // the one run's tail, not a restart's
    options.chain_restarts = 0;
    auto solver = make_solver("newton", kin, options);
    const double reach = test::reach(kin);  // errors are made dimensionless with the rig's size
    std::vector<double> ratios;
    int stationary = 0;
    // The first 20 of the 40 targets under the sanitizers.
    const auto cases = test::incremental_targets(kin, test::sanitized_count(40, 20), 31);
    for (size_t i = 0; i < cases.size(); ++i) {
      const SolverSummary& s = solver->solve(cases[i].start, cases[i].target);
      // No step helps, or an exact hit (E = 0 < the tolerance).
      ASSERT_TRUE(s.stop_reason == StopReason::zero_step || (s.stop_reason == StopReason::converged_E && s.E == 0))
          << name << " target " << i << ": " << stop_reason_name(s.stop_reason) << " " << s.message;
      if (s.E >= 1e-10) {
        // Only allowed at a constrained stationary point: some angles on their limits block the
        // last bit of error (the projected gradient vanishes there).
        EXPECT_LT(s.gradient_norm, 1e-12 * reach * reach) << name << " target " << i << " E " << s.E;
        ++stationary;
        continue;
      }
      // Quadratic: e_{k+1} <= C e_k^2 with e = |r| / reach, measured on the last step that starts
      // below 1e-4 and ends above the rounding floor 1e-12.
      const auto history = solver->error_history();
      const auto e = [&](Eigen::Index k) { return std::sqrt(2 * history[k]) / reach; };
      for (Eigen::Index k = history.size() - 2; k >= 0; --k)
        if (e(k + 1) >= 1e-12 && e(k) <= 1e-4) {
          ratios.push_back(e(k + 1) / (e(k) * e(k)));
          break;
        }
    }
    EXPECT_LE(stationary, 2) << name;
    ASSERT_GE(ratios.size(), cases.size() / 2) << name;
    // C grows with the rig's conditioning (chimpanzee-hand's narrow limits: ~1e4). A linearly or
    // superlinearly converging method (bfgs) scores 1e10 and more on the same measure.
    std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
    EXPECT_LE(ratios[ratios.size() / 2], 1e5) << name << ": median e_{k+1} / e_k^2";
  }
}

}  // namespace
}  // namespace ik
