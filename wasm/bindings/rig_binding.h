// The rig object that JavaScript holds: a Kinematics plus reusable buffers for the arrays that
// cross the boundary. JavaScript must call delete() on it (the TS wrapper's dispose() does).
#pragma once

#include <emscripten/val.h>

#include <Eigen/Core>
#include <vector>

#include "kinematics.h"

namespace ik::js {

class RigBinding {
 public:
  // spec: { parents: Int32Array(m), rest: Float64Array(16m, row-major canonical->rest),
  //         lengths: Float64Array(m), lower/upper: Float64Array(3m, degrees),
  //         effectors: Int32Array(n), names?: string[] }. Throws a JS Error on a bad rig.
  explicit RigBinding(const emscripten::val& spec);

  int num_bones() const { return kin_.num_bones(); }
  int num_angles() const { return kin_.num_angles(); }
  int num_effectors() const { return kin_.num_effectors(); }
  emscripten::val effectors() const;             // Int32Array(n) of bone indices
  void set_effectors(const emscripten::val& effectors);
  emscripten::val lower() const;                 // Float64Array(3m), degrees
  emscripten::val upper() const;                 // Float64Array(3m), degrees

  // All take angles as 3m numbers in degrees.
  emscripten::val tips(const emscripten::val& angles);       // Float64Array(3n)
  emscripten::val bone_tips(const emscripten::val& angles);  // Float64Array(3m), every bone's tip
  emscripten::val poses(const emscripten::val& angles);      // Float64Array(16m), row-major T_i
  emscripten::val jacobian(const emscripten::val& angles);   // Float64Array(3n*3m), row-major, per degree
  emscripten::val finite_difference_jacobian(const emscripten::val& angles, double h_deg, bool clamp);
  double objective(const emscripten::val& angles, const emscripten::val& target);  // E
  emscripten::val gradient(const emscripten::val& angles, const emscripten::val& target);  // Float64Array(3m)
  emscripten::val project(const emscripten::val& angles);    // clamped copy, Float64Array(3m)

  Kinematics& kinematics() { return kin_; }

 protected:
  // Reads and checks angles / target into internal buffers; the maps alias those buffers.
  Eigen::Map<const Eigen::VectorXd> read_angles(const emscripten::val& angles);
  Eigen::Map<const Eigen::VectorXd> read_target(const emscripten::val& target);

 private:
  static Kinematics build(const emscripten::val& spec);
  emscripten::val row_major_copy();

  Kinematics kin_;
  std::vector<double> angles_, target_, tips_, jac_, scratch_;
};

}  // namespace ik::js
