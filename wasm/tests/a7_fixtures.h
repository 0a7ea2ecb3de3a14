// Shared test fixtures: the report's five rigs (read from ../shared/rigs/a7), random angles,
// and the reference composition of PROTOCOL.md written the plain way with 4x4 matrices.
#pragma once

#include <Eigen/Geometry>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "../native/a7_rig.h"
#include "kinematics.h"

namespace ik::test {

inline const std::vector<std::string>& a7_rig_names() {
  static const std::vector<std::string> names = {"ikea-lamp", "robot-arm", "knight", "chimpanzee-hand", "beast"};
  return names;
}

inline std::string a7_path(const std::string& name) {
  const char* dir = std::getenv("IK_A7_DIR");
  return std::string(dir ? dir : IK_A7_DIR) + "/" + name + ".json";
}

inline Rig load_a7(const std::string& name) { return load_a7_rig(a7_path(name)); }

// Angles uniform in [-360, 360] degrees per angle, clamped to the limits (the random target set).
inline Eigen::VectorXd random_angles(const Kinematics& kin, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd a(kin.num_angles());
  for (int i = 0; i < a.size(); ++i) a[i] = 360.0 * u(rng);
  kin.project(a);
  return a;
}

// Tips by the straightforward composition: 4x4 matrices, Eigen AngleAxis about X, Z, X.
inline Eigen::VectorXd reference_tips(const Rig& rig, const Eigen::VectorXd& angles_deg) {
  const int n = static_cast<int>(rig.bones.size());
  std::vector<Eigen::Matrix4d> T(n);
  std::vector<bool> done(n, false);
  const double d2r = 3.14159265358979323846 / 180.0;
  for (int pass = 0; pass < n; ++pass)
    for (int i = 0; i < n; ++i) {
      const int p = rig.bones[i].parent;
      if (done[i] || (p != -1 && !done[p])) continue;
      Eigen::Matrix4d rot = Eigen::Matrix4d::Identity();
      rot.topLeftCorner<3, 3>() = (Eigen::AngleAxisd(angles_deg[3 * i] * d2r, Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(angles_deg[3 * i + 1] * d2r, Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(angles_deg[3 * i + 2] * d2r, Eigen::Vector3d::UnitX()))
                                      .toRotationMatrix();
      const Eigen::Matrix4d parent = p == -1 ? Eigen::Matrix4d::Identity() : T[p];
      T[i] = parent * rig.bones[i].rest * rot * rig.bones[i].rest.inverse();
      done[i] = true;
    }
  Eigen::VectorXd tips(3 * rig.effectors.size());
  for (size_t k = 0; k < rig.effectors.size(); ++k) {
    const int b = rig.effectors[k];
    const Eigen::Vector4d tip = T[b] * rig.bones[b].rest * Eigen::Vector4d(rig.bones[b].length, 0, 0, 1);
    tips.segment<3>(3 * k) = tip.head<3>();
  }
  return tips;
}

}  // namespace ik::test
