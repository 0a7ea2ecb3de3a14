#include "protocol.h"

#include <algorithm>
#include <stdexcept>

namespace ik::protocol {

namespace {

// The usual tolerances, for a rig of size kReferenceSize (rig units).
constexpr Tolerances kReference = {1e-4, 2e-4};
constexpr Tolerances kBeast = {0.01, 0.002};
constexpr double kReferenceSize = 1;

}  // namespace

const std::vector<std::string>& a7_rig_names() {
  static const std::vector<std::string> names = {"ikea-lamp", "robot-arm", "knight", "chimpanzee-hand", "beast"};
  return names;
}

double rig_size(const Rig& rig) {
  Kinematics kin(rig);
  kin.forward(Eigen::VectorXd::Zero(kin.num_angles()));
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kUnbounded), hi = -lo;
  for (int b = 0; b < kin.num_bones(); ++b) {
    lo = lo.cwiseMin(kin.tip(b));
    hi = hi.cwiseMax(kin.tip(b));
  }
  return (hi - lo).norm();
}

Tolerances report_tolerances(const std::string& name, bool a7, double size) {
  const std::vector<std::string>& names = a7_rig_names();
  if (a7 && std::find(names.begin(), names.end(), name) != names.end()) return name == "beast" ? kBeast : kReference;
  const double scale = (size / kReferenceSize) * (size / kReferenceSize);
  return {kReference.gradient * scale, kReference.error * scale};
}

std::vector<TargetCase> target_set(Kinematics& kin, const std::string& experiment, int count, std::uint32_t seed) {
  const bool incremental = experiment == "incremental";
  if (!incremental && experiment != "random")
    throw std::invalid_argument("unknown experiment \"" + experiment + "\" (known: random, incremental)");
  Mulberry32 unit = stream_for(seed, experiment);
  Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  kin.project(rest);
  std::vector<TargetCase> cases;
  Eigen::VectorXd previous = rest;
  for (int k = 0; k < count; ++k) {
    TargetCase c;
    c.start = incremental ? previous : rest;
    c.goal = incremental ? incremental_angles(kin, previous, unit) : random_angles(kin, unit);
    c.target.resize(kin.num_residuals());
    kin.tips(c.goal, c.target);
    previous = c.goal;
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace ik::protocol
