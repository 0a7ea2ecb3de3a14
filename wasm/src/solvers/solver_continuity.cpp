// The Solver's continuity while a user drags (option max_joint_move > 0, outside paper mode):
// a chain restart that lands on another branch of solutions far from the start looks for a
// nearer answer (seek_nearer(), take_nearest()), and an answer still too far comes back partway,
// the next solve resuming the move (bound_motion(), joint_motion.h); a chain restart's run that
// the budget cut off target goes on in the next solve (carries_run(), carry_run_on()). The rest of the Solver is in
// solver.cpp, solver_move_on.cpp and solver_priority.cpp.
#include <cmath>

#include "goal_residual.h"
#include "solver.h"

namespace ik {

bool Solver::answer_here(StopReason otherwise) {
  E_ = evaluate(a_, r_);
  if (!std::isfinite(E_) || !update_derivatives(true)) return false;
  summary_.angles = a_;
  summary_.E = E_;
  summary_.gradient_norm = gradient_norm_;
  summary_.tip_distance = largest_tip_distance(goals_, r_);
  summary_.reached = on_target();
  summary_.out_of_reach = summary_.orientation_out_of_reach = false;
  summary_.stop_reason = summary_.reached ? StopReason::converged_E : otherwise;
  return true;
}

bool Solver::seek_nearer(StopReason& reason) {
  if (!bounds_joints() || summary_.chain_restarts == discarded_chain_restarts_ || nearer_tries_ >= kNearerTries ||
      out_of_time() || summary_.iterations >= opt_.max_iterations)
    return false;
  kin_.forward(a_);
  const double move = motion_.largest_move(kin_);
  if (move <= allowed_move_) return false;  // near enough
  if (move < nearest_move_) {
    nearest_ = a_;
    nearest_move_ = move;
  }
  if (nearer_tries_++ == 0) seek_limit_ = summary_.chain_restarts + kSeekRestarts;
  if (summary_.chain_restarts >= seek_limit_ || !chain_restart()) return false;
  ++summary_.chain_restarts;
  reason = measure_new_start();
  return true;
}

void Solver::take_nearest() {
  if (nearer_tries_ == 0 || summary_.stop_reason == StopReason::numerical_failure) return;
  if (summary_.reached) {
    kin_.forward(summary_.angles);
    if (motion_.largest_move(kin_) <= nearest_move_) return;
  }
  a_ = nearest_;
  answer_here(summary_.stop_reason);
}

void Solver::bound_motion() {
  const double bound = allowed_move_;
  const StopReason stop = summary_.stop_reason;
  if (!bounds_joints() || stop == StopReason::numerical_failure || stop == StopReason::invalid_input) return;
  // A run from the start follows E down from there: it moves the body as the target moved (a
  // straight limb starting to bend included). Only a chain restart can land on another branch.
  if (summary_.chain_restarts == discarded_chain_restarts_ && !resumed_) return;
  kin_.forward(summary_.angles);
  if (motion_.largest_move(kin_) <= bound) return;
  heading_to_ = summary_.angles;
  // Partway in angles is not partway on target: the held goals (the pinned effectors) are
  // brought back within their tolerance by a few priority steps from there. Those steps move the
  // joints too (8% of the character's height in one frame, seen): past the bound, the partway
  // pose is sought again towards the restored one, whose held goals are met. When no round
  // gives a pose within the bound that holds them, the solve stays at its start (the held goals
  // met there): no snap and no pinned limb pulled away; the next solve starts afresh.
  const bool restore = priority_.active();
  trial_ = summary_.angles;  // where the partway pose heads
  for (int round = 0; round < kRestoreRounds; ++round) {
    motion_.limit(kin_, moved_from_, trial_, bound, a_);
    if (!answer_here(StopReason::joint_speed)) return;
    if (!restore || held()) break;
    if (round + 1 == kRestoreRounds) {
      a_ = moved_from_;
      answer_here(StopReason::joint_speed);
      return;
    }
    priority_damping_.reset(opt_.lm_initial_mu);
    for (int i = 0; i < kRestoreSteps && !held(); ++i) {
      const Progress p = priority_iterate();
      if (p != Progress::moved || !update_derivatives(true)) break;
    }
    if (!answer_here(StopReason::joint_speed)) return;
    kin_.forward(a_);
    if (held() && motion_.largest_move(kin_) <= bound) break;
    trial_ = a_;
  }
  partway_ = a_;
  heading_ = true;
}

bool Solver::carries_run() const {
  const bool budget = summary_.stop_reason == StopReason::max_iterations || summary_.stop_reason == StopReason::timeout;
  return bounds_joints() && budget && chain_run_going_ && !together_ && nearer_tries_ == 0 && !summary_.reached &&
         std::isfinite(E_) && a_ != summary_.angles;
}

void Solver::carry_run_on() {
  a_ = carried_run_;
  E_ = evaluate(a_, r_);
  if (!std::isfinite(E_) || !update_derivatives(true)) {  // finite when it was cut; kept safe
    a_ = start_;
    E_ = evaluate(a_, r_);
    update_derivatives(true);
    return;
  }
  settling_.begin_run();
  reset();
  chain_run_ = priority_.active();
  chain_run_going_ = true;
  resumed_ = true;  // its answer may lie on another branch: bound_motion() bounds the move
  priority_damping_.reset(opt_.lm_initial_mu);
  note_best();
}

}  // namespace ik
