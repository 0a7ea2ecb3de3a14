#include "solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "finite_difference_jacobian.h"
#include "line_search.h"
#include "size_limits.h"
#include "objective.h"

namespace ik {

namespace {

using Clock = std::chrono::steady_clock;

// Paper mode backtracks until the projected step is exactly 0, as the original did (it halved
// alpha until it underflowed); alpha reaches 0 after about 1100 halvings.
constexpr int kPaperMaxBacktracks = 2000;

// With restarts left, a run above the error tolerance counts as stationary (and restarts) only
// when |g| is below this share of the gradient tolerance. The protocol's tolerance is absolute
// (rig units^2 per degree): on a small rig such as the knight, a run still descending towards
// its target passes it long before it nears a stationary point, and restarting there threw away
// good runs (knight random gd: 71% success in 20 ms mean; with this test 100% in 0.4 ms).
constexpr double kStationaryFraction = 0.1;

// Escapes from stationary points per solve (each lowers E; this bounds a solve without a time budget).
constexpr int kMaxEscapes = 50;

double seconds_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

double seconds_since(Clock::time_point t) { return seconds_between(t, Clock::now()); }

bool finite(double x) { return std::isfinite(x); }

// The first problem with `o`, or an empty string.
std::string check_options(const SolverOptions& o) {
  auto bad = [](const char* field, const std::string& rule) { return std::string("option ") + field + " must be " + rule; };
  if (!(finite(o.gradient_tolerance) && o.gradient_tolerance >= 0)) return bad("gradient_tolerance", "a number >= 0");
  if (!(finite(o.error_tolerance) && o.error_tolerance >= 0)) return bad("error_tolerance", "a number >= 0");
  if (o.max_iterations < 0) return bad("max_iterations", ">= 0");
  if (!(o.time_budget_s >= 0)) return bad("time_budget_s", ">= 0 (0 or infinity: no limit)");
  if (!(finite(o.tip_tolerance) && o.tip_tolerance >= 0)) return bad("tip_tolerance", "a number >= 0 (0: the E test)");
  if (o.history_capacity < 1 || o.history_capacity > kMaxHistory)
    return bad("history_capacity", "in 1.." + std::to_string(kMaxHistory));
  if (!(finite(o.fd_step_deg) && o.fd_step_deg > 0)) return bad("fd_step_deg", "a number > 0");
  if (!(finite(o.gd_initial_step) && o.gd_initial_step > 0)) return bad("gd_initial_step", "a number > 0");
  if (!(o.backtrack_factor > 0 && o.backtrack_factor < 1)) return bad("backtrack_factor", "in (0, 1)");
  if (!(o.armijo_c1 >= 0 && o.armijo_c1 < 1)) return bad("armijo_c1", "in [0, 1)");
  if (o.max_backtracks < 1 || o.max_backtracks > kMaxBacktracks)
    return bad("max_backtracks", "in 1.." + std::to_string(kMaxBacktracks));
  if (!(o.gn_singular_cutoff >= 0 && o.gn_singular_cutoff < 1)) return bad("gn_singular_cutoff", "in [0, 1)");
  if (!(o.gn_max_step_deg > 0)) return bad("gn_max_step_deg", "> 0");
  if (!(o.newton_max_step_deg > 0)) return bad("newton_max_step_deg", "> 0");
  if (!(finite(o.lm_initial_mu) && o.lm_initial_mu > 0)) return bad("lm_initial_mu", "a number > 0");
  if (!(finite(o.lm_damping_floor) && o.lm_damping_floor >= 0)) return bad("lm_damping_floor", "a number >= 0");
  if (o.lm_max_rejections < 1) return bad("lm_max_rejections", ">= 1");
  if (o.restarts < 0) return bad("restarts", ">= 0");
  if (o.stall_iterations < 1) return bad("stall_iterations", ">= 1");
  if (o.chain_restarts < 0) return bad("chain_restarts", ">= 0");
  return {};
}

// The first non-finite entry of `v` named `what`, or an empty string.
std::string check_finite(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!finite(v[i])) return std::string(what) + "[" + std::to_string(i) + "] is not a finite number";
  return {};
}

}  // namespace

const char* stop_reason_name(StopReason reason) {
  switch (reason) {
    case StopReason::running: return "running";
    case StopReason::converged_E: return "converged_E";
    case StopReason::converged_grad: return "converged_grad";
    case StopReason::zero_step: return "zero_step";
    case StopReason::max_iterations: return "max_iterations";
    case StopReason::timeout: return "timeout";
    case StopReason::invalid_input: return "invalid_input";
    case StopReason::numerical_failure: return "numerical_failure";
  }
  return "unknown";
}

Solver::Solver(Kinematics& kin, const SolverOptions& options) : kin_(kin), opt_(options), next_opt_(options) {}

bool Solver::validate(const Eigen::Ref<const Eigen::VectorXd>& angles, const Eigen::Ref<const Eigen::VectorXd>& target) {
  std::string problem = check_options(opt_);
  if (problem.empty() && angles.size() != kin_.num_angles())
    problem = "angles has " + std::to_string(angles.size()) + " values, expected " + std::to_string(kin_.num_angles()) +
              " (3 per bone)";
  if (problem.empty() && target.size() != kin_.num_residuals())
    problem = "target has " + std::to_string(target.size()) + " values, expected " +
              std::to_string(kin_.num_residuals()) + " (3 per end effector)";
  const int limit = std::min(angle_limit(kin_.num_residuals()), opt_.paper_mode ? kMaxDenseAngles : kNoAngleLimit);
  if (problem.empty() && kin_.num_angles() > limit)
    problem = std::string(name()) + (opt_.paper_mode ? " in paper mode" : "") + " takes rigs of at most " +
              std::to_string(limit) + " angles (" + std::to_string(limit / 3) + " bones); this one has " +
              std::to_string(kin_.num_angles()) + (opt_.paper_mode ? ": turn paper mode off" : ": use lm or gd");
  if (problem.empty()) problem = check_finite(angles, "angles");
  if (problem.empty()) problem = check_finite(target, "target");
  summary_.message = problem;
  return problem.empty();
}

StopReason Solver::start(const Eigen::Ref<const Eigen::VectorXd>& angles,
                         const Eigen::Ref<const Eigen::VectorXd>& target) {
  return begin(angles, target, /*close=*/true);
}

StopReason Solver::begin(const Eigen::Ref<const Eigen::VectorXd>& angles,
                         const Eigen::Ref<const Eigen::VectorXd>& target, bool close) {
  call_start_ = Clock::now();
  // A solve from where the previous one ended, towards the same target (a held drag whose frame
  // budget ran out), goes on along the chain restarts instead of trying the same ones again.
  const bool continues = chain_index_ > 0 && target.size() == target_.size() && angles.size() == summary_.angles.size() &&
                         target == target_ && angles == summary_.angles;
  if (!continues) chain_index_ = 0;
  elapsed_before_call_ = 0;
  opt_ = next_opt_;
  summary_.iterations = summary_.function_evaluations = summary_.jacobian_evaluations = summary_.restarts = 0;
  summary_.escapes = summary_.chain_restarts = 0;
  summary_.reached = false;
  summary_.message.clear();
  history_size_ = 0;
  failure_ = nullptr;
  if (!validate(angles, target)) {
    summary_.stop_reason = StopReason::invalid_input;
    summary_.initial_E = summary_.E = summary_.gradient_norm = summary_.tip_distance =
        std::numeric_limits<double>::quiet_NaN();
    summary_.elapsed_s = seconds_since(call_start_);
    return summary_.stop_reason;
  }
  // Workspace: sized here only, so that step() never allocates.
  if (m_ != kin_.num_residuals() || n_ != kin_.num_angles() || effectors_ != kin_.rig().effectors) {
    effectors_ = kin_.rig().effectors;
    m_ = kin_.num_residuals();
    n_ = kin_.num_angles();
    target_.resize(m_);
    r_.resize(m_);
    r_trial_.resize(m_);
    a_.resize(n_);
    trial_.resize(n_);
    g_.resize(n_);
    free_mask_.resize(n_);
    J_.resize(m_, n_);
    free_.resize(n_);
    fd_scratch_.resize(n_);
    fd_plus_.resize(m_);
    fd_minus_.resize(m_);
    summary_.angles.resize(n_);
    reach_ = 0;
    for (int e = 0; e < kin_.num_effectors(); ++e) {
      double length = 0;
      for (int b : kin_.effector_chain(e)) length += kin_.rig().bones[b].length;
      reach_ = std::max(reach_, length);
    }
    if (!(reach_ > 0)) reach_ = 1;
    unit_.resize(n_);
    escape_.resize(kin_);
    chain_restart_.resize(kin_);
    resize(m_, n_);
  }
  if (sequence_seed_ != opt_.seed || sequence_.dimension() != n_) {
    sequence_ = QuasiRandom(n_, opt_.seed);
    sequence_seed_ = opt_.seed;
  }
  restart_index_ = 0;
  run_iterations_ = run_best_iteration_ = 0;
  run_best_E_ = std::numeric_limits<double>::infinity();
  if (static_cast<int>(history_.size()) != opt_.history_capacity) history_.resize(opt_.history_capacity);

  target_ = target;
  a_ = angles;
  kin_.project(a_);
  reset();
  E_ = evaluate(a_, r_);
  summary_.stop_reason = StopReason::running;
  if (!finite(E_)) {
    summary_.stop_reason = StopReason::numerical_failure;
    summary_.message = "E is not finite at the start angles";
  } else if (!update_derivatives(true)) {
    summary_.stop_reason = StopReason::numerical_failure;
    summary_.message = "the gradient is not finite at the start angles";
  }
  summary_.initial_E = E_;
  summary_.E = E_;
  summary_.gradient_norm = gradient_norm_;
  summary_.tip_distance = largest_tip_distance(r_);
  summary_.reached = finite(E_) && on_target();
  summary_.angles = a_;
  record();
  if (running()) {
    // A start on a stationary point off target (a tip pointing straight away from its target, a
    // straight limb whose target lies along it) moves on at once, as a stopped run would.
    StopReason reason = check_stop();
    while (reason == StopReason::converged_grad && move_on(reason)) {
    }
    if (reason == StopReason::running && opt_.max_iterations == 0) reason = StopReason::max_iterations;
    summary_.stop_reason = settle(reason);
  }
  if (close || !running()) {
    last_read_ = Clock::now();
    elapsed_before_call_ = seconds_between(call_start_, last_read_);
  } else {
    elapsed_before_call_ = 0;  // the first step's time runs from call_start_
  }
  summary_.elapsed_s = elapsed_before_call_;
  return summary_.stop_reason;
}

bool Solver::step() { return advance(Clock::now()); }

bool Solver::advance(std::chrono::steady_clock::time_point begin) {
  if (!running()) return false;
  call_start_ = begin;
  cut_short_ = false;
  StopReason reason = StopReason::running;
  if (kin_.rig().effectors != effectors_) {
    summary_.message = "the rig's end effectors changed during the solve; call start() again";
    reason = StopReason::invalid_input;
  } else {
    switch (iterate()) {
      case Progress::failed:
        reason = StopReason::numerical_failure;
        summary_.message = failure_ ? failure_ : "numerical failure";
        break;
      case Progress::stuck:
        reason = cut_short_ ? StopReason::timeout : StopReason::zero_step;
        break;
      case Progress::moved:
        ++summary_.iterations;
        if (!finite(E_) || !update_derivatives(true)) {
          reason = StopReason::numerical_failure;
          summary_.message = "E or its gradient became non-finite";
          break;
        }
        record();
        note_best();
        reason = check_stop();
        break;
    }
    // A run stopped off target moves on: a stalled one by a restart, one stopped at a stationary
    // point by an escape or a restart (again while it lands on one).
    if (reason == StopReason::running && stalls()) move_on(reason);
    while ((reason == StopReason::zero_step || reason == StopReason::converged_grad) && move_on(reason)) {
    }
  }
  // One clock read per step (in WebAssembly a read is a call out to JavaScript, ~65 ns in Node).
  last_read_ = Clock::now();
  elapsed_before_call_ += seconds_between(call_start_, last_read_);
  if (reason == StopReason::running) {
    if (summary_.iterations >= opt_.max_iterations)
      reason = StopReason::max_iterations;
    else if (has_budget() && elapsed_before_call_ >= opt_.time_budget_s)
      reason = StopReason::timeout;
  }
  summary_.stop_reason = settle(reason);
  summary_.elapsed_s = elapsed_before_call_;
  return reason == StopReason::running;
}

const SolverSummary& Solver::solve(const Eigen::Ref<const Eigen::VectorXd>& angles,
                                   const Eigen::Ref<const Eigen::VectorXd>& target) {
  // Back-to-back: the first step's time runs from the start's, each later one's from the previous
  // step's closing clock read (one read per step; two for a solve of one iteration).
  if (begin(angles, target, /*close=*/false) == StopReason::running) {
    Clock::time_point from = call_start_;
    while (advance(from)) from = last_read_;
  }
  return summary_;
}

double Solver::evaluate(const Eigen::Ref<const Eigen::VectorXd>& angles, Eigen::Ref<Eigen::VectorXd> residual) {
  ++summary_.function_evaluations;
  return objective(kin_, angles, target_, residual);
}

bool Solver::backtrack(const Eigen::Ref<const Eigen::VectorXd>& direction, double initial_step, double c1) {
  BacktrackingOptions search;
  search.initial_step = initial_step;
  search.factor = opt_.backtrack_factor;
  search.c1 = c1;
  search.max_tries = opt_.paper_mode ? kPaperMaxBacktracks : opt_.max_backtracks;
  search.projected_slope = !opt_.paper_mode;
  search.deadline = deadline();
  const BacktrackingResult found = projected_backtracking(kin_, target_, a_, E_, g_, direction, search, trial_, r_trial_);
  summary_.function_evaluations += found.evaluations;
  cut_short_ = cut_short_ || found.timed_out;
  if (!found.found) return false;
  a_.swap(trial_);
  r_.swap(r_trial_);
  E_ = found.E;
  return true;
}

bool Solver::update_derivatives(bool posed) {
  if (opt_.paper_mode) {
    finite_difference_jacobian(kin_, a_, opt_.fd_step_deg, /*clamp_to_limits=*/true, fd_scratch_, fd_plus_,
                               fd_minus_, J_);
    // The original divided the central difference by h, not by the spread 2h: its columns are
    // twice the derivative away from the limits (one-sided, exact scale, on a limit).
    const double h = opt_.fd_step_deg;
    for (int j = 0; j < n_; ++j) {
      const double spread = std::min(a_[j] + h, kin_.upper()[j]) - std::max(a_[j] - h, kin_.lower()[j]);
      if (spread > 0) J_.col(j) *= spread / h;
    }
  } else {
    if (!posed) kin_.forward(a_);
    kin_.current_jacobian(J_);
  }
  ++summary_.jacobian_evaluations;
  g_.noalias() = J_.transpose() * r_;
  const Eigen::VectorXd& lo = kin_.lower();
  const Eigen::VectorXd& hi = kin_.upper();
  num_free_ = 0;
  double free_norm2 = 0;
  for (int i = 0; i < n_; ++i) {
    const bool blocked = lo[i] >= hi[i] || (a_[i] <= lo[i] && g_[i] > 0) || (a_[i] >= hi[i] && g_[i] < 0);
    free_mask_[i] = blocked ? 0.0 : 1.0;
    if (blocked) continue;
    free_[num_free_++] = i;
    free_norm2 += g_[i] * g_[i];
  }
  gradient_norm_ = opt_.paper_mode ? g_.norm() : std::sqrt(free_norm2);
  return finite(gradient_norm_);
}

bool Solver::stalls() {
  if (opt_.restarts == 0 || opt_.paper_mode) return false;
  ++run_iterations_;
  if (E_ < 0.9 * run_best_E_) {
    run_best_E_ = E_;
    run_best_iteration_ = run_iterations_;
    return false;
  }
  return run_iterations_ - run_best_iteration_ >= opt_.stall_iterations;
}

bool Solver::restarts_left() const { return !opt_.paper_mode && restart_index_ < opt_.restarts; }

bool Solver::chain_restarts_left() const { return !opt_.paper_mode && chain_index_ < opt_.chain_restarts; }

bool Solver::descends_further() const {
  return restarts_left() && !on_target() && gradient_norm_ >= kStationaryFraction * opt_.gradient_tolerance;
}

bool Solver::restart() {
  if (!restarts_left()) return false;
  ++restart_index_;
  sequence_.point(restart_index_, unit_);
  point_in_limits(unit_, kin_.lower(), kin_.upper(), a_);
  run_iterations_ = run_best_iteration_ = 0;
  run_best_E_ = std::numeric_limits<double>::infinity();
  reset();
  E_ = evaluate(a_, r_);
  return finite(E_);
}

bool Solver::escape() {
  if (opt_.paper_mode || !opt_.escape_saddles || summary_.escapes >= kMaxEscapes) return false;
  kin_.forward(a_);  // the tip Hessian reads the pose
  const EscapeResult found = escape_.find(kin_, target_, a_, r_, E_, J_, trial_, r_trial_);
  summary_.function_evaluations += found.evaluations;
  if (!found.found) return false;
  a_.swap(trial_);
  r_.swap(r_trial_);
  E_ = found.E;
  reset();
  return true;
}

bool Solver::chain_restart() {
  if (!chain_restarts_left()) return false;
  trial_ = summary_.angles;
  evaluate(trial_, r_trial_);  // poses kin_ at the best point
  // How far off a tip may be on target: the tip tolerance, or with the E test the distance at which
  // one effector alone makes E the tolerance.
  const double slack = opt_.tip_tolerance > 0 ? opt_.tip_tolerance : std::sqrt(2 * opt_.error_tolerance);
  if (!chain_restart_.propose(kin_, trial_, r_trial_, target_, slack, sequence_, ++chain_index_, a_))
    return false;
  run_iterations_ = run_best_iteration_ = 0;
  run_best_E_ = std::numeric_limits<double>::infinity();
  reset();
  E_ = evaluate(a_, r_);
  return finite(E_);
}

bool Solver::move_on(StopReason& reason) {
  if (summary_.reached) return false;
  const bool out_of_iterations = summary_.iterations >= opt_.max_iterations;
  if (out_of_iterations || out_of_time()) {
    // The budget, not the problem, ends the solve while restarts of either kind are left.
    const bool left = restarts_left() || chain_restarts_left();
    if (left) reason = out_of_iterations ? StopReason::max_iterations : StopReason::timeout;
    return false;
  }
  // Restarts come first while any are left: on random targets escaping first cost more than it
  // saved (native, lm, 1000 restarts: knight 96 -> 184 us mean, beast 75 -> 137 us).
  const bool stationary = reason == StopReason::zero_step || reason == StopReason::converged_grad;
  if (stationary && !restarts_left() && escape())
    ++summary_.escapes;
  else if (stationary && !restarts_left() && chain_restart())
    ++summary_.chain_restarts;
  else if (restart())
    ++summary_.restarts;
  else
    return false;
  ++summary_.iterations;
  if (!finite(E_) || !update_derivatives(false)) {
    reason = StopReason::numerical_failure;
    summary_.message = "E or its gradient is not finite after an escape or a restart";
    return true;
  }
  record();
  note_best();
  reason = check_stop();
  return true;
}

StopReason Solver::settle(StopReason reason) const {
  switch (reason) {
    case StopReason::converged_E:
    case StopReason::converged_grad:
    case StopReason::zero_step:
      if (summary_.reached) return StopReason::converged_E;
      return summary_.gradient_norm < opt_.gradient_tolerance ? StopReason::converged_grad : StopReason::zero_step;
    case StopReason::max_iterations:
    case StopReason::timeout:
      return summary_.reached ? StopReason::converged_E : reason;
    default:
      return reason;
  }
}

Solver::Progress Solver::fail(const char* message) {
  failure_ = message;
  return Progress::failed;
}

bool Solver::has_budget() const { return opt_.time_budget_s > 0 && !std::isinf(opt_.time_budget_s); }

bool Solver::out_of_time() const { return deadline().passed(); }

bool Solver::time_is_up() {
  cut_short_ = cut_short_ || out_of_time();
  return cut_short_;
}

Deadline Solver::deadline() const {
  constexpr double kYear = 3.2e7;  // seconds; a longer budget is none (and would overflow the clock)
  if (!has_budget() || opt_.time_budget_s - elapsed_before_call_ > kYear) return Deadline();
  const auto left = std::chrono::duration<double>(opt_.time_budget_s - elapsed_before_call_);
  return Deadline(call_start_ + std::chrono::duration_cast<Clock::duration>(left));
}

bool Solver::on_target() const {
  if (opt_.tip_tolerance > 0) return largest_tip_distance(r_) < opt_.tip_tolerance;
  return E_ < opt_.error_tolerance;
}

StopReason Solver::check_stop() const {
  if (on_target()) return StopReason::converged_E;
  if (gradient_norm_ < opt_.gradient_tolerance && !descends_further()) return StopReason::converged_grad;
  return StopReason::running;
}

void Solver::record() {
  if (history_size_ < static_cast<int>(history_.size())) history_[history_size_++] = E_;
}

void Solver::note_best() {
  // A point on target beats any point off it (the tip test is not the E order); then lower E.
  const bool reached = on_target();
  if (reached != summary_.reached ? !reached : !(E_ < summary_.E)) return;
  summary_.E = E_;
  summary_.gradient_norm = gradient_norm_;
  summary_.tip_distance = largest_tip_distance(r_);
  summary_.reached = reached;
  summary_.angles = a_;
}

}  // namespace ik
