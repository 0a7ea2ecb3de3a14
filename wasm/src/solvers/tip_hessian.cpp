#include "tip_hessian.h"

#include <utility>

namespace ik {

void tip_hessian(const Kinematics& kin, int effector, Eigen::Ref<Eigen::MatrixXd> hx, Eigen::Ref<Eigen::MatrixXd> hy,
                 Eigen::Ref<Eigen::MatrixXd> hz) {
  hx.setZero();
  hy.setZero();
  hz.setZero();
  const Eigen::Vector3d p = kin.tip(kin.rig().effectors[effector]);
  const std::vector<int>& chain = kin.effector_chain(effector);
  constexpr double scale = kRadPerDeg * kRadPerDeg;
  // j runs over the chain's angles up to and including k.
  for (size_t kb = 0; kb < chain.size(); ++kb)
    for (int ka = 0; ka < 3; ++ka) {
      const int k = 3 * chain[kb] + ka;
      const Eigen::Vector3d dk = kin.joint_axis(chain[kb], ka).cross(p - kin.joint_origin(chain[kb]));
      for (size_t jb = 0; jb <= kb; ++jb)
        for (int ja = 0; ja < (jb == kb ? ka + 1 : 3); ++ja) {
          const int j = 3 * chain[jb] + ja;
          const Eigen::Vector3d d2 = scale * kin.joint_axis(chain[jb], ja).cross(dk);
          hx(j, k) = hx(k, j) = d2.x();
          hy(j, k) = hy(k, j) = d2.y();
          hz(j, k) = hz(k, j) = d2.z();
        }
    }
}

namespace {

// sum_i weights[i] * d2 tips[i] / dA dA into out(at(j), at(k)) for the angles with at(.) >= 0.
// bones(e) lists the bones of effector e's chain to visit, parents first (the whole chain, or only
// those with a kept angle: a subset of a 10,000-bone chain costs its own size squared, not the chain's).
template <class Position, class Bones>
void add_weighted(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& weights, Position at, Bones bones,
                  Eigen::Ref<Eigen::MatrixXd> out) {
  constexpr double scale = kRadPerDeg * kRadPerDeg;
  for (int e = 0; e < kin.num_effectors(); ++e) {
    const Eigen::Vector3d p = kin.tip(kin.rig().effectors[e]);
    const Eigen::Vector3d w = weights.segment<3>(3 * e);
    const auto [chain, count] = bones(e);
    // w . (a_j x d_k) = a_j . (d_k x w): one cross product per k, one dot per (j, k).
    for (size_t kb = 0; kb < count; ++kb)
      for (int ka = 0; ka < 3; ++ka) {
        const int k = at(3 * chain[kb] + ka);
        if (k < 0) continue;
        const Eigen::Vector3d c = scale * kin.joint_axis(chain[kb], ka).cross(p - kin.joint_origin(chain[kb])).cross(w);
        for (size_t jb = 0; jb <= kb; ++jb)
          for (int ja = 0; ja < (jb == kb ? ka + 1 : 3); ++ja) {
            const int j = at(3 * chain[jb] + ja);
            if (j < 0) continue;
            const double v = kin.joint_axis(chain[jb], ja).dot(c);
            out(j, k) += v;
            if (j != k) out(k, j) += v;
          }
      }
  }
}

}  // namespace

void add_weighted_tip_hessian(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& weights,
                              Eigen::Ref<Eigen::MatrixXd> out) {
  add_weighted(
      kin, weights, [](int angle) { return angle; },
      [&kin](int e) { return std::make_pair(kin.effector_chain(e).data(), kin.effector_chain(e).size()); }, out);
}

void add_weighted_tip_hessian(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& weights,
                              const std::vector<int>& position, std::vector<int>& scratch,
                              Eigen::Ref<Eigen::MatrixXd> out) {
  auto kept = [&position](int bone) {
    return position[3 * bone] >= 0 || position[3 * bone + 1] >= 0 || position[3 * bone + 2] >= 0;
  };
  add_weighted(
      kin, weights, [&position](int angle) { return position[angle]; },
      [&](int e) {
        size_t count = 0;
        for (int bone : kin.effector_chain(e))
          if (kept(bone)) scratch[count++] = bone;
        return std::make_pair(static_cast<const int*>(scratch.data()), count);
      },
      out);
}

}  // namespace ik
