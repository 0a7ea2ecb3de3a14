// The Solver's start / step / solve cycle: input checks, the workspace, the clock, the
// derivatives and the free set at each point, the stop tests and the best point. How a run that
// stopped off target moves on (restarts, escapes, chain restarts) is in solver_move_on.cpp.
#include "solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "free_set.h"
#include "goal_residual.h"
#include "line_search.h"
#include "objective.h"
#include "paper_jacobian.h"
#include "size_limits.h"
#include "solve_input.h"

namespace ik {

namespace {

using Clock = TimeBudget::Clock;

// Paper mode backtracks until the projected step is exactly 0, as the original did (it halved
// alpha until it underflowed); alpha reaches 0 after about 1100 halvings.
constexpr int kPaperMaxBacktracks = 2000;

bool finite(double x) { return std::isfinite(x); }

// A run off target has settled when its distance from the goals fell by less than this share of
// the tip tolerance over Settling::kSteps steps.
constexpr double kSettleShare = 0.05;
// Without goals given up, a run settles only where it will stay this many tip tolerances off
// target: a run nearing a local minimum close to its target goes on to it, so that the chain
// restarts start from there.
constexpr double kFarShare = 30;

// With soft rows on and the hard goals on target, a step that lowers E by less than this share
// of E ends the solve (converged_E): near the soft optimum gd and bfgs creep.
constexpr double kSoftStallShare = 1e-4;
// With the hard goals on target, soft rows whose residual is under this share of the tip
// tolerance are met: nearer to a pole or the rest pose is nothing the tolerance can tell.
constexpr double kSoftMetShare = 0.1;

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
    case StopReason::joint_speed: return "joint_speed";
  }
  return "unknown";
}

Solver::Solver(Kinematics& kin, const SolverOptions& options) : kin_(kin), opt_(options), next_opt_(options) {}

StopReason Solver::start(const Eigen::Ref<const Eigen::VectorXd>& angles,
                         const Eigen::Ref<const Eigen::VectorXd>& target) {
  incoming_.set_positions(kin_, target);
  return begin(angles, std::string(), /*close=*/true);
}

StopReason Solver::start(const Eigen::Ref<const Eigen::VectorXd>& angles, const Goals& goals) {
  const std::string problem = incoming_.set(kin_, goals);
  return begin(angles, problem, /*close=*/true);
}

StopReason Solver::begin(const Eigen::Ref<const Eigen::VectorXd>& angles, const std::string& goals_problem,
                         bool close) {
  clock_.open(Clock::now());
  preferred_on_ = preferred_pending_ && preferred_.size() == angles.size();
  preferred_pending_ = false;
  // The rest rows belong to the goals: they depend on the options and the start angles.
  incoming_.set_rest(kin_, next_opt_.rest_weight, next_opt_.rest_from_start, angles);
  // A solve from where the previous one ended, towards the same goals (a held drag whose frame
  // budget ran out), goes on along the chain restarts instead of trying the same ones again.
  const bool continues =
      chain_index_ > 0 && angles.size() == summary_.angles.size() && incoming_ == goals_ && angles == summary_.angles;
  if (!continues) chain_index_ = 0;
  bool carry = carrying_ && continues;  // continues: from the pose the last solve returned
  carrying_ = false;
  opt_ = next_opt_;
  clock_.reset(opt_.time_budget_s);
  summary_.iterations = summary_.function_evaluations = summary_.jacobian_evaluations = summary_.restarts = 0;
  summary_.escapes = summary_.chain_restarts = summary_.goals_given_up = 0;
  summary_.reached = summary_.out_of_reach = summary_.orientation_out_of_reach = false;
  history_size_ = 0;
  failure_ = nullptr;
  const int rows = incoming_.plain() ? kin_.num_residuals() : incoming_.rows();
  const int limit = std::min(angle_limit(rows), opt_.paper_mode ? kMaxPaperAngles : kNoAngleLimit);
  summary_.message = goals_problem;
  if (summary_.message.empty())
    summary_.message = check_solve_input(kin_, opt_, name(), limit, rows, angles, incoming_.plain_target(),
                                         incoming_.plain_positions());
  if (summary_.message.empty() && opt_.paper_mode && (opt_.rest_weight > 0 || incoming_.num_poles() > 0))
    summary_.message =
        "paper mode takes no bend hints (poles) and no rest pull (restWeight > 0): the original "
        "program's objective has neither; turn paper mode off for them";
  if (summary_.message.empty() && static_cast<long long>(rows) * kin_.num_angles() > kMaxMatrixEntries)
    summary_.message = "the goals' Jacobian would have " + std::to_string(rows) + " x " +
                       std::to_string(kin_.num_angles()) + " entries, more than " + std::to_string(kMaxMatrixEntries) +
                       " (fewer bones with a rest pull: restWeight 0 or stiffness 0)";
  if (summary_.message.empty() && opt_.paper_mode && !incoming_.plain())
    summary_.message =
        "paper mode takes position goals of weight 1 only (the original program's objective); "
        "turn paper mode off for orientation goals or weights";
  if (!summary_.message.empty()) {
    summary_.stop_reason = StopReason::invalid_input;
    summary_.initial_E = summary_.E = summary_.gradient_norm = summary_.tip_distance =
        std::numeric_limits<double>::quiet_NaN();
    clock_.close();
    summary_.elapsed_s = clock_.spent();
    return summary_.stop_reason;
  }
  // A drag's next frame starts where the last solve ended: how far its targets moved since (-1:
  // not such a frame). Read before the new goals replace the last ones.
  const double target_change =
      angles.size() == summary_.angles.size() && angles == summary_.angles ? incoming_.largest_change_from(goals_) : -1;
  // The last solve's budget stopped it off target and this one goes on from there (a drag's
  // frames on a machine too slow to finish one within its budget): that counts as a run stopped
  // off target, and the soft rows start lowered as move_on() lowers them. Else each frame began
  // with them at full weight, and a pole held a dragged hand 0.12 of the character's height off
  // its target for hundreds of frames, a step a frame.
  const bool budget_stopped = target_change >= 0 && (summary_.stop_reason == StopReason::timeout ||
                                                     summary_.stop_reason == StopReason::max_iterations);
  const double cut_soft_scale = goals_.soft_scale();
  // Workspace: sized here only, so that step() never allocates.
  goals_ = incoming_;
  if (budget_stopped && goals_.has_soft() && !opt_.paper_mode)
    goals_.set_soft_scale(lowered_soft_scale(cut_soft_scale));
  if (m_ != goals_.rows() || n_ != kin_.num_angles() || effectors_ != kin_.rig().effectors ||
      layout_ != goals_.layout()) {
    resize_workspace();
    carry = false;
  }
  pattern_.set_root_weight(opt_.root_unit * opt_.root_unit);
  priority_.clear();
  restarts_.begin_solve(n_, opt_.seed);
  if (static_cast<int>(history_.size()) != opt_.history_capacity) history_.resize(opt_.history_capacity);

  a_ = angles;
  kin_.project(a_);
  // A solve that starts where the last one stopped partway to its answer (joint_speed) goes on
  // towards it: its run starts from that answer, the joints' move is measured from here.
  const bool resume = heading_ && bounds_joints() && a_ == partway_;  // sized alike by resize_workspace()
  heading_ = false;
  resumed_ = resume;
  chain_run_going_ = false;
  nearer_tries_ = 0;
  together_ = together_tried_ = false;
  discarded_chain_restarts_ = 0;
  nearest_move_ = std::numeric_limits<double>::infinity();
  start_ = moved_from_ = a_;
  soft_retried_ = false;
  soft_on_target_since_ = -1;
  settling_.begin_run();
  reset();
  priority_damping_.reset(opt_.lm_initial_mu);
  E_ = evaluate(a_, r_);
  if (bounds_joints()) motion_.note_start(kin_);  // kin_ is posed at the start
  if (resume) {
    a_ = start_ = heading_to_;
    E_ = evaluate(a_, r_);
  }
  if (bounds_joints()) {
    // The joints may move as far as the goals moved, and the bound more: on a drag's next frame
    // as far as its targets moved since the last one (a target out of reach keeps a residual
    // that is no move, and the closest point on another branch was a snap of up to 9.5% of the
    // rig); else as far as the goals are from the tips at the start (or resuming, from the
    // answer the last solve was heading to).
    double moved = target_change;
    if (moved < 0)
      for (int b = 0; b < goals_.num_blocks(); ++b) moved = std::max(moved, r_.segment<3>(3 * b).norm());
    allowed_move_ = opt_.max_joint_move + std::max(moved, 0.0);
  }
  if (finite(E_)) {
    priority_.note_start(goals_, r_, goal_tolerance());
    const bool strict = !opt_.paper_mode && opt_.strict_priority;
    // Goals that yield (the dragged one) give way from the start: the others are held.
    if (strict && goals_.has_yielding()) priority_.give_up_yielding(goals_);
    // A target beyond what its chain reaches (a hand dragged past the arm's reach, the rest
    // pinned) is given up at once: no run towards the least-squares point of all goals, which
    // would pull the others off theirs.
    if (strict && goals_.num_blocks() > 1 && !priority_.active() &&
        chain_restart_.beyond_any(kin_, r_, goals_, goal_tolerance().tip, false))
      priority_.give_up_next(goals_, r_, goal_tolerance());
    summary_.goals_given_up = priority_.count();
  }
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
  summary_.tip_distance = largest_tip_distance(goals_, r_);
  summary_.reached = finite(E_) && on_target();
  summary_.angles = a_;
  best_rank_ = finite(E_) ? rank() : 0;
  best_given_up_E_ = priority_.given_up_E(goals_, r_);
  note_given_up(r_);
  record();
  if (carry && bounds_joints() && running()) carry_run_on();
  if (running()) {
    // A start on a stationary point off target (a tip pointing straight away from its target, a
    // straight limb whose target lies along it) moves on at once, as a stopped run would.
    StopReason reason = check_stop();
    while (reason == StopReason::converged_grad && move_on(reason)) {
    }
    if (reason == StopReason::running && opt_.max_iterations == 0) reason = StopReason::max_iterations;
    summary_.stop_reason = settle(reason);
  }
  if (close || !running()) clock_.close();  // otherwise the first step's time runs from this call's start
  summary_.elapsed_s = clock_.spent();
  if (!running()) conclude();
  return summary_.stop_reason;
}

void Solver::conclude() {
  const bool carry = carries_run();
  if (carry) carried_run_ = a_;
  end_together();
  take_nearest();
  finish();
  bound_motion();
  keep_contract();
  carrying_ = carry && !heading_ &&
              (summary_.stop_reason == StopReason::max_iterations || summary_.stop_reason == StopReason::timeout);
}

void Solver::resize_workspace() {
  effectors_ = kin_.rig().effectors;
  layout_ = goals_.layout();
  m_ = goals_.rows();
  n_ = kin_.num_angles();
  r_.resize(m_);
  r_trial_.resize(m_);
  a_.resize(n_);
  trial_.resize(n_);
  start_.resize(n_);
  g_.resize(n_);
  free_mask_.resize(n_);
  J_.resize(m_, n_);
  free_.resize(n_);
  fd_scratch_.resize(n_);
  fd_plus_.resize(m_);
  fd_minus_.resize(m_);
  summary_.angles.resize(n_);
  reach_ = rig_reach(kin_);
  escape_.resize(kin_, m_);
  chain_restart_.resize(kin_);
  motion_.resize(kin_);
  moved_from_.resize(n_);
  heading_to_.resize(n_);
  partway_.resize(n_);
  carried_run_.resize(n_);
  carrying_ = false;
  heading_ = false;
  nearest_.resize(n_);
  stuck_.resize(n_);
  together_best_.resize(n_);
  pattern_.build(kin_, goals_);
  priority_.resize(goals_, n_);
  resize(m_, n_);
}

bool Solver::set_preferred_move(const Eigen::Ref<const Eigen::VectorXd>& move) {
  preferred_pending_ = false;
  if (move.size() != kin_.num_angles() || !move.allFinite()) return false;
  preferred_ = move;
  preferred_pending_ = true;
  return true;
}

bool Solver::step() { return advance(Clock::now()); }

bool Solver::advance(Clock::time_point begin) {
  if (!running()) return false;
  clock_.open(begin);
  cut_short_ = false;
  StopReason reason = StopReason::running;
  const double before = E_;
  double previous_E = std::numeric_limits<double>::infinity();
  if (kin_.rig().effectors != effectors_) {
    summary_.message = "the rig's end effectors changed during the solve; call start() again";
    reason = StopReason::invalid_input;
  } else {
    switch (priority_.active() ? priority_iterate() : iterate()) {
      case Progress::failed:
        reason = StopReason::numerical_failure;
        summary_.message = failure_ ? failure_ : "numerical failure";
        break;
      case Progress::stuck: reason = cut_short_ ? StopReason::timeout : StopReason::zero_step; break;
      case Progress::moved:
        ++summary_.iterations;
        if (goals_.soft_on()) previous_E = before;
        if (!finite(E_) || !(ends_on_target() ? update_gradient() : update_derivatives(true))) {
          reason = StopReason::numerical_failure;
          summary_.message = "E or its gradient became non-finite";
          break;
        }
        record();
        note_best();
        if (opt_.soft_iterations > 0 && soft_on_target_since_ < 0 && goals_.soft_on() && on_target())
          soft_on_target_since_ = summary_.iterations;
        reason = check_stop(previous_E);
        break;
    }
    // A run stopped off target moves on: a stalled one by a restart, one stopped at a stationary
    // point by an escape or a restart (again while it lands on one).
    if (reason == StopReason::running && stalls())
      move_on(reason);
    else if (reason == StopReason::running && settles())
      reason = StopReason::zero_step;  // judged as a stop: an escape, a chain restart or a give-up, else the end
    while ((reason == StopReason::zero_step || reason == StopReason::converged_grad) && move_on(reason)) {
    }
    if (reason == StopReason::converged_E) end_together();
    while (reason == StopReason::converged_E && seek_nearer(reason)) {
    }
  }
  // One clock read per step (in WebAssembly a read is a call out to JavaScript, ~65 ns in Node).
  clock_.close();
  if (reason == StopReason::running) {
    if (summary_.iterations >= opt_.max_iterations)
      reason = StopReason::max_iterations;
    else if (budget_holds() && clock_.used_up())
      reason = StopReason::timeout;
  }
  summary_.stop_reason = settle(reason);
  summary_.elapsed_s = clock_.spent();
  if (reason != StopReason::running) conclude();
  return reason == StopReason::running;
}

const SolverSummary& Solver::solve(const Eigen::Ref<const Eigen::VectorXd>& angles,
                                   const Eigen::Ref<const Eigen::VectorXd>& target) {
  incoming_.set_positions(kin_, target);
  return run(angles, std::string());
}

const SolverSummary& Solver::solve(const Eigen::Ref<const Eigen::VectorXd>& angles, const Goals& goals) {
  const std::string problem = incoming_.set(kin_, goals);
  return run(angles, problem);
}

const SolverSummary& Solver::run(const Eigen::Ref<const Eigen::VectorXd>& angles, const std::string& goals_problem) {
  // Back-to-back: the first step's time runs from the start's, each later one's from the previous
  // step's closing clock read (one read per step; two for a solve of one iteration).
  if (begin(angles, goals_problem, /*close=*/false) == StopReason::running) {
    Clock::time_point from = clock_.call_start();
    while (advance(from)) from = clock_.last_read();
  }
  return summary_;
}

double Solver::evaluate(const Eigen::Ref<const Eigen::VectorXd>& angles, Eigen::Ref<Eigen::VectorXd> residual) {
  ++summary_.function_evaluations;
  return goal_objective(kin_, goals_, angles, residual);
}

bool Solver::backtrack(const Eigen::Ref<const Eigen::VectorXd>& direction, double initial_step, double c1) {
  BacktrackingOptions search;
  search.initial_step = initial_step;
  search.factor = opt_.backtrack_factor;
  search.c1 = c1;
  search.max_tries = opt_.paper_mode ? kPaperMaxBacktracks : opt_.max_backtracks;
  search.projected_slope = !opt_.paper_mode;
  search.deadline = deadline();
  const BacktrackingResult found =
      projected_backtracking(kin_, goals_, a_, E_, g_, direction, search, trial_, r_trial_);
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
    paper_jacobian(kin_, a_, opt_.fd_step_deg, fd_scratch_, fd_plus_, fd_minus_, J_);
  } else {
    if (!posed) kin_.forward(a_);
    goal_jacobian(kin_, goals_, J_, Kinematics::Columns::movable);  // fixed angles never move: no columns
  }
  ++summary_.jacobian_evaluations;
  g_.noalias() = J_.transpose() * r_;
  const FreeAngles found = find_free_angles(a_, kin_.lower(), kin_.upper(), g_, free_, free_mask_);
  num_free_ = found.count;
  gradient_norm_ = opt_.paper_mode ? g_.norm() : found.gradient_norm;
  if (priority_.active()) {
    if (!priority_.prepare(kin_, J_, pattern_)) return false;
    gradient_norm_ = priority_.reduced_gradient_norm(kin_, J_, pattern_, a_, r_);
  }
  return finite(gradient_norm_);
}

bool Solver::ends_on_target() const {
  return !opt_.paper_mode && !goals_.plain() && !goals_.soft_on() && !priority_.active() && !together_ &&
         summary_.iterations >= opt_.min_iterations && on_target();
}

bool Solver::update_gradient() {
  goal_gradient(kin_, goals_, r_, g_, Kinematics::Columns::movable);
  const FreeAngles found = find_free_angles(a_, kin_.lower(), kin_.upper(), g_, free_, free_mask_);
  num_free_ = found.count;
  gradient_norm_ = found.gradient_norm;
  return finite(gradient_norm_);
}

StopReason Solver::settle(StopReason reason) const {
  switch (reason) {
    case StopReason::converged_E:
    case StopReason::converged_grad:
    case StopReason::zero_step:
      if (summary_.reached) return StopReason::converged_E;
      return summary_.gradient_norm < opt_.gradient_tolerance ? StopReason::converged_grad : StopReason::zero_step;
    case StopReason::max_iterations:
    case StopReason::timeout: return summary_.reached ? StopReason::converged_E : reason;
    default: return reason;
  }
}

Solver::Progress Solver::fail(const char* message) {
  failure_ = message;
  return Progress::failed;
}

bool Solver::time_is_up() {
  cut_short_ = cut_short_ || out_of_time();
  return cut_short_;
}

bool Solver::on_target() const {
  // The hard rows only: the soft ones (poles, rest pull) never decide it.
  if (!goals_.has_orientation()) {
    if (opt_.tip_tolerance > 0) return largest_tip_distance(goals_, r_) < opt_.tip_tolerance;
    if (goals_.has_soft()) return position_error(goals_, r_) < opt_.error_tolerance;
    return E_ < opt_.error_tolerance;
  }
  const bool positions = opt_.tip_tolerance > 0 ? largest_tip_distance(goals_, r_) < opt_.tip_tolerance
                                                : position_error(goals_, r_) < opt_.error_tolerance;
  return positions && largest_orientation_error_deg(goals_, r_) < opt_.orientation_tolerance_deg;
}

StopReason Solver::check_stop(double previous_E) const {
  if (summary_.iterations < opt_.min_iterations) return StopReason::running;
  // With soft rows on, on target is not yet the end: the run goes on towards the soft terms'
  // optimum until |g| is under the gradient tolerance, a step lowers E by less than
  // kSoftStallShare of it (a slow method's steps near that optimum), or the soft rows are met
  // (lm polished a knee's pole by 1e-10 of E a step for 47 iterations of a tracked frame), or
  // soft_iterations are spent.
  if (on_target() && (!goals_.soft_on() || gradient_norm_ < opt_.gradient_tolerance ||
                      previous_E - E_ < kSoftStallShare * previous_E || soft_rows_met() || soft_iterations_spent()))
    return StopReason::converged_E;
  // Goals given up: the closest point once the held goals are met and the given-up rows'
  // gradient within their freedom vanishes.
  if (priority_.active())
    return gradient_norm_ < opt_.gradient_tolerance && priority_.held_share(goals_, r_, goal_tolerance()) <= 1
               ? StopReason::converged_grad
               : StopReason::running;
  if (gradient_norm_ < opt_.gradient_tolerance && !descends_further()) return StopReason::converged_grad;
  return StopReason::running;
}

bool Solver::soft_iterations_spent() const {
  return opt_.soft_iterations > 0 && soft_on_target_since_ >= 0 &&
         summary_.iterations - soft_on_target_since_ >= opt_.soft_iterations;
}

bool Solver::soft_rows_met() const {
  const double tip = goal_tolerance().tip;
  return tip > 0 && r_.tail(m_ - goals_.hard_rows()).norm() < kSoftMetShare * tip;
}

void Solver::record() {
  if (history_size_ < static_cast<int>(history_.size())) history_[history_size_++] = E_;
}

void Solver::note_best() {
  if (together_ && E_ < together_best_E_) {
    together_best_ = a_;
    together_best_E_ = E_;
  }
  // A point on target beats any point off it (the tip test is not the E order); with goals given
  // up, one that meets the held goals beats one that does not, and among those the lower E of
  // the given-up rows wins; otherwise lower E.
  const int now = rank();
  const double given_up_E = priority_.given_up_E(goals_, r_);
  if (now != best_rank_ ? now < best_rank_ : !(now == 1 ? given_up_E < best_given_up_E_ : E_ < summary_.E)) return;
  best_rank_ = now;
  best_given_up_E_ = given_up_E;
  summary_.E = E_;
  summary_.gradient_norm = gradient_norm_;
  summary_.tip_distance = largest_tip_distance(goals_, r_);
  summary_.reached = now == 2;
  summary_.angles = a_;
  note_given_up(r_);
}

void Solver::note_given_up(const Eigen::Ref<const Eigen::VectorXd>& r) {
  const GoalTolerance tol = goal_tolerance();
  summary_.out_of_reach = !summary_.reached && priority_.position_given_up(goals_, r, tol);
  summary_.orientation_out_of_reach =
      !summary_.reached && !summary_.out_of_reach && priority_.orientation_given_up(goals_, r, tol);
}

bool Solver::settles() {
  if (opt_.paper_mode || restarts_left() || on_target()) return false;
  const double E = priority_.active() ? priority_.given_up_E(goals_, r_) : E_;
  const GoalTolerance tol = goal_tolerance();
  const double threshold = kSettleShare * tol.tip;
  settling_.record(std::sqrt(2 * E));
  // With goals given up, a run that stopped falling, or will not get nearer than the tolerance,
  // has settled. Without: one crawling towards a target beyond its chain's reach, or with goals
  // that could be given up, one that will not get nearer than the tolerance (a slow method still
  // closing on a reachable target has not; a single goal keeps the stationarity test).
  const bool strict = opt_.strict_priority && goals_.num_blocks() > 1;
  settling_.set_ended(priority_.active() ? settling_.stalled(threshold) || settling_.settled(threshold, tol.tip)
                                         : strict && ((settling_.stalled(threshold) &&
                                                       chain_restart_.beyond_any(kin_, r_, goals_, tol.tip, false)) ||
                                                      settling_.settled(threshold, kFarShare * tol.tip)));
  return settling_.ended();
}

void Solver::finish() {
  const bool closest = summary_.stop_reason == StopReason::converged_grad ||
                       (summary_.stop_reason == StopReason::zero_step && settling_.ended());
  if (!priority_.active() && !summary_.reached && closest && !opt_.paper_mode) {
    // Nothing given up: the point is the closest one for every goal.
    summary_.out_of_reach = summary_.tip_distance >= goal_tolerance().tip || !goals_.has_orientation();
    summary_.orientation_out_of_reach = !summary_.out_of_reach;
  }
}

}  // namespace ik
