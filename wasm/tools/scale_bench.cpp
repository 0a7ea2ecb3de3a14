// How the default method's cost per iteration grows with rig size (issue 6, "Scale").
// Builds synthetic rigs of 10, 100 and 1000 bones: a chain (one effector at its end) and a tree
// (a root with five branches, effectors at the five leaves), limits +-45 degrees per angle,
// total reach 1. Solves random reachable targets (angles uniform in the limits) with `lm` from
// rest and prints the median time per iteration, and that time divided by
// (#angles x #effectors), which stays flat when growth is linear in that product.
// Usage: scale_bench [--json] [--sizes 10,100,1000] [--solves N]
// --json prints one JSON array instead of the table, for programs to read:
//   [{"shape", "bones", "angles", "effectors", "us_per_iteration", "ns_per_angle_effector",
//     "iterations_median", "success_rate"}]
// Builds natively (build/native/scale_bench) and for Node (build/wasm/scale_bench.cjs).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "kinematics.h"
#include "solvers/solver_registry.h"

namespace {

ik::Bone bone(int parent, double length, double x_offset) {
  ik::Bone b;
  b.parent = parent;
  b.length = length;
  b.rest(0, 3) = x_offset;  // rest bones continue along +x: the joint sits at the parent's tip
  b.min_deg = Eigen::Vector3d::Constant(-45);
  b.max_deg = Eigen::Vector3d::Constant(45);
  return b;
}

// A chain of n bones of length 1/n; the effector is the last bone's tip.
ik::Rig chain(int n) {
  ik::Rig rig;
  const double l = 1.0 / n;
  for (int i = 0; i < n; ++i) rig.bones.push_back(bone(i - 1, l, i * l));
  rig.effectors = {n - 1};
  return rig;
}

// A root bone with `branches` chains hanging off its tip (n bones in all, the n - 1 shared out as
// evenly as possible), fanned out about z; effectors at the branch ends.
ik::Rig tree(int n, int branches = 5) {
  ik::Rig rig;
  const double l = 1.0 / ((n - 1 + branches - 1) / branches + 1);
  rig.bones.push_back(bone(-1, l, 0));
  for (int b = 0; b < branches; ++b) {
    const int per_branch = (n - 1) / branches + (b < (n - 1) % branches ? 1 : 0);
    const double fan = (b - (branches - 1) / 2.0) * 0.5;  // radians about z
    for (int i = 0; i < per_branch; ++i) {
      ik::Bone child = bone(i == 0 ? 0 : static_cast<int>(rig.bones.size()) - 1, l, 0);
      // Rest frame: rotated by `fan` about z, placed along that direction from the root's tip.
      Eigen::Matrix3d r = Eigen::AngleAxisd(fan, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      child.rest.topLeftCorner<3, 3>() = r;
      child.rest.block<3, 1>(0, 3) = Eigen::Vector3d(l, 0, 0) + r * Eigen::Vector3d(i * l, 0, 0);
      rig.bones.push_back(child);
    }
    rig.effectors.push_back(static_cast<int>(rig.bones.size()) - 1);
  }
  return rig;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  bool json = false;
  std::vector<int> sizes = {10, 100, 1000};
  int solves = 40;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--json")) {
      json = true;
    } else if (!std::strcmp(argv[i], "--solves") && i + 1 < argc) {
      solves = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
      sizes.clear();
      for (char* s = std::strtok(argv[++i], ","); s; s = std::strtok(nullptr, ",")) sizes.push_back(std::atoi(s));
    } else {
      std::fprintf(stderr, "usage: scale_bench [--json] [--sizes 10,100,1000] [--solves N]\n");
      return 2;
    }
  }
  nlohmann::json rows = nlohmann::json::array();
  if (!json)
    std::printf("%-6s %6s %7s %9s %14s %22s %10s %8s\n", "shape", "bones", "angles", "effectors", "us/iteration",
                "ns/(angle x effector)", "iter med", "success");
  for (const char* shape : {"chain", "tree"}) {
    for (int n : sizes) {
      ik::Kinematics kin(std::string(shape) == "chain" ? chain(n) : tree(n));
      ik::SolverOptions options;
      options.error_tolerance = 1e-10;  // reach is 1
      options.gradient_tolerance = 1e-14;
      options.time_budget_s = 10;
      auto solver = ik::make_solver("lm", kin, options);
      std::mt19937_64 rng(n);
      std::uniform_real_distribution<double> u(-45, 45);
      Eigen::VectorXd goal(kin.num_angles()), target(kin.num_residuals());
      const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
      std::vector<double> per_iteration, iterations;
      int successes = 0;
      for (int s = 0; s < solves; ++s) {
        for (int i = 0; i < goal.size(); ++i) goal[i] = u(rng);
        kin.tips(goal, target);
        const auto t0 = std::chrono::steady_clock::now();
        const ik::SolverSummary& result = solver->solve(rest, target);
        const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
        if (result.iterations > 0) per_iteration.push_back(us / result.iterations);
        iterations.push_back(result.iterations);
        successes += result.E < options.error_tolerance;
      }
      const double us = median(per_iteration);
      const double product = static_cast<double>(kin.num_angles()) * kin.num_effectors();
      if (json)
        rows.push_back({{"shape", shape},
                        {"bones", kin.num_bones()},
                        {"angles", kin.num_angles()},
                        {"effectors", kin.num_effectors()},
                        {"us_per_iteration", us},
                        {"ns_per_angle_effector", 1000 * us / product},
                        {"iterations_median", median(iterations)},
                        {"success_rate", static_cast<double>(successes) / solves}});
      else
        std::printf("%-6s %6d %7d %9d %14.3f %22.3f %10.0f %7.0f%%\n", shape, kin.num_bones(), kin.num_angles(),
                    kin.num_effectors(), us, 1000 * us / product, median(iterations), 100.0 * successes / solves);
    }
  }
  if (json) std::printf("%s\n", rows.dump().c_str());
  return 0;
}
