// Paper mode behaves like the original program: on the incremental targets its mean iteration
// count and final errors agree with ../shared/paper/original-measured.csv (the original re-run,
// beside the A7 rigs). Only the report's rigs have such numbers: skipped without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>

#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

struct Measured {
  double iterations, E_avg, E_iqm;
};

// (rig, experiment, METHOD) -> the original's measured row.
std::map<std::string, Measured> original_measured() {
  std::ifstream in(test::a7_dir() + "/../../paper/original-measured.csv");
  std::map<std::string, Measured> rows;
  std::string line;
  std::getline(in, line);  // header: rig,experiment,method,samples,t_avg_s,iter_avg,E_avg,E_iqm,E_max
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string field[9];
    for (auto& f : field) std::getline(row, f, ',');
    rows[field[0] + "," + field[1] + "," + field[2]] = {std::stod(field[5]), std::stod(field[6]), std::stod(field[7])};
  }
  return rows;
}

double interquartile_mean(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t lo = v.size() / 4, hi = v.size() - v.size() / 4;
  return std::accumulate(v.begin() + lo, v.begin() + hi, 0.0) / (hi - lo);
}

using PaperMode = test::NeedsA7;

TEST_F(PaperMode, IncrementalTargetsBehaveLikeTheOriginal) {
  const auto measured = original_measured();
  ASSERT_FALSE(measured.empty()) << "original-measured.csv not found";
  for (const test::TestRig& r : test::test_rigs()) {
    if (!r.a7) continue;  // the original program ran on the report's rigs
    const std::string& name = r.name;
    Kinematics kin(r.rig);
    for (const std::string method : {"gn", "bfgs"}) {
      SolverOptions options = test::report_options(r);
      options.paper_mode = true;
      options.max_iterations = 5000;
      auto solver = make_solver(method, kin, options);
      std::vector<double> iterations, errors;
      for (const test::TargetCase& c : test::incremental_targets(kin, 100, 51)) {
        const SolverSummary& s = solver->solve(c.start, c.target);
        // The original's harness counted the final call that found the stopping test true.
        iterations.push_back(s.iterations + 1);
        errors.push_back(s.E);
      }
      std::string upper = method;
      std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
      const Measured& m = measured.at(name + ",incremental," + upper);
      const double it = std::accumulate(iterations.begin(), iterations.end(), 0.0) / iterations.size();
      const double iqm = interquartile_mean(errors);
      std::printf("%-16s %-5s iterations %6.2f (original %6.2f)  E_iqm %.3g (original %.3g)\n", name.c_str(),
                  method.c_str(), it, m.iterations, iqm, m.E_iqm);
      EXPECT_NEAR(it, m.iterations, 0.2 * m.iterations) << name << " " << method;
      EXPECT_NEAR(iqm, m.E_iqm, 0.3 * m.E_iqm) << name << " " << method;
    }
  }
}

}  // namespace
}  // namespace ik
