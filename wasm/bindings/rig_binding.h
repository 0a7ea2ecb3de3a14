// The rig object that JavaScript holds: a Kinematics plus reusable buffers for the arrays that
// cross the boundary. JavaScript must call delete() on it (the TS wrapper's dispose() does).
// Calls that fail return null (or NaN, false) and leave the message for take_error().
#pragma once

#include <emscripten/val.h>

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "kinematics.h"

namespace ik::js {

class RigBinding {
 public:
  // spec: { parents: Int32Array(m), rest: Float64Array(16m, row-major canonical->rest),
  //         lengths: Float64Array(m), lower/upper: Float64Array(3m, degrees),
  //         effectors: Int32Array(n), names?: string[] }. A new rig (JavaScript owns it), or
  // null for a bad rig.
  static RigBinding* create(const emscripten::val& spec);

  int num_bones() const { return kin_.num_bones(); }
  int num_angles() const { return kin_.num_angles(); }
  int num_effectors() const { return kin_.num_effectors(); }
  emscripten::val effectors() const;                     // Int32Array(n) of bone indices
  bool set_effectors(const emscripten::val& effectors);  // false (the old list kept) if refused
  emscripten::val lower() const;                         // Float64Array(3m), degrees
  emscripten::val upper() const;                         // Float64Array(3m), degrees

  // Forward kinematics with no JavaScript values crossing (the TS wrapper's tips(), poses() and
  // their kin). io_view() sizes a buffer of #angles | 16m output numbers and returns a
  // Float64Array view on it (stale, length 0, after the WebAssembly memory grows: ask again).
  // JavaScript writes the angles (degrees) there; forward_io(what) poses the rig and writes
  // output `what` after them, returning how many numbers it wrote, or -1 on failure:
  //   kTips          3 per effector;
  //   kBoneTips      3 per bone, every bone's tip;
  //   kTipRotations  4 per effector: each effector bone's frame rotation (Kinematics::tip_rotation)
  //                  as a unit quaternion x, y, z, w (what an orientation goal targets);
  //   kPoses         16 per bone, row-major T_i.
  // forward_outputs() names them in this order.
  enum ForwardOutput { kTips, kBoneTips, kTipRotations, kPoses };
  emscripten::val io_view();
  int forward_io(int what);
  static emscripten::val forward_outputs();

  // These take angles as 3m numbers in degrees.
  emscripten::val jacobian(const emscripten::val& angles);  // Float64Array(3n*3m), row-major, per degree
  emscripten::val finite_difference_jacobian(const emscripten::val& angles, double h_deg, bool clamp);
  double objective(const emscripten::val& angles, const emscripten::val& target);          // E, NaN on failure
  emscripten::val gradient(const emscripten::val& angles, const emscripten::val& target);  // Float64Array(3m)
  emscripten::val project(const emscripten::val& angles);  // clamped copy, Float64Array(3m)
  // The start of the solvers' k-th restart (k >= 1) with option seed `seed`: Float64Array(3m),
  // degrees, inside the limits (restarts.h), for harnesses that restart other solvers alike.
  emscripten::val restart_start(double k, double seed);

  Kinematics& kinematics() { return kin_; }

 protected:
  // Reads and checks angles / target into internal buffers; the maps alias those buffers.
  Eigen::Map<const Eigen::VectorXd> read_angles(const emscripten::val& angles);
  Eigen::Map<const Eigen::VectorXd> read_target(const emscripten::val& target);

 private:
  explicit RigBinding(Kinematics kin) : kin_(std::move(kin)) {}
  static Kinematics build(const emscripten::val& spec);
  // Sizes tips_ (3 per effector) and jac_ for the current effectors (allocated on first use, inside a guarded call).
  Eigen::Map<Eigen::VectorXd> residual_buffer();
  Eigen::Map<Eigen::MatrixXd> jacobian_buffer();
  emscripten::val row_major_copy();

  Kinematics kin_;
  std::vector<double> angles_, target_, tips_, jac_, scratch_;  // sized on use
  std::vector<double> io_;                                      // forward_io(): angles | output
};

}  // namespace ik::js
