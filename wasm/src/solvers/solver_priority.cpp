// Strict priority in the Solver (priority.h): when nothing else is left to try off target (or at
// once, for a goal that yields or a target beyond its chain's reach), a goal is given up in
// priority.h's order and a priority run starts from the solve's start angles: every step holds
// the other goals (Newton on their rows) and brings the given-up ones as close as the freedom
// left allows. Every method takes
// these steps once goals are given up (outside paper mode), so all of them follow one order:
// reachable goals within their tolerance, then the closest point for the rest. A yielding goal
// within its chain's reach that the priority run leaves off target is tried with every goal as
// an equal too (begin_together()): what the goals reach together, the yielding one reaches. The
// rest of the Solver is in solver.cpp and solver_move_on.cpp.
#include <algorithm>
#include <cmath>

#include "goal_residual.h"
#include "solver.h"

namespace ik {

namespace {

// While a held goal is beyond this share of its tolerance, a step is judged by the held goals
// alone (they are brought back first); below it, by the given-up ones, with the held ones kept
// below it or where they were.
constexpr double kHoldShare = 0.5;

// Rejected trials per priority iteration before it is stuck (each is a whole active-set solve,
// and at a closest point every trial fails): with Nielsen's rule mu has grown by 2^45 by then.
constexpr int kMaxRejections = 10;

}  // namespace

GoalTolerance Solver::goal_tolerance() const {
  GoalTolerance tol;
  tol.tip = opt_.tip_tolerance > 0 ? opt_.tip_tolerance : std::sqrt(2 * opt_.error_tolerance);
  tol.orientation_deg = opt_.orientation_tolerance_deg;
  return tol;
}

int Solver::rank() const {
  if (on_target()) return 2;
  return priority_.active() && held() ? 1 : 0;
}

bool Solver::held() const { return priority_.held_share(goals_, r_, goal_tolerance()) <= 1; }

bool Solver::could_give_up() const {
  if (opt_.paper_mode || !opt_.strict_priority || summary_.reached || goals_.num_blocks() < 2) return false;
  return !priority_.active() || !held();
}

bool Solver::give_up_next_goal() {
  if (opt_.paper_mode || !opt_.strict_priority) return false;
  const GoalTolerance tol = goal_tolerance();
  if (priority_.active()) {
    // The priority run ended here with a held goal off target: one more is given up.
    if (!priority_.give_up_next(goals_, r_, tol)) return false;
  } else {
    evaluate(summary_.angles, r_trial_);  // the best point so far (the least-squares closest point)
    if (!priority_.give_up_next(goals_, r_trial_, tol)) return false;
  }
  summary_.goals_given_up = priority_.count();
  // The best point ranked again under the new levels.
  evaluate(summary_.angles, r_trial_);
  best_rank_ = priority_.held_share(goals_, r_trial_, tol) <= 1 ? 1 : 0;
  best_given_up_E_ = priority_.given_up_E(goals_, r_trial_);
  note_given_up(r_trial_);
  chain_run_ = false;
  priority_damping_.reset(opt_.lm_initial_mu);
  run_from_start();
  return std::isfinite(E_);
}

bool Solver::begin_together() {
  if (together_tried_ || opt_.paper_mode || !goals_.has_yielding() || !held()) return false;
  evaluate(start_, r_trial_);  // poses kin_ at the start angles, where the goals were set
  if (chain_restart_.beyond_any(kin_, r_trial_, goals_, goal_tolerance().tip, false)) return false;
  together_tried_ = together_ = true;
  reweights_ = 0;
  priority_.suspend();
  run_from_start();
  together_best_ = a_;
  together_best_E_ = E_;
  return std::isfinite(E_);
}

bool Solver::reweight_together() {
  if (reweights_ == 0) {  // the first from the run's best point
    a_ = together_best_;
    E_ = evaluate(a_, r_);
  }
  const GoalTolerance tol = goal_tolerance();
  bool near = true, off = false;
  for (int b = 0; b < goals_.num_blocks(); ++b) {
    const double share = block_share(goals_, r_, b, tol);
    near = near && share < kReweightNear;
    off = off || share > 1;
  }
  if (reweights_ >= 0 && reweights_ < kReweights && near && off) {
    for (int b = 0; b < goals_.num_blocks(); ++b) {
      const double share = block_share(goals_, r_, b, tol);
      if (share > 1) goals_.set_block_scale(b, goals_.block(b).scale * 2 * share);
    }
    ++reweights_;
    settling_.begin_run();
    reset();
    E_ = evaluate(a_, r_);
    together_best_ = a_;  // E has a new meaning: the best point from here on
    together_best_E_ = E_;
    return std::isfinite(E_);
  }
  // None (more): the goals' own weights back, E measured with them again.
  if (reweights_ > 0) {
    restore_weights();
    together_best_E_ = evaluate(together_best_, r_trial_);
    E_ = evaluate(a_, r_);
  }
  reweights_ = -1;
  return false;
}

void Solver::restore_weights() {
  for (int b = 0; b < goals_.num_blocks(); ++b) goals_.set_block_scale(b, incoming_.block(b).scale);
}

void Solver::end_together() {
  if (!together_) return;
  together_ = false;
  priority_.resume();
  if (reweights_ > 0) restore_weights();
  // On target: its answer, measured with the goals' own weights. Off: the priority run goes on
  // from its best point (its chain restarts next). Either was finite there, and so were its
  // derivatives.
  if (!summary_.reached) discarded_chain_restarts_ = summary_.chain_restarts;
  a_ = summary_.angles;
  settling_.begin_run();
  reset();
  if (summary_.reached) {
    answer_here(StopReason::converged_E);
  } else {
    E_ = evaluate(a_, r_);
    update_derivatives(true);
  }
}

Solver::Progress Solver::priority_iterate() {
  const double s = priority_.scale();
  if (!std::isfinite(s)) return fail("the Jacobian is not finite");
  if (!(s > 0)) return Progress::stuck;  // no movable angle moves a goal
  const GoalTolerance tol = goal_tolerance();
  const double held_before = priority_.held_share(goals_, r_, tol);
  const bool restoring = held_before > kHoldShare;
  const double held_E = priority_.held_E(goals_, r_), given_up_E = priority_.given_up_E(goals_, r_);
  for (int attempt = 0; attempt < std::min(opt_.lm_max_rejections, kMaxRejections); ++attempt) {
    if (attempt > 0 && time_is_up()) return Progress::stuck;
    // Bringing the held goals back: Levenberg-Marquardt on their rows (their error sets the
    // damping), the others damped 1 / kHeldDamping times as much. Holding them: the damping of
    // the given-up rows, the held ones nearly undamped.
    const double lambda =
        restoring
            ? priority_damping_.shift(2 * held_E / (reach_ * reach_), opt_.lm_damping_floor, s) / Priority::kHeldDamping
            : priority_damping_.shift(2 * given_up_E / (reach_ * reach_), opt_.lm_damping_floor, s);
    const double floor = restoring ? 0 : opt_.lm_damping_floor * s;
    switch (priority_.step(kin_, J_, pattern_, a_, r_, lambda, floor, deadline(), trial_)) {
      case Priority::Status::failed: return fail("the priority step's matrix could not be factorised");
      case Priority::Status::out_of_time: gave_up_for_time(); return Progress::stuck;
      case Priority::Status::ok: break;
    }
    if (trial_ == a_) return Progress::stuck;
    const double E_trial = evaluate(trial_, r_trial_);
    bool accepted;
    if (restoring) {
      accepted =
          priority_damping_.accept(held_E, priority_.held_E(goals_, r_trial_), priority_.predicted_decrease(r_, true));
    } else {
      const bool held = priority_.held_share(goals_, r_trial_, tol) <= std::max(kHoldShare, held_before);
      const double trial_given_up_E = held ? priority_.given_up_E(goals_, r_trial_) : INFINITY;
      accepted = priority_damping_.accept(given_up_E, trial_given_up_E, priority_.predicted_decrease(r_, false));
    }
    if (accepted && std::isfinite(E_trial)) {
      a_.swap(trial_);
      r_.swap(r_trial_);
      E_ = E_trial;
      return Progress::moved;
    }
  }
  return Progress::stuck;
}

}  // namespace ik
