// embind bindings for the rig and its kinematics. Arrays cross as typed arrays in bulk;
// results are copied out. A failed call returns null (NaN, false) and leaves its message for
// takeError() (js_arrays.h says why nothing is thrown).
#include <emscripten/bind.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <limits>

#include "finite_difference_jacobian.h"
#include "js_arrays.h"
#include "kinematics.h"
#include "objective.h"
#include "rig_binding.h"
#include "size_limits.h"
#include "solvers/restarts.h"

namespace ik::js {

using emscripten::val;

RigBinding* RigBinding::create(const val& spec) {
  return guarded([&] { return new RigBinding(build(spec)); }, static_cast<RigBinding*>(nullptr));
}

Eigen::Map<Eigen::MatrixXd> RigBinding::jacobian_buffer() {
  jac_.resize(static_cast<size_t>(kin_.num_residuals()) * kin_.num_angles());
  return Eigen::Map<Eigen::MatrixXd>(jac_.data(), kin_.num_residuals(), kin_.num_angles());
}

Eigen::Map<Eigen::VectorXd> RigBinding::residual_buffer() {
  tips_.resize(kin_.num_residuals());
  return Eigen::Map<Eigen::VectorXd>(tips_.data(), tips_.size());
}

Kinematics RigBinding::build(const val& spec) {
  std::vector<int> parents, effectors;
  copy_in(spec["parents"], parents, "parents");
  const size_t n = parents.size();
  std::vector<double> rest, lengths, lower, upper;
  copy_in(spec["rest"], 16 * n, rest, "rest (16 row-major numbers per bone)");
  copy_in(spec["lengths"], n, lengths, "lengths");
  copy_in(spec["lower"], 3 * n, lower, "lower (3 limits per bone, degrees)");
  copy_in(spec["upper"], 3 * n, upper, "upper (3 limits per bone, degrees)");
  copy_in(spec["effectors"], effectors, "effectors");
  const val names = spec["names"];
  Rig rig;
  rig.bones.resize(n);
  for (size_t i = 0; i < n; ++i) {
    Bone& b = rig.bones[i];
    if (!names.isUndefined() && !names.isNull() && i < names["length"].as<size_t>())
      b.name = names[i].as<std::string>();
    b.parent = parents[i];
    b.rest = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(&rest[16 * i]);
    b.length = lengths[i];
    b.min_deg = Eigen::Map<const Eigen::Vector3d>(&lower[3 * i]);
    b.max_deg = Eigen::Map<const Eigen::Vector3d>(&upper[3 * i]);
  }
  rig.effectors = effectors;
  const val root_lower = spec["rootLower"], root_upper = spec["rootUpper"];
  if (!root_lower.isUndefined() || !root_upper.isUndefined()) {
    std::vector<double> low, high;
    copy_in(root_lower, 3, low, "rootLower (the floating root's x, y, z lower bounds, rig units)");
    copy_in(root_upper, 3, high, "rootUpper (the floating root's x, y, z upper bounds, rig units)");
    rig.floating_root.on = true;
    rig.floating_root.min = Eigen::Map<const Eigen::Vector3d>(low.data());
    rig.floating_root.max = Eigen::Map<const Eigen::Vector3d>(high.data());
  }
  return Kinematics(std::move(rig));
}

Eigen::Map<const Eigen::VectorXd> RigBinding::read_angles(const val& angles) {
  copy_in(angles, kin_.num_angles(), angles_, "angles");
  check_finite(angles_.data(), angles_.size(), "angles");
  return Eigen::Map<const Eigen::VectorXd>(angles_.data(), angles_.size());
}

Eigen::Map<const Eigen::VectorXd> RigBinding::read_target(const val& target) {
  copy_in(target, kin_.num_residuals(), target_, "target");
  check_finite(target_.data(), target_.size(), "target");
  return Eigen::Map<const Eigen::VectorXd>(target_.data(), target_.size());
}

val RigBinding::io_view() {
  return guarded(
      [&] {
        const size_t size = static_cast<size_t>(kin_.num_angles()) + 16 * static_cast<size_t>(kin_.num_bones());
        if (io_.size() != size) io_.assign(size, 0.0);  // kept otherwise: a view asked anew reads the last output
        return val(emscripten::typed_memory_view(io_.size(), io_.data()));
      },
      val::null());
}

int RigBinding::forward_io(int what) {
  return guarded(
      [&] {
        const int n = kin_.num_angles();
        if (io_.size() != static_cast<size_t>(n) + 16 * static_cast<size_t>(kin_.num_bones()))
          throw RigError("forwardIo before ioView");
        check_finite(io_.data(), n, "angles");
        kin_.forward(Eigen::Map<const Eigen::VectorXd>(io_.data(), n));
        double* out = io_.data() + n;
        const auto& effectors = kin_.rig().effectors;
        switch (what) {
          case kTips:
            for (size_t e = 0; e < effectors.size(); ++e)
              Eigen::Map<Eigen::Vector3d>(out + 3 * e) = kin_.tip(effectors[e]);
            return 3 * kin_.num_effectors();
          case kBoneTips:
            for (int i = 0; i < kin_.num_bones(); ++i) Eigen::Map<Eigen::Vector3d>(out + 3 * i) = kin_.tip(i);
            return 3 * kin_.num_bones();
          case kTipRotations:
            for (size_t e = 0; e < effectors.size(); ++e)
              Eigen::Map<Eigen::Vector4d>(out + 4 * e) = Eigen::Quaterniond(kin_.tip_rotation(effectors[e])).coeffs();
            return 4 * kin_.num_effectors();
          case kPoses:
            for (int i = 0; i < kin_.num_bones(); ++i)
              Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(out + 16 * i) = kin_.pose(i).matrix();
            return 16 * kin_.num_bones();
          default: throw RigError("forwardIo: no output " + std::to_string(what));
        }
      },
      -1);
}

val RigBinding::forward_outputs() {
  val names = val::array();
  for (const char* name : {"tips", "boneTips", "tipRotations", "poses"}) names.call<void>("push", std::string(name));
  return names;
}

val RigBinding::jacobian(const val& angles) {
  return guarded(
      [&] {
        kin_.jacobian(read_angles(angles), residual_buffer(), jacobian_buffer());
        return row_major_copy();
      },
      val::null());
}

val RigBinding::finite_difference_jacobian(const val& angles, double h_deg, bool clamp) {
  return guarded(
      [&] {
        if (!(h_deg > 0)) throw RigError("finite difference step must be > 0 degrees");
        const auto a = read_angles(angles);
        Eigen::VectorXd scratch(kin_.num_angles()), plus(kin_.num_residuals()), minus(kin_.num_residuals());
        ik::finite_difference_jacobian(kin_, a, h_deg, clamp, scratch, plus, minus, jacobian_buffer());
        return row_major_copy();
      },
      val::null());
}

val RigBinding::row_major_copy() {
  const int rows = kin_.num_residuals(), cols = kin_.num_angles();
  scratch_.resize(static_cast<size_t>(rows) * cols);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(scratch_.data(), rows, cols) =
      Eigen::Map<const Eigen::MatrixXd>(jac_.data(), rows, cols);
  return copy_out(scratch_.data(), scratch_.size());
}

double RigBinding::objective(const val& angles, const val& target) {
  return guarded(
      [&] {
        const auto a = read_angles(angles);
        return ik::objective(kin_, a, read_target(target), residual_buffer());
      },
      std::numeric_limits<double>::quiet_NaN());
}

val RigBinding::gradient(const val& angles, const val& target) {
  return guarded(
      [&] {
        const auto a = read_angles(angles);
        const auto t = read_target(target);
        scratch_.resize(kin_.num_angles());
        objective_and_gradient(kin_, a, t, residual_buffer(), jacobian_buffer(),
                               Eigen::Map<Eigen::VectorXd>(scratch_.data(), scratch_.size()));
        return copy_out(scratch_.data(), scratch_.size());
      },
      val::null());
}

val RigBinding::project(const val& angles) {
  return guarded(
      [&] {
        read_angles(angles);  // checked, into angles_
        Eigen::Map<Eigen::VectorXd> a(angles_.data(), angles_.size());
        kin_.project(a);
        return copy_out(angles_.data(), angles_.size());
      },
      val::null());
}

val RigBinding::restart_start(double k, double seed) {
  return guarded(
      [&] {
        if (!(k >= 1 && k <= kMaxRestartIndex && k == std::floor(k)))
          throw RigError("a restart index is an integer in 1.." + std::to_string(kMaxRestartIndex));
        if (!(seed >= 0 && seed <= 4294967295.0 && seed == std::floor(seed)))
          throw RigError("a seed is an integer in [0, 2^32)");
        const int n = kin_.num_angles();
        const QuasiRandom sequence(n, static_cast<std::uint32_t>(seed));
        Eigen::VectorXd unit(n), start(n);
        Restarts::start_of(sequence, static_cast<long>(k), kin_.lower(), kin_.upper(), unit, start);
        return copy_out(start.data(), start.size());
      },
      val::null());
}

bool RigBinding::set_effectors(const val& effectors) {
  return guarded(
      [&] {
        std::vector<int> list;
        copy_in(effectors, list, "effectors");
        kin_.set_effectors(list);
        return true;
      },
      false);
}

val RigBinding::effectors() const {
  const auto& e = kin_.rig().effectors;
  return val::global("Int32Array").new_(emscripten::typed_memory_view(e.size(), e.data()));
}

val RigBinding::lower() const { return copy_out(kin_.lower().data(), kin_.lower().size()); }
val RigBinding::upper() const { return copy_out(kin_.upper().data(), kin_.upper().size()); }

}  // namespace ik::js

EMSCRIPTEN_BINDINGS(ik_kinematics) {
  using ik::js::RigBinding;
  emscripten::function("takeError", &ik::js::take_error);
  emscripten::class_<RigBinding>("Rig")
      .class_function("create", &RigBinding::create, emscripten::allow_raw_pointers())
      .property("numBones", &RigBinding::num_bones)
      .property("numAngles", &RigBinding::num_angles)
      .property("numEffectors", &RigBinding::num_effectors)
      .function("effectors", &RigBinding::effectors)
      .function("setEffectors", &RigBinding::set_effectors)
      .function("lower", &RigBinding::lower)
      .function("upper", &RigBinding::upper)
      .function("ioView", &RigBinding::io_view)
      .function("forwardIo", &RigBinding::forward_io)
      .class_function("forwardOutputs", &RigBinding::forward_outputs)
      .function("jacobian", &RigBinding::jacobian)
      .function("finiteDifferenceJacobian", &RigBinding::finite_difference_jacobian)
      .function("objective", &RigBinding::objective)
      .function("gradient", &RigBinding::gradient)
      .function("project", &RigBinding::project)
      .function("restartStart", &RigBinding::restart_start);
}
