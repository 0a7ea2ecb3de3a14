// Shared test fixtures: the rigs the tests run on, random angles, and the reference composition
// of PROTOCOL.md written the plain way with 4x4 matrices.
//
// Two sets of rigs in A7 format: the project's own (build/test-rigs, written from
// web/public/models by scripts/write-test-rigs.ts, which npm test runs first; the tests fail
// without them), and the report's five A7 rigs from $IK_A7_DIR (default ../shared/rigs/a7; a
// relative path starts at the repository root), when that folder exists. Tests of a general
// property loop over test_rigs(); tests whose expectations belong to the report's rigs use the
// fixture NeedsA7, which skips them without the folder (and fails them under CI).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "../native/a7_rig.h"
#include "../native/protocol.h"
#include "kinematics.h"

namespace ik::test {

using protocol::a7_rig_names;

// The folder of the project's rigs in A7 format, written by scripts/write-test-rigs.ts.
inline std::string project_rigs_dir() { return std::string(IK_REPO_ROOT) + "/build/test-rigs"; }

// The project's rigs by base name ("knight"), in the order of the list names.txt that
// scripts/write-test-rigs.ts writes beside them (its testRigNames, the one list of them). Throws
// when the list is missing or empty, so the tests fail rather than test nothing.
inline const std::vector<std::string>& project_rig_names() {
  static const std::vector<std::string> names = [] {
    const std::string list = project_rigs_dir() + "/names.txt";
    std::ifstream in(list);
    std::vector<std::string> read;
    for (std::string name; in >> name;) read.push_back(name);
    if (read.empty()) throw std::runtime_error(list + " is missing or empty: run npx tsx scripts/write-test-rigs.ts");
    return read;
  }();
  return names;
}

inline std::string a7_dir() {
  const char* env = std::getenv("IK_A7_DIR");
  const std::filesystem::path dir = env && *env ? env : "../shared/rigs/a7";
  return (dir.is_absolute() ? dir : std::filesystem::path(IK_REPO_ROOT) / dir).lexically_normal().string();
}

inline bool a7_present() { return std::filesystem::is_directory(a7_dir()); }

inline Rig load_a7(const std::string& name) { return load_a7_rig(a7_dir() + "/" + name + ".json"); }

// A rig the tests run on.
struct TestRig {
  std::string name;  // the file's base name: "knight"
  bool a7;           // one of the report's rigs, else the project's own
  Rig rig;
  std::string label() const { return (a7 ? "A7 " : "project ") + name; }
};

// The project's rigs, then the report's when $IK_A7_DIR exists.
inline const std::vector<TestRig>& test_rigs() {
  static const std::vector<TestRig> rigs = [] {
    std::vector<TestRig> all;
    for (const std::string& name : project_rig_names())
      all.push_back({name, false, load_a7_rig(project_rigs_dir() + "/" + name + ".json")});
    if (a7_present())
      for (const std::string& name : a7_rig_names()) all.push_back({name, true, load_a7(name)});
    return all;
  }();
  return rigs;
}

// The project's counterpart of the report's rig `a7_name` ("ikea-lamp" -> lamp), and that rig too
// when $IK_A7_DIR exists: for tests of a general property written for one rig.
inline std::vector<TestRig> rigs_like(const std::string& a7_name) {
  const std::string project = a7_name == "ikea-lamp" ? "lamp" : a7_name == "chimpanzee-hand" ? "hand" : a7_name;
  std::vector<TestRig> like;
  for (const TestRig& r : test_rigs())
    if (r.name == (r.a7 ? a7_name : project)) like.push_back(r);
  return like;
}

// Fixture of the tests that need the report's rigs: skipped without $IK_A7_DIR, failed when the
// CI environment variable is set (CI has the folder, so nothing may be skipped there).
class NeedsA7 : public ::testing::Test {
 protected:
  void SetUp() override {
    if (a7_present()) return;
    if (const char* ci = std::getenv("CI"); ci && *ci)
      FAIL() << "A7 rigs folder missing: " << a7_dir() << " (CI is set; point IK_A7_DIR at the report's A7 rigs)";
    GTEST_SKIP() << "A7 rigs not found at " << a7_dir();
  }
};

// A source of numbers in [0, 1) drawn from `rng` for protocol.h's generators: the very numbers
// std::uniform_real_distribution(-1, 1) maps to 2u - 1, which the tests were first written with.
inline auto unit_from(std::mt19937_64& rng) {
  return [&rng] { return std::generate_canonical<double, std::numeric_limits<double>::digits>(rng); };
}

// The random target set's angles (protocol.h) drawn from `rng`.
inline Eigen::VectorXd random_angles(const Kinematics& kin, std::mt19937_64& rng) {
  return protocol::random_angles(kin, unit_from(rng));
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
