// Times the analytic Jacobian against the central finite-difference Jacobian on an A7 rig.
// Usage: jacobian_cost RIG.json [repeats]
// Prints the median time per evaluation (microseconds) over repeated batches, and the ratio, at
// 64 poses drawn as the random target set draws its angles.
// Builds natively (wasm/tools) and with Emscripten for Node (scripts/jacobian-cost.sh), so the
// same code measures both engines.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "../native/a7_rig.h"
#include "../native/protocol.h"
#include "finite_difference_jacobian.h"
#include "kinematics.h"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Median over `batches` of the time per call (microseconds) of `body` run `per_batch` times.
template <class Body>
double median_us(int batches, int per_batch, Body body) {
  std::vector<double> times;
  for (int b = 0; b < batches; ++b) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < per_batch; ++i) body(i);
    const auto t1 = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count() / per_batch);
  }
  return median(times);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: jacobian_cost RIG.json [evaluations per batch]\n");
    return 2;
  }
  try {
    ik::Kinematics kin(ik::load_a7_rig(argv[1]));
    const int per_batch = argc > 2 ? std::atoi(argv[2]) : 2000;
    ik::Mulberry32 unit = ik::stream_for(1, "jacobian-cost");
    std::vector<Eigen::VectorXd> poses;  // poses of the random target set (protocol.h)
    for (int k = 0; k < 64; ++k) poses.push_back(ik::protocol::random_angles(kin, unit));
    Eigen::VectorXd tips(kin.num_residuals()), scratch(kin.num_angles()), plus(kin.num_residuals()),
        minus(kin.num_residuals());
    Eigen::MatrixXd jac(kin.num_residuals(), kin.num_angles());
    double sink = 0;
    const double analytic = median_us(31, per_batch, [&](int i) {
      kin.jacobian(poses[i % poses.size()], tips, jac);
      sink += jac(0, 3);
    });
    const double differences = median_us(31, std::max(1, per_batch / 20), [&](int i) {
      ik::finite_difference_jacobian(kin, poses[i % poses.size()], 1e-7, true, scratch, plus, minus, jac);
      sink += jac(0, 3);
    });
    std::printf("rig %s: %d bones, %d effectors, Jacobian %dx%d\n", argv[1], kin.num_bones(), kin.num_effectors(),
                kin.num_residuals(), kin.num_angles());
    std::printf("analytic Jacobian:          median %.3f us\n", analytic);
    std::printf("central differences (paper): median %.3f us\n", differences);
    std::printf("ratio differences / analytic: %.1fx%s\n", differences / analytic, sink == 12345.678 ? " " : "");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jacobian_cost: %s\n", e.what());
    return 1;
  }
  return 0;
}
