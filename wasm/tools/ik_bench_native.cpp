// The native engine of `npm run bench`: runs one method over a batch of solves prepared by the
// TypeScript command line (bench-node/run_native.ts), with the same C++ core the WebAssembly build
// uses, and writes one result line per solve.
//
// Usage:
//   ik_bench_native --rig RIG.json --method NAME --input JOB.bin --output RESULTS.jsonl
//                   [--gradient-tolerance X] [--error-tolerance Y] [--tip-tolerance Z] [--time-budget SECONDS]
//                   [--paper] [--restarts N]
//                   [--max-joint-move D] [--page-goals ROWS]
//                   [--goals position|pose] [--orientation-tolerance DEG]
//   ik_bench_native --list-methods     prints the methods it knows (the core's registry, the
//                                      default first, then "kdl" and "kdl_nr_jl" when built with
//                                      Orocos KDL) as a JSON array of names
// Method "kdl" (native builds with Orocos KDL only, native/kdl/kdl_solver.h) solves with KDL's
// tree solvers under the same tolerances, time budget and restarts. Method "kdl_nr_jl"
// (native/kdl/kdl_nr_jl.h) is KDL's ChainIkSolverPos_NR_JL as TRAC-IK's harness runs it: whole
// poses of one end effector, one iteration per call until success or the time budget.
// --tip-tolerance Z > 0 makes "on target" every tip within Z (rig units) of its target (SolverOptions::
// tip_tolerance) instead of E < Y. --max-joint-move D > 0 caps how far a joint moves in one solve
// (SolverOptions::max_joint_move, rig units). --page-goals ROWS: records with a dragged effector
// are solved towards the page's goals (bench-node/drag_goals.ts): the dragged effector yields,
// the others keep their positions and, where row d (d the dragged effector; comma-separated, one
// digit per effector) has a 1, the frames they had at the start of the record's path (the last
// record that was not chained).
// --goals pose: each record also carries each effector's target orientation, and every method
// solves towards the whole poses (Goals of native/pose_goals.h: position and orientation per
// effector, weight 1; kdl with its rotation rows weighted); on target then also needs every
// orientation within SolverOptions::orientation_tolerance_deg (0.5 degrees; --orientation-tolerance DEG,
// > 0, sets it: the bench's tracik experiment asks for 1e-5 rad).
//
// JOB.bin, little-endian:
//   header  char[8] "IKBJOB1\0", int32 count, int32 #angles, int32 #residuals, int32 #orientation
//           numbers (0, or with --goals pose 4 per effector)
//   count records of float64: chained (0 or 1), dragged effector (-1: none), start (#angles,
//   degrees), target (#residuals, rig units), then with --goals pose the target orientations
//   (quaternions x, y, z, w, 4 per effector). A chained record starts from the previous record's
//   solution instead of its start (drag and reach paths).
// RESULTS.jsonl: one JSON object per record and line, numbers written to round-trip exactly:
//   {"E", "gradient_norm", "iterations", "function_evaluations", "jacobian_evaluations", "seconds",
//    "stop_reason", "wobble_during", "wobble_after", "tip_distance", "jump_deg", "jump_move"},
//   "angles" (records with a dragged effector), and with --goals
//   pose "rot_err_deg": the largest angle of an effector's frame from its target orientation at the
//   solution (degrees, from forward kinematics of the returned angles) and "twist_max" (pose_goals.h
//   largest_twist_component); E is then the positions'
//   1/2 |x(A) - x_b|^2 at the solution, from forward kinematics too (the solver's E holds the
//   orientation rows as well).
// `seconds` is steady_clock around Solver::solve(). tip_distance: the largest distance of an
// effector's tip from its target at the solution (rig units); jump_deg: the largest change of one
// angle from the start to the solution (degrees; an angle whose limits span 360 degrees or more
// the shortest way round, as bench-node/evaluate.ts largestChange); jump_move: the largest
// distance a joint (the head or the tip of any bone) moved from the start to the solution (rig
// units); all three null for invalid input. Records with a dragged effector also carry "angles",
// the solution (degrees), from which the command line judges the step's limbs. Wobble (records
// with a dragged effector and other effectors to pin; null otherwise): the largest distance of a
// pinned effector from its target, over the iterates of a replay of the same solve
// (max_iterations = the solve's count, no time budget) for "during", at the solution for "after".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "../native/a7_rig.h"
#include "../native/pose_goals.h"
#include "kinematics.h"
#include "solvers/solver.h"
#include "solvers/solver_registry.h"
#ifdef IK_HAVE_KDL
#include "../native/kdl/kdl_nr_jl.h"
#include "../native/kdl/kdl_solver.h"
#endif

namespace {

struct Args {
  std::string rig, method, input, output;
  ik::SolverOptions options;
  bool list_methods = false;
  bool pose = false;  // --goals pose
  // --page-goals ROWS: per dragged effector d, one digit per effector, 1 where it keeps its frame
  // (bench-node/drag_goals.ts); empty: plain targets.
  std::vector<std::string> page_goals;
};

[[noreturn]] void usage(const std::string& problem) {
  throw std::invalid_argument(problem +
                              "\nusage: ik_bench_native --rig RIG.json --method NAME --input JOB.bin --output "
                              "RESULTS.jsonl [--gradient-tolerance X] [--error-tolerance Y] [--tip-tolerance Z] "
                              "[--time-budget S] [--paper] [--restarts N]\n"
                              "       [--max-joint-move D] [--page-goals ROWS]\n"
                              "       [--goals position|pose] [--orientation-tolerance DEG]\n"
                              "       ik_bench_native --list-methods");
}

double number_arg(const std::string& flag, const char* text) {
  char* end = nullptr;
  const double x = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(x) || x < 0)
    usage(flag + ": \"" + text + "\" is not a number >= 0");
  return x;
}

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--paper") {
      a.options.paper_mode = true;
      continue;
    }
    if (flag == "--list-methods") {
      a.list_methods = true;
      continue;
    }
    if (i + 1 >= argc) usage(flag + " needs a value");
    const char* value = argv[++i];
    if (flag == "--rig")
      a.rig = value;
    else if (flag == "--method")
      a.method = value;
    else if (flag == "--input")
      a.input = value;
    else if (flag == "--output")
      a.output = value;
    else if (flag == "--gradient-tolerance")
      a.options.gradient_tolerance = number_arg(flag, value);
    else if (flag == "--error-tolerance")
      a.options.error_tolerance = number_arg(flag, value);
    else if (flag == "--tip-tolerance")
      a.options.tip_tolerance = number_arg(flag, value);
    else if (flag == "--orientation-tolerance") {
      a.options.orientation_tolerance_deg = number_arg(flag, value);
      if (a.options.orientation_tolerance_deg <= 0) usage(flag + ": \"" + value + "\" is not a number > 0");
    } else if (flag == "--max-joint-move")
      a.options.max_joint_move = number_arg(flag, value);
    else if (flag == "--page-goals") {
      std::string rows = value;
      for (size_t at = 0; at <= rows.size();) {
        const size_t comma = std::min(rows.find(',', at), rows.size());
        a.page_goals.push_back(rows.substr(at, comma - at));
        at = comma + 1;
      }
    } else if (flag == "--time-budget")
      a.options.time_budget_s = number_arg(flag, value);
    else if (flag == "--restarts")
      a.options.restarts = static_cast<int>(number_arg(flag, value));
    else if (flag == "--goals") {
      const std::string kind = value;
      if (kind != "position" && kind != "pose") usage("--goals: \"" + kind + "\" is not position or pose");
      a.pose = kind == "pose";
    } else
      usage("unknown option " + flag);
  }
  if (!a.list_methods && (a.rig.empty() || a.method.empty() || a.input.empty() || a.output.empty()))
    usage("--rig, --method, --input and --output are required");
  return a;
}

struct Job {
  int count = 0, num_angles = 0, num_residuals = 0, num_orientations = 0;
  std::vector<double> records;  // count x (2 + #angles + #residuals + #orientation numbers)
  int stride() const { return 2 + num_angles + num_residuals + num_orientations; }
};

Job read_job(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open file");
  char magic[8];
  std::int32_t header[4];
  in.read(magic, sizeof magic);
  in.read(reinterpret_cast<char*>(header), sizeof header);
  if (!in || std::memcmp(magic, "IKBJOB1", 8) != 0) throw std::runtime_error(path + ": not a job file");
  Job job;
  job.count = header[0];
  job.num_angles = header[1];
  job.num_residuals = header[2];
  job.num_orientations = header[3];
  if (job.count < 0 || job.num_angles <= 0 || job.num_residuals <= 0 || job.num_orientations < 0)
    throw std::runtime_error(path + ": bad header");
  job.records.resize(static_cast<size_t>(job.count) * job.stride());
  in.read(reinterpret_cast<char*>(job.records.data()),
          static_cast<std::streamsize>(job.records.size() * sizeof(double)));
  if (!in) throw std::runtime_error(path + ": truncated");
  return job;
}

// Largest distance (rig units) of an effector other than `skip` (-1: none) from its target, with
// `kin` posed at `angles`; `tips` is workspace.
double largest_distance(ik::Kinematics& kin, const Eigen::VectorXd& angles,
                        const Eigen::Ref<const Eigen::VectorXd>& target, int skip, Eigen::VectorXd& tips) {
  kin.tips(angles, tips);
  double worst = 0;
  for (int e = 0; e < kin.num_effectors(); ++e)
    if (e != skip) worst = std::max(worst, (tips.segment<3>(3 * e) - target.segment<3>(3 * e)).norm());
  return worst;
}

// Wobble during a solve of `iterations` iterations from `start` that ended `after` (rig units) off
// the pinned targets: the largest distance of a pinned effector (every one but `dragged`) from its
// target over the iterates of a replay of the same solve, stepped one iteration at a time with
// max_iterations = `iterations` and no time budget (deterministic, so the same iterates).
double replay_wobble(const Args& args, ik::Kinematics& kin, ik::Kinematics& observer, const Eigen::VectorXd& start,
                     const Eigen::VectorXd& target, const ik::Goals* goals, int dragged, int iterations, double after,
                     Eigen::VectorXd& tips) {
  ik::SolverOptions options = args.options;
  options.max_iterations = iterations;
  options.time_budget_s = 0;
  std::unique_ptr<ik::Solver> replay = ik::make_solver(args.method, kin, options);
  if (goals)
    replay->start(start, *goals);
  else
    replay->start(start, target);
  double during = 0;
  int seen = 0;
  while (replay->running()) {
    replay->step();
    if (replay->summary().iterations == seen) continue;
    seen = replay->summary().iterations;
    during = std::max(during, largest_distance(observer, replay->angles(), target, dragged, tips));
  }
  return seen == 0 ? after : during;  // no iterate: the start already met a stopping test
}

// The largest change of one angle from `from` to `to` (degrees): an angle whose limits span a full
// turn or more the shortest way round, min(|d| mod 360, 360 - |d| mod 360); a limited one |d|.
double largest_angle_change(const ik::Kinematics& kin, const Eigen::VectorXd& from, const Eigen::VectorXd& to) {
  double worst = 0;
  for (int i = 0; i < kin.num_angles(); ++i) {
    const double d = std::abs(to[i] - from[i]);
    const double r = std::fmod(d, 360.0);
    worst = std::max(worst, kin.upper()[i] - kin.lower()[i] >= 360 ? std::min(r, 360 - r) : d);
  }
  return worst;
}

// Every bone's head (joint origin) and tip at `angles`, 6 per bone (rig units), into `joints`.
void joint_positions(ik::Kinematics& kin, const Eigen::VectorXd& angles, Eigen::VectorXd& joints) {
  kin.forward(angles);
  joints.resize(6 * kin.num_bones());
  for (int b = 0; b < kin.num_bones(); ++b) {
    joints.segment<3>(6 * b) = kin.joint_origin(b);
    joints.segment<3>(6 * b + 3) = kin.tip(b);
  }
}

// The largest distance (rig units) any joint (the head or the tip of a bone) moves from the pose at
// `from` to the pose at `to`; `a` and `b` are workspace.
double largest_joint_move(ik::Kinematics& kin, const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                          Eigen::VectorXd& a, Eigen::VectorXd& b) {
  joint_positions(kin, from, a);
  joint_positions(kin, to, b);
  double worst = 0;
  for (int j = 0; j < a.size() / 3; ++j) worst = std::max(worst, (b.segment<3>(3 * j) - a.segment<3>(3 * j)).norm());
  return worst;
}

// The registry's method names, the default first, then "kdl" when built with KDL, as a JSON
// array on stdout.
void list_methods() {
  std::vector<std::string> names = ik::solver_names();
#ifdef IK_HAVE_KDL
  names.push_back("kdl");
  names.push_back("kdl_nr_jl");
#endif
  std::printf("%s\n", nlohmann::json(names).dump().c_str());
}

// One solve's outcome, whichever method ran it.
struct Outcome {
  Eigen::VectorXd angles;  // degrees
  double E = 0, gradient_norm = 0;
  int iterations = 0, fevals = 0, jevals = 0;
  std::string reason;
  bool valid = true;
};

// Runs the method named in `args` on `kin`: a core solver from the registry, or KDL's.
class Method {
 public:
  Method(const Args& args, ik::Kinematics& kin) : args_(args), kin_(kin) {
    if (args.method == "kdl" || args.method == "kdl_nr_jl") {
#ifdef IK_HAVE_KDL
      if (args.method == "kdl")
        kdl_ = std::make_unique<ik::kdl::KdlSolver>(kin.rig(), args.options);
      else
        nr_jl_ = std::make_unique<ik::kdl::KdlNrJl>(kin.rig(), args.options);
      return;
#else
      throw std::invalid_argument("method " + args.method +
                                  ": this build has no Orocos KDL (install liborocos-kdl-dev: "
                                  "scripts/setup.sh --native, then rebuild build/native)");
#endif
    }
    solver_ = ik::make_solver(args.method, kin, args.options);
  }

  // Solves from `start` (degrees) towards `target` (rig units), or with `orientations` (4 per
  // effector, quaternions x, y, z, w; empty: none) towards the whole poses, or with `drag_goals`
  // (--page-goals; null: none) towards those (kdl: the positions alone); `seconds` is
  // steady_clock around the solver's call alone (making the goals and copying the outcome out
  // are not timed).
  Outcome solve(const Eigen::VectorXd& start, const Eigen::VectorXd& target, const Eigen::VectorXd& orientations,
                const ik::Goals* drag_goals, double& seconds) {
    const bool pose = orientations.size() > 0;
    if (pose) {
      goals_ = ik::bench::pose_goals(kin_, target, orientations);
      rotations_.clear();
      for (const ik::EffectorGoal& g : goals_.effectors) rotations_.push_back(g.orientation_target);
    }
    // kdl takes the positions alone (as the peers do).
    const ik::Goals* goals = drag_goals && !kdl_active() ? drag_goals : pose ? &goals_ : nullptr;
    const auto t0 = std::chrono::steady_clock::now();
#ifdef IK_HAVE_KDL
    if (kdl_ || nr_jl_) {
      const ik::kdl::KdlSummary& s = nr_jl_ ? nr_jl_->solve(start, target, rotations_)
                                     : pose ? kdl_->solve(start, target, rotations_)
                                            : kdl_->solve(start, target);
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      return {s.angles,
              s.E,
              s.gradient_norm,
              s.iterations,
              s.function_evaluations,
              s.jacobian_evaluations,
              s.stop_reason,
              s.stop_reason != "invalid_input"};
    }
#endif
    const ik::SolverSummary& s = goals ? solver_->solve(start, *goals) : solver_->solve(start, target);
    last_goals_ = goals;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return {s.angles,
            s.E,
            s.gradient_norm,
            s.iterations,
            s.function_evaluations,
            s.jacobian_evaluations,
            ik::stop_reason_name(s.stop_reason),
            s.stop_reason != ik::StopReason::invalid_input};
  }

  // Wobble during a solve of `iterations` iterations from `start` that ended `after` (rig units)
  // off the pinned targets (see replay_wobble). Rigs of two or more effectors only: never kdl_nr_jl.
  double wobble(ik::Kinematics& observer, const Eigen::VectorXd& start, const Eigen::VectorXd& target, int dragged,
                int iterations, double after, Eigen::VectorXd& tips) {
#ifdef IK_HAVE_KDL
    if (kdl_) {
      ik::SolverOptions options = args_.options;
      options.max_iterations = iterations;
      options.time_budget_s = 0;
      ik::kdl::KdlSolver replay(kin_.rig(), options);
      double during = 0;
      replay.solve(start, target, [&](const Eigen::VectorXd& angles) {
        during = std::max(during, largest_distance(observer, angles, target, dragged, tips));
      });
      return iterations == 0 ? after : during;
    }
#endif
    return replay_wobble(args_, kin_, observer, start, target, last_goals_, dragged, iterations, after, tips);
  }

 private:
  bool kdl_active() const {
#ifdef IK_HAVE_KDL
    return kdl_ != nullptr || nr_jl_ != nullptr;
#else
    return false;
#endif
  }
  const ik::Goals* last_goals_ = nullptr;  // the goals of the last solve (null: plain targets), until the next
  const Args& args_;
  ik::Kinematics& kin_;
  std::unique_ptr<ik::Solver> solver_;
  ik::Goals goals_;                         // pose goals of the current solve
  std::vector<Eigen::Matrix3d> rotations_;  // their orientations, for kdl
#ifdef IK_HAVE_KDL
  std::unique_ptr<ik::kdl::KdlSolver> kdl_;
  std::unique_ptr<ik::kdl::KdlNrJl> nr_jl_;
#endif
};

void run(const Args& args) {
  if (args.list_methods) return list_methods();
  ik::Kinematics kin(ik::load_a7_rig(args.rig));
  ik::Kinematics observer(kin.rig());  // poses for wobble, so the solver's own rig is never disturbed
  Method method(args, kin);            // first: an unknown method is the first error
  const Job job = read_job(args.input);
  const int num_orientations = args.pose ? 4 * kin.num_effectors() : 0;
  if (job.num_angles != kin.num_angles() || job.num_residuals != kin.num_residuals() ||
      job.num_orientations != num_orientations)
    throw std::runtime_error(args.input + ": sizes do not match the rig (" + std::to_string(kin.num_angles()) +
                             " angles, " + std::to_string(kin.num_residuals()) + " residuals, " +
                             std::to_string(num_orientations) + " orientation numbers)");
  std::FILE* out = std::fopen(args.output.c_str(), "w");
  if (!out) throw std::runtime_error(args.output + ": cannot write");

  Eigen::VectorXd start(kin.num_angles()), target(kin.num_residuals()), previous(kin.num_angles()),
      tips(kin.num_residuals()), orientations(num_orientations), joints_from, joints_to;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // --page-goals: the frames pinned at the start of the current path, per effector.
  std::vector<Eigen::Matrix3d> pins(kin.num_effectors(), Eigen::Matrix3d::Identity());
  ik::Goals page;
  page.effectors.resize(kin.num_effectors());
  for (int k = 0; k < job.count; ++k) {
    const double* rec = job.records.data() + static_cast<size_t>(k) * job.stride();
    const bool chained = rec[0] != 0 && k > 0;
    const int dragged = static_cast<int>(rec[1]);
    start = chained ? previous : Eigen::Map<const Eigen::VectorXd>(rec + 2, job.num_angles);
    target = Eigen::Map<const Eigen::VectorXd>(rec + 2 + job.num_angles, job.num_residuals);
    orientations = Eigen::Map<const Eigen::VectorXd>(rec + 2 + job.num_angles + job.num_residuals, num_orientations);

    const bool paged = !args.page_goals.empty() && !args.options.paper_mode && dragged >= 0;
    if (paged && (dragged >= static_cast<int>(args.page_goals.size()) ||
                  static_cast<int>(args.page_goals[dragged].size()) != kin.num_effectors()))
      throw std::invalid_argument("--page-goals: no row of " + std::to_string(kin.num_effectors()) +
                                  " digits for dragged effector " + std::to_string(dragged));
    if (paged && !chained) {  // a path begins: pin the effectors' frames at its start
      observer.forward(start);
      for (int e = 0; e < kin.num_effectors(); ++e) pins[e] = observer.tip_rotation(kin.rig().effectors[e]);
    }
    if (paged)
      for (int e = 0; e < kin.num_effectors(); ++e) {
        ik::EffectorGoal& g = page.effectors[e];
        g.position_target = target.segment<3>(3 * e);
        g.yields = e == dragged;
        g.orientation = e != dragged && args.page_goals[dragged][e] == '1';
        g.orientation_target = pins[e];
      }
    double seconds = 0;
    const Outcome s = method.solve(start, target, orientations, paged ? &page : nullptr, seconds);
    previous = s.angles;
    double E = s.E;
    const double gradient_norm = s.gradient_norm;
    const int iterations = s.iterations, fevals = s.fevals, jevals = s.jevals;
    const std::string& reason = s.reason;

    const bool valid = s.valid;
    const double tip_distance = valid ? largest_distance(observer, previous, target, -1, tips) : nan;
    const double jump = valid ? largest_angle_change(observer, start, previous) : nan;
    const double jump_move = valid ? largest_joint_move(observer, start, previous, joints_from, joints_to) : nan;
    double during = nan, after = nan;
    if (dragged >= 0 && kin.num_effectors() > 1 && valid) {
      after = largest_distance(observer, previous, target, dragged, tips);
      during = method.wobble(observer, start, target, dragged, iterations, after, tips);
    }
    nlohmann::json line = {{"E", E},
                           {"gradient_norm", gradient_norm},
                           {"iterations", iterations},
                           {"function_evaluations", fevals},
                           {"jacobian_evaluations", jevals},
                           {"seconds", seconds},
                           {"stop_reason", reason},
                           {"wobble_during", during},
                           {"wobble_after", after},
                           {"tip_distance", tip_distance},
                           {"jump_deg", jump},
                           {"jump_move", jump_move}};
    if (dragged >= 0 && valid) line["angles"] = std::vector<double>(previous.data(), previous.data() + previous.size());
    if (args.pose) {  // judged from forward kinematics of the returned angles, as the bench does
      line["rot_err_deg"] = valid ? ik::bench::largest_rotation_error_deg(observer, previous, orientations) : nan;
      line["twist_max"] = valid ? ik::bench::largest_twist_component(observer, previous, target, orientations) : nan;
      if (valid) {
        observer.tips(previous, tips);
        E = 0.5 * (tips - target).squaredNorm();
      }
      line["E"] = E;
    }
    std::fprintf(out, "%s\n", line.dump().c_str());
  }
  if (std::fclose(out) != 0) throw std::runtime_error(args.output + ": write failed");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    run(parse_args(argc, argv));
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "ik_bench_native: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ik_bench_native: %s\n", e.what());
    return 1;
  }
  return 0;
}
