// A small solver benchmark on the report's target sets (PROTOCOL.md): per method, median and
// mean iterations, median and mean time per solve, E average / IQM / max, and the success rate
// (E < error tolerance). The same program builds natively and for Node (build/wasm/solver_speed.cjs).
// The project's full benchmark CLI is `npm run bench`; this one only checks the solvers.
//
// Usage: solver_speed RIG.json [--methods gd,bfgs,...] [--set incremental|random|both]
//                     [--samples N] [--gd-samples N] [--paper] [--restarts N] [--stall N] [--gn-cutoff C] [--seed S]
//                     [--no-escape] [--json]
// Columns: iterations, time (median, mean, p95), E, success, and the mean number of restarts.
// --json prints the rows instead as one JSON array (times in seconds), for programs to read:
//   [{"set", "method", "samples", "iterations_median", "iterations_mean", "t_median_s", "t_mean_s",
//     "t_p95_s", "E_avg", "E_iqm", "E_max", "success_rate", "restarts_mean"}]
// Target sets and tolerances are the protocol's (../native/protocol.h): the same sets as
// `npm run bench` for the same seed (default 1 there too); the rig's default tolerances by its
// file's base name (beast 0.01, 0.002; the report's other rigs 1e-4, 2e-4; any other rig scaled
// by its size); time budget 1 s. Each (set, method) first solves its targets untimed for 0.3 s (warm-up).
// Exits 1 if a solve returns invalid_input or numerical_failure, or leaves the limits.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "../native/a7_rig.h"
#include "../native/protocol.h"
#include "kinematics.h"
#include "solvers/solver_registry.h"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

// Mean of the middle half of the sorted values (the report's E_IQM).
double interquartile_mean(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t lo = v.size() / 4, hi = v.size() - v.size() / 4;
  return std::accumulate(v.begin() + lo, v.begin() + hi, 0.0) / (hi - lo);
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

// One (set, method) of the output; times in seconds.
struct Row {
  std::string set, method;
  int samples;
  double iterations_median, iterations_mean, t_median_s, t_mean_s, t_p95_s, E_avg, E_iqm, E_max, success_rate,
      restarts_mean;
};

// The rows as a table for people: times in microseconds, success in percent.
void print_table(const std::vector<Row>& rows) {
  std::printf("%-11s %-6s %5s %8s %8s %10s %10s %10s %10s %10s %7s %7s %10s\n", "set", "method", "n", "it_med",
              "it_avg", "t_med_us", "t_avg_us", "E_avg", "E_iqm", "E_max", "success", "rs_avg", "t_p95_us");
  for (const Row& r : rows)
    std::printf("%-11s %-6s %5d %8.1f %8.2f %10.2f %10.2f %10.3g %10.3g %10.3g %6.1f%% %7.2f %10.2f\n", r.set.c_str(),
                r.method.c_str(), r.samples, r.iterations_median, r.iterations_mean, 1e6 * r.t_median_s,
                1e6 * r.t_mean_s, r.E_avg, r.E_iqm, r.E_max, 100.0 * r.success_rate, r.restarts_mean, 1e6 * r.t_p95_s);
}

// The rows as one JSON array, the field names of the header comment.
void print_json(const std::vector<Row>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const Row& r : rows)
    out.push_back({{"set", r.set},
                   {"method", r.method},
                   {"samples", r.samples},
                   {"iterations_median", r.iterations_median},
                   {"iterations_mean", r.iterations_mean},
                   {"t_median_s", r.t_median_s},
                   {"t_mean_s", r.t_mean_s},
                   {"t_p95_s", r.t_p95_s},
                   {"E_avg", r.E_avg},
                   {"E_iqm", r.E_iqm},
                   {"E_max", r.E_max},
                   {"success_rate", r.success_rate},
                   {"restarts_mean", r.restarts_mean}});
  std::printf("%s\n", out.dump().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(
        stderr,
        "usage: solver_speed RIG.json [--methods a,b] [--set incremental|random|both] [--samples N]\n"
        "                    [--gd-samples N] [--paper] [--restarts N] [--stall N] [--gn-cutoff C] [--seed S]\n"
        "                    [--no-escape] [--json]\n");
    return 2;
  }
  const std::string path = argv[1];
  std::vector<std::string> methods = ik::solver_names();
  std::string set = "both";
  int samples = 200, gd_samples = -1, restarts = 0, stall = 30;
  std::uint32_t seed = 1;
  bool paper = false, escape = true, json = false;
  double gn_cutoff = ik::SolverOptions().gn_singular_cutoff;
  for (int i = 2; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", flag.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (flag == "--methods")
      methods = split(value());
    else if (flag == "--set")
      set = value();
    else if (flag == "--samples")
      samples = std::atoi(value().c_str());
    else if (flag == "--gd-samples")
      gd_samples = std::atoi(value().c_str());
    else if (flag == "--restarts")
      restarts = std::atoi(value().c_str());
    else if (flag == "--stall")
      stall = std::atoi(value().c_str());
    else if (flag == "--gn-cutoff")
      gn_cutoff = std::atof(value().c_str());
    else if (flag == "--seed")
      seed = static_cast<std::uint32_t>(std::strtoul(value().c_str(), nullptr, 10));
    else if (flag == "--paper")
      paper = true;
    else if (flag == "--no-escape")
      escape = false;
    else if (flag == "--json")
      json = true;
    else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  if (gd_samples < 0) gd_samples = samples;
  int status = 0;
  try {
    ik::Kinematics kin(ik::load_a7_rig(path));
    const ik::protocol::Tolerances tolerances = ik::protocol::report_tolerances(
        std::filesystem::path(path).stem().string(), true, ik::protocol::rig_size(kin.rig()));
    std::vector<Row> rows;
    for (const std::string which : {"incremental", "random"}) {
      if (set != "both" && set != which) continue;
      for (const std::string& method : methods) {
        ik::SolverOptions options;
        options.gradient_tolerance = tolerances.gradient;
        options.error_tolerance = tolerances.error;
        options.paper_mode = paper;
        options.restarts = restarts;
        options.stall_iterations = stall;
        options.gn_singular_cutoff = gn_cutoff;
        options.escape_saddles = escape;
        std::unique_ptr<ik::Solver> solver = ik::make_solver(method, kin, options);
        const int count = method == "gd" ? gd_samples : samples;
        const std::vector<ik::protocol::TargetCase> cases = ik::protocol::target_set(kin, which, count, seed);
        // Untimed warm-up: WebAssembly engines compile hot code in tiers (V8: baseline first, the
        // optimising tier after a while), so solve the targets over and over for 0.3 s first.
        const auto warm = std::chrono::steady_clock::now();
        for (size_t k = 0; std::chrono::steady_clock::now() - warm < std::chrono::milliseconds(300); ++k)
          solver->solve(cases[k % cases.size()].start, cases[k % cases.size()].target);
        std::vector<double> iterations, seconds, errors, restart_counts;
        int successes = 0;
        for (const ik::protocol::TargetCase& c : cases) {
          const auto t0 = std::chrono::steady_clock::now();
          const ik::SolverSummary& s = solver->solve(c.start, c.target);
          seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
          iterations.push_back(s.iterations);
          restart_counts.push_back(s.restarts);
          errors.push_back(s.E);
          successes += s.E < options.error_tolerance;
          const bool inside =
              ((s.angles - kin.lower()).array() >= 0).all() && ((kin.upper() - s.angles).array() >= 0).all();
          if (s.stop_reason == ik::StopReason::invalid_input || s.stop_reason == ik::StopReason::numerical_failure ||
              !inside) {
            std::fprintf(stderr, "%s %s: %s %s\n", method.c_str(), which.c_str(), ik::stop_reason_name(s.stop_reason),
                         inside ? s.message.c_str() : "angles outside the limits");
            status = 1;
          }
        }
        std::vector<double> sorted = seconds;
        std::sort(sorted.begin(), sorted.end());
        rows.push_back({which, method, count, median(iterations), mean(iterations), median(seconds), mean(seconds),
                        sorted[static_cast<size_t>(0.95 * (sorted.size() - 1))], mean(errors),
                        interquartile_mean(errors), *std::max_element(errors.begin(), errors.end()),
                        static_cast<double>(successes) / count, mean(restart_counts)});
      }
    }
    if (json)
      print_json(rows);
    else
      print_table(rows);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return status;
}
