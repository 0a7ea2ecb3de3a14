// Prints what wasm/native/protocol.h makes of an A7 rig, as JSON: its size, default tolerances,
// and the random and incremental target sets of a seed. tests/bench/protocol_agreement.test.ts
// compares it with the TypeScript side (web/src/rig/tolerances.ts, bench-node/targets.ts).
//
// Usage: protocol_targets RIG.json [--samples N] [--seed S]   (defaults 5 and 1)
// Output: {"size": rig units, "gradientTolerance": ..., "errorTolerance": ..., "random": SET, "incremental": SET},
// where SET = {"starts": [[degrees]], "goals": [[degrees]], "targets": [[rig units]]}, one row per sample.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "../native/a7_rig.h"
#include "../native/protocol.h"

namespace {

nlohmann::json rows(const std::vector<ik::protocol::TargetCase>& cases,
                    Eigen::VectorXd ik::protocol::TargetCase::*field) {
  nlohmann::json out = nlohmann::json::array();
  for (const ik::protocol::TargetCase& c : cases) {
    const Eigen::VectorXd& v = c.*field;
    out.push_back(std::vector<double>(v.data(), v.data() + v.size()));
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: protocol_targets RIG.json [--samples N] [--seed S]\n");
    return 2;
  }
  int samples = 5;
  std::uint32_t seed = 1;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--samples")
      samples = std::atoi(argv[i + 1]);
    else if (flag == "--seed")
      seed = static_cast<std::uint32_t>(std::strtoul(argv[i + 1], nullptr, 10));
    else {
      std::fprintf(stderr, "protocol_targets: unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  try {
    const std::string path = argv[1];
    ik::Kinematics kin(ik::load_a7_rig(path));
    const double size = ik::protocol::rig_size(kin.rig());
    const ik::protocol::Tolerances tol =
        ik::protocol::report_tolerances(std::filesystem::path(path).stem().string(), true, size);
    nlohmann::json doc = {{"size", size}, {"gradientTolerance", tol.gradient}, {"errorTolerance", tol.error}};
    for (const char* experiment : {"random", "incremental"}) {
      const auto cases = ik::protocol::target_set(kin, experiment, samples, seed);
      doc[experiment] = {{"starts", rows(cases, &ik::protocol::TargetCase::start)},
                         {"goals", rows(cases, &ik::protocol::TargetCase::goal)},
                         {"targets", rows(cases, &ik::protocol::TargetCase::target)}};
    }
    std::printf("%s\n", doc.dump().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "protocol_targets: %s\n", e.what());
    return 1;
  }
  return 0;
}
