// The Solver's ways out of a run that stopped off target (move_on()): with soft rows on, a new
// run with them lowered (or dropped); then a whole restart from a quasi-random point
// (restarts.h), an escape along negative curvature (saddle_escape.h) or a restart of the
// off-target chains only (chain_restart.h), in that order of preference, and when none is left
// giving up the goals that cannot be met (solver_priority.cpp), within the iteration and time
// budgets. The rest of the Solver is in solver.cpp, solver_priority.cpp and
// solver_continuity.cpp.
#include <cmath>

#include "solver.h"

namespace ik {

namespace {

// With restarts left, a run above the error tolerance counts as stationary (and restarts) only
// when |g| is below this share of the gradient tolerance. The protocol's tolerance is absolute
// (rig units^2 per degree): on a small rig such as the knight, a run still descending towards
// its target passes it long before it nears a stationary point, and restarting there threw away
// good runs (knight random gd: 71% success in 20 ms mean; with this test 100% in 0.4 ms).
constexpr double kStationaryFraction = 0.1;

// Escapes from stationary points per solve (each lowers E; this bounds a solve without a time budget).
constexpr int kMaxEscapes = 50;

// A run with soft rows (poles, rest pull) that stops off target goes on with them times this
// factor, and once the factor falls below kSoftFloor without them: each run ends nearer the
// target and the last one on it, near the point of the hard goals' solutions that the soft
// terms prefer (soft_goals_test measures the cost).
constexpr double kSoftShrink = 0.1;
constexpr double kSoftFloor = 1e-3;

bool finite(double x) { return std::isfinite(x); }

}  // namespace

bool Solver::stalls() {
  if (opt_.restarts == 0 || opt_.paper_mode) return false;
  return restarts_.stalls(E_, opt_.stall_iterations);
}

// With goals given up, a run moves on only by giving up more (solver_priority.cpp): a restart
// or an escape would judge the point by the weighted sum of all goals.
bool Solver::restarts_left() const {
  return !opt_.paper_mode && !priority_.active() && restarts_.used() < opt_.restarts;
}

bool Solver::chain_restarts_left() const { return !opt_.paper_mode && chain_index_ < opt_.chain_restarts; }

bool Solver::descends_further() const {
  return restarts_left() && !on_target() && gradient_norm_ >= kStationaryFraction * opt_.gradient_tolerance;
}

double Solver::lowered_soft_scale(double scale) {
  scale *= kSoftShrink;
  return scale < kSoftFloor ? 0.0 : scale;
}

void Solver::lower_soft_terms() {
  goals_.set_soft_scale(lowered_soft_scale(goals_.soft_scale()));
  restarts_.begin_run();
  settling_.begin_run();
  reset();
  // E changed meaning: the best point's E is measured afresh (poses kin_ there), then the current one's.
  summary_.E = evaluate(summary_.angles, r_trial_);
  E_ = evaluate(a_, r_);
}

void Solver::retry_without_soft_terms() {
  soft_retried_ = true;
  run_from_start();
}

void Solver::run_from_start() {
  a_ = start_;
  chain_run_going_ = false;
  restarts_.begin_run();
  settling_.begin_run();
  reset();
  E_ = evaluate(a_, r_);
}

bool Solver::restart() {
  if (!restarts_left()) return false;
  restarts_.next_start(kin_.lower(), kin_.upper(), a_);
  chain_run_going_ = false;
  settling_.begin_run();
  reset();
  E_ = evaluate(a_, r_);
  return finite(E_);
}

bool Solver::escape() {
  if (opt_.paper_mode || !opt_.escape_saddles || summary_.escapes >= kMaxEscapes) return false;
  kin_.forward(a_);  // the tip Hessian reads the pose
  const EscapeResult found = escape_.find(kin_, goals_, a_, r_, E_, J_, trial_, r_trial_);
  summary_.function_evaluations += found.evaluations;
  if (!found.found) return false;
  a_.swap(trial_);
  r_.swap(r_trial_);
  E_ = found.E;
  reset();
  settling_.begin_run();
  return true;
}

bool Solver::beyond_reach() {
  if (opt_.paper_mode || !opt_.strict_priority) return false;
  evaluate(summary_.angles, r_trial_);  // poses kin_ at the best point
  return chain_restart_.beyond_any(kin_, r_trial_, goals_, goal_tolerance().tip, false);
}

bool Solver::chain_restart() {
  if (!chain_restarts_left()) return false;
  // The first one in a solve notes where the run was stuck; seeking a nearer answer
  // (seek_nearer()) goes on from there, not from the answer found.
  if (summary_.chain_restarts == discarded_chain_restarts_) stuck_ = summary_.angles;
  trial_ = nearer_tries_ > 0 ? stuck_ : together_ ? together_best_ : summary_.angles;
  evaluate(trial_, r_trial_);  // poses kin_ at the best point
  // How far off a tip may be on target: the tip tolerance, or with the E test the distance at which
  // one effector alone makes E the tolerance.
  const double slack = opt_.tip_tolerance > 0 ? opt_.tip_tolerance : std::sqrt(2 * opt_.error_tolerance);
  if (!chain_restart_.propose(kin_, trial_, r_trial_, goals_, slack, priority_.active(), restarts_.sequence(),
                              ++chain_index_, a_))
    return false;
  restarts_.begin_run();
  settling_.begin_run();
  reset();
  chain_run_ = priority_.active();
  chain_run_going_ = true;
  priority_damping_.reset(opt_.lm_initial_mu);
  E_ = evaluate(a_, r_);
  return finite(E_);
}

bool Solver::move_on(StopReason& reason) {
  // Soft rows on and the current point off target (an earlier point may have been on it): they
  // are lowered first, whatever the best point so far.
  const bool soften = goals_.soft_on() && !on_target();
  // Dropped soft rows and still off target: the path they bent may have led where the hard goals
  // alone converge slowly (a rest pose of straight limbs is a singular pose); the plain solve
  // from the start angles comes next, before any escape or restart.
  const bool retry = !goals_.soft_on() && goals_.has_soft() && !soft_retried_;
  // An answer on target is in hand and a nearer one sought (seek_nearer()): a run that stops
  // off target moves on to the next chain restart, while any of the search's are left.
  const bool seeking = nearer_tries_ > 0;
  if (summary_.reached && !soften && !seeking) return false;
  const bool out_of_iterations = summary_.iterations >= opt_.max_iterations;
  if (out_of_iterations || out_of_time()) {
    // The budget, not the problem, ends the solve while restarts of either kind are left.
    const bool left = restarts_left() || chain_restarts_left() || could_give_up();
    if (left) reason = out_of_iterations ? StopReason::max_iterations : StopReason::timeout;
    return false;
  }
  // Restarts come first while any are left: on random targets escaping first cost more than it
  // saved (native, lm, 1000 restarts: knight 96 -> 184 us mean, beast 75 -> 137 us).
  const bool stationary = reason == StopReason::zero_step || reason == StopReason::converged_grad;
  // Every goal as an equal (solver.h, begin_together()): an escape, a chain restart, then heavier
  // weights on the goals beyond their tolerance; when none is left, back to the priority run.
  if (together_) {
    if (stationary && escape())
      ++summary_.escapes;
    else if (stationary && chain_restart())
      ++summary_.chain_restarts;
    else if (stationary && reweight_together()) {
    } else
      end_together();
    reason = measure_new_start();
    return true;
  }
  // Without restarts: an escape along negative curvature first (a straight limb), then chain
  // restarts (the other chains follow the moved ones: a hand's fingers around a moved wrist),
  // unless a target lies beyond its chain's reach; then the goals that cannot be met are given
  // up, and what is left of the chain restarts moves the given-up chains only.
  const bool last_resort = stationary && !restarts_left();
  const bool prioritised = priority_.active();
  const bool beyond = !prioritised && last_resort && beyond_reach();
  if (seeking) {
    if (!stationary || summary_.chain_restarts >= seek_limit_ || !chain_restart()) return false;
    ++summary_.chain_restarts;
  } else if (soften)
    lower_soft_terms();  // counted below as a step, like a restart
  else if (retry)
    retry_without_soft_terms();
  else if (!prioritised && last_resort && !beyond && escape())
    ++summary_.escapes;
  else if (!prioritised && last_resort && !beyond && chain_restart())
    ++summary_.chain_restarts;
  else if (!prioritised && last_resort && give_up_next_goal()) {
  } else if (!prioritised && restart())
    ++summary_.restarts;
  else if (prioritised && !held() && !chain_run_ && give_up_next_goal()) {
  } else if (prioritised && stationary && begin_together()) {
  } else if (prioritised && stationary && chain_restart())
    ++summary_.chain_restarts;  // the given-up chains moved, the held ones kept (a run that
                                // fails to keep them is not a reason to give up more)
  else
    return false;
  reason = measure_new_start();
  return true;
}

StopReason Solver::measure_new_start() {
  ++summary_.iterations;
  if (!finite(E_) || !update_derivatives(false)) {
    summary_.message = "E or its gradient is not finite after an escape or a restart";
    return StopReason::numerical_failure;
  }
  record();
  note_best();
  return check_stop();
}

}  // namespace ik
