// The interface every IK method implements: options with defaults (solver_options.h), a summary,
// the stop reasons, and a start / step / solve cycle over one Kinematics.
//
// Units everywhere: angles in DEGREES (3 per bone, XZX), tips and targets in rig units,
// E = 1/2 |x(A) - x_b|^2 in rig units^2, gradients in rig units^2 per degree, time in seconds.
// With goals (goals.h) E = 1/2 |r|^2 over the goals' residual rows (weighted positions, and
// orientations as rotation vectors times a length), still in rig units^2.
//
// Each method lives in its own file (gd.cpp, bfgs.cpp, ...) and is listed in
// solver_registry.cpp. Workspace is allocated by start() (only when the rig's sizes or the
// goals' layout changed); step() allocates nothing.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "block_pattern.h"
#include "chain_restart.h"
#include "damping.h"
#include "deadline.h"
#include "goals.h"
#include "joint_motion.h"
#include "kinematics.h"
#include "priority.h"
#include "restarts.h"
#include "saddle_escape.h"
#include "settling.h"
#include "solver_options.h"
#include "time_budget.h"

namespace ik {

enum class StopReason {
  running,            // no test below has fired; step() may be called
  converged_E,        // on target: E < error_tolerance, or with tip_tolerance > 0 every effector's tip
                      // within tip_tolerance of its target. With orientation goals: E over the position
                      // rows only (or the tip test), and every orientation within orientation_tolerance_deg.
                      // With soft rows (poles, rest_weight > 0): E over the position rows only, and
                      // while the soft rows are on, also |g| < gradient_tolerance or the last step
                      // lowered E by less than 1e-4 of it
  converged_grad,     // |g| < gradient_tolerance, not on target; g = grad E without the components of fixed
                      // angles and of angles on a bound that the gradient pushes outward (free_set.h; paper
                      // mode: the full grad E). While restarts are left a run stops there only once |g| <
                      // gradient_tolerance / 10 (descends_further()), and then restarts. Outside paper mode
                      // with escape_saddles no direction of negative curvature was found there (a local
                      // minimum: the closest point the solver can reach from here)
  zero_step,          // the line search (or damping loop) found no point with lower E: the trial point
                      // equalled A, or max_backtracks tries failed; restarts exhausted if enabled
  max_iterations,     // iterations >= max_iterations
  timeout,            // time spent inside start() and step() since start() >= time_budget_s
  invalid_input,      // start() got a wrong length, a non-finite angle or target, bad goals (or goals other than
                      // plain positions in paper mode), or a bad option; or the rig's
                      // effector list changed between start() and step() (see message)
  numerical_failure,  // E or a derivative became non-finite, or a factorisation failed at every damping
  joint_speed,        // a chain restart's answer lay farther than max_joint_move from the start
                      // (joint_motion.h): the angles are the pose partway there, not on target; the
                      // next solve from them resumes the move
};

// "running", "converged_E", ... exactly the enumerator names.
const char* stop_reason_name(StopReason reason);

struct SolverSummary {
  Eigen::VectorXd angles;        // best angles found (#angles, degrees, inside the limits)
  double initial_E = 0;          // E at the start angles (after projection into the limits)
  double E = 0;                  // E at `angles` (with the soft rows while they are on)
  double gradient_norm = 0;      // |g| at `angles` as the gradient test measures it
  double tip_distance = 0;       // largest distance of an effector's tip from its target at `angles`, rig units
                                 // (position goals only; 0 without any)
  bool reached = false;          // `angles` is on target (the test of converged_E)
  int iterations = 0;            // accepted steps (a restart counts as one)
  int function_evaluations = 0;  // forward-kinematics evaluations of E (line-search trials included)
  int jacobian_evaluations = 0;  // Jacobian evaluations (one finite-difference Jacobian counts once)
  int restarts = 0;              // restarts performed
  int escapes = 0;               // steps along negative curvature out of a stationary point (escape_saddles)
  int chain_restarts = 0;        // restarts of the off-target chains only (chain_restarts)
  // Strict priority (priority.h), outside paper mode: when the goals cannot all be met, the ones
  // that can are held within their tolerance and the others given up, brought as close as the
  // freedom left allows. At `angles`: a position goal was given up and is off target (out of
  // reach), or only orientation goals were (their positions held: orientation out of reach).
  bool out_of_reach = false;
  bool orientation_out_of_reach = false;
  int goals_given_up = 0;  // goals (3-row blocks) given up in this solve; 0: none (the
                           // history then falls at every step of a run)
  // Describes `angles`: converged_E if and only if `reached` (keep_contract() holds it at the end
  // of every solve, as it holds the numbers above free of NaN); converged_grad only with
  // gradient_norm < gradient_tolerance; with restarts, taken from the best point, not the last run.
  // With goals given up (out_of_reach or orientation_out_of_reach), gradient_norm is that of the
  // given-up rows within what leaves the held ones alone (Priority::reduced_gradient_norm).
  StopReason stop_reason = StopReason::invalid_input;
  std::string message;   // why, for invalid_input and numerical_failure
  double elapsed_s = 0;  // seconds spent inside start() and step()
};

class Solver {
 public:
  // The solver works on `kin`, which must outlive it. Options are checked by start().
  Solver(Kinematics& kin, const SolverOptions& options);
  virtual ~Solver() = default;
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  // Registry name of the method ("lm", ...).
  virtual const char* name() const = 0;

  // Replaces the options. They take effect at the next start(), which checks them; a solve in
  // progress keeps the options it started with.
  void set_options(const SolverOptions& options) { next_opt_ = options; }

  // Begins a solve from `angles` (#angles, degrees; projected into the limits) towards `target`
  // (#residuals, rig units). Sizes the workspace if the rig's effectors changed since the last
  // start(). Returns running, converged_E / converged_grad (already there), or invalid_input.
  StopReason start(const Eigen::Ref<const Eigen::VectorXd>& angles, const Eigen::Ref<const Eigen::VectorXd>& target);
  // The same towards `goals` (goals.h): per effector a position and/or an orientation goal with
  // weights, bend hints (poles) and stiffness. Position goals of weight 1 alone (no pole, option
  // rest_weight 0) behave exactly as start(angles, target); paper mode takes nothing else
  // (invalid_input). Goals of weight 0 count as none. Goals GoalSet::set() refuses give
  // invalid_input with its message.
  //
  // Soft rows (poles, and the rest pull of option rest_weight > 0, in either start()) never
  // decide "on target". When a run with them stops off target (zero_step, converged_grad, a
  // stall) they are lowered 10x and the run goes on from that point (before any escape or
  // restart), and below 1e-3 of their weight dropped for the rest of the solve: the solve ends
  // on target near the soft terms' optimum. If the run without them still stops off target, the
  // next run is the plain solve from the start angles (once), then restarts and escapes as
  // usual: soft terms do not lower the success rate (soft_goals_test measures it).
  StopReason start(const Eigen::Ref<const Eigen::VectorXd>& angles, const Goals& goals);

  // A move for the next solve's first Levenberg-Marquardt step to add where the goals leave room:
  // `move` (#angles: degrees, then a floating root's translation in rig units) becomes d0 in the
  // step d0 + delta, delta the damped least change that meets the goals' linearisation from
  // a + d0, so that to first order the goals see none of d0. A posture preference applied once per
  // solve (an avatar's body unwinding its twist); a first trial it makes worse is tried again
  // without it. Other methods, a solve that starts with goals given up and one that starts on its
  // goals to round-off (it takes no step) ignore it. Returns
  // false, keeping none, when `move` has not #angles values or one is not finite. Allocates only
  // when #angles changes.
  bool set_preferred_move(const Eigen::Ref<const Eigen::VectorXd>& move);

  // One iteration. Returns true while the solve is still running. No allocation. Between steps
  // the Kinematics may be used by others (posed elsewhere): every method re-poses what it reads.
  bool step();

  // start() and step() until stopped. Returns the summary.
  const SolverSummary& solve(const Eigen::Ref<const Eigen::VectorXd>& angles,
                             const Eigen::Ref<const Eigen::VectorXd>& target);
  // The same towards `goals` (see start(angles, goals)).
  const SolverSummary& solve(const Eigen::Ref<const Eigen::VectorXd>& angles, const Goals& goals);

  bool running() const { return summary_.stop_reason == StopReason::running; }
  // The state so far: best angles, E, counts, stop reason (running while not stopped).
  const SolverSummary& summary() const { return summary_; }
  // The current iterate (#angles, degrees). With restarts it can differ from summary().angles.
  const Eigen::VectorXd& angles() const { return a_; }
  // E per iteration: [0] at the start, [k] after iteration k; at most history_capacity values.
  Eigen::Map<const Eigen::VectorXd> error_history() const {
    return Eigen::Map<const Eigen::VectorXd>(history_.data(), history_size_);
  }
  // The options of the current solve (set_options() shows here after the next start()).
  const SolverOptions& options() const { return opt_; }
  const Kinematics& kinematics() const { return kin_; }

 protected:
  // What one iteration of a method did.
  enum class Progress {
    moved,   // a_, r_, E_ hold the new point; kin_ is posed there
    stuck,   // no point with lower E found (zero_step)
    failed,  // numerical failure; message set through fail()
  };

  // Method workspace for `residuals` x `angles` (called by start() when the sizes or the
  // effector list changed).
  virtual void resize(int residuals, int angles) = 0;
  // Method state at the start of a run: of a solve, and after each restart (e.g. BFGS's H = I).
  virtual void reset() {}
  // One iteration from a_ (with r_, E_, J_, g_, the free set). On `moved`, must leave kin_ posed at a_.
  virtual Progress iterate() = 0;

  // E and the residual at `angles` (poses kin_ there); counts one function evaluation.
  double evaluate(const Eigen::Ref<const Eigen::VectorXd>& angles, Eigen::Ref<Eigen::VectorXd> residual);
  // Projected backtracking from a_ along `direction` (line_search.h) from alpha = `initial_step`
  // with sufficient-decrease constant `c1`, the options' factor and max_backtracks. Paper mode
  // halves until the step is 0 and takes the original's unprojected slope. On success moves to
  // the accepted point (a_, r_, E_; trial_ then holds the previous angles) and returns true.
  bool backtrack(const Eigen::Ref<const Eigen::VectorXd>& direction, double initial_step, double c1);
  // J_, g_, the free set and the gradient norm at a_, given r_. `posed`: kin_ is posed at a_.
  // Returns false if the gradient is not finite.
  bool update_derivatives(bool posed);
  // After an accepted step: does it end the run on target whatever the gradient (no soft rows,
  // nothing given up, the iterations asked for taken; not plain goals, paper mode or a run of
  // the goals together)? Then only the gradient there is needed, for its norm.
  bool ends_on_target() const;
  // g_, the free set and the gradient norm at a_ (kin_ posed there), as update_derivatives()
  // but without J_ (goal_gradient: a tracked frame's last Jacobian was never used). Returns
  // false if the gradient is not finite.
  bool update_gradient();
  // Marks a numerical failure with `message` (a string literal); returns Progress::failed.
  Progress fail(const char* message);
  // Is the solve over its time budget right now?
  bool out_of_time() const { return deadline().passed(); }
  // For the long loops inside one iteration: out_of_time(), and if so the iteration's `stuck`
  // reports timeout, not zero_step.
  bool time_is_up();
  // The iteration gave up because deadline() passed: its `stuck` reports timeout, not zero_step.
  void gave_up_for_time() { cut_short_ = true; }
  // When the time budget runs out (never, without a budget, or before the solve's first
  // opt_.steps_before_budget accepted steps).
  Deadline deadline() const { return budget_holds() ? clock_.deadline() : Deadline(); }
  // The solve has taken opt_.steps_before_budget accepted steps: its time budget can stop it.
  bool budget_holds() const { return summary_.iterations >= opt_.steps_before_budget; }
  // Is the current iterate (E_, r_) on target (the test of converged_E)?
  bool on_target() const;
  // The preferred move (set_preferred_move()) while this solve has not yet used it, else null;
  // marking it used leaves it for no later step.
  const Eigen::VectorXd* preferred_move() const { return preferred_on_ ? &preferred_ : nullptr; }
  void mark_preferred_move_used() { preferred_on_ = false; }

  Kinematics& kin_;
  SolverOptions opt_;           // the current solve's
  SolverOptions next_opt_;      // from set_options(), copied into opt_ by start()
  int n_ = 0;                   // #angles
  int m_ = 0;                   // #residuals
  std::vector<int> effectors_;  // the rig's effector list the workspace was sized for
  std::vector<int> layout_;     // the goals' block layout the workspace was sized for
  GoalSet goals_;               // the current solve's goals: the residual's rows (goals.h)
  Eigen::VectorXd a_, trial_, r_, r_trial_, g_;
  Eigen::MatrixXd J_;
  double E_ = 0;
  double gradient_norm_ = 0;
  // Free angles at a_ (free_set.h): not fixed (min == max) and not on a bound that grad E pushes outward.
  std::vector<int> free_;      // indices of the free angles, ascending, the first num_free_ entries
  Eigen::VectorXd free_mask_;  // 1 for a free angle, 0 otherwise
  int num_free_ = 0;
  double reach_ = 1;      // longest effector chain (sum of bone lengths), rig units
  BlockPattern pattern_;  // which residual blocks each angle moves (sized with the workspace)
  // The largest #angles the method takes with `residuals` residuals (its dense matrices grow
  // with #angles squared); the base class applies kMaxPaperAngles in paper mode.
  virtual int angle_limit(int /*residuals*/) const { return kNoAngleLimit; }
  static constexpr int kNoAngleLimit = 1 << 30;

 private:
  // The stop test at the current iterate; `previous_E`: E before the step that led here (with
  // soft rows on, a step that barely lowered E ends a run on target).
  StopReason check_stop(double previous_E = std::numeric_limits<double>::infinity()) const;
  void record();
  void note_best();
  // Moving on from a run stopped off target (solver_move_on.cpp).
  // With restarts on, after each accepted step: is the run stalling (best E down < 10% over
  // stall_iterations)?
  bool stalls();
  // Outside paper mode, fewer restarts done in this solve than the option allows.
  bool restarts_left() const;
  // Outside paper mode, fewer chain restarts drawn (in this solve and the ones it continues) than
  // the option allows.
  bool chain_restarts_left() const;
  // With restarts left and E above the error tolerance: is |g| under the gradient tolerance but
  // above a tenth of it (still descending: the gradient test does not end the run)?
  bool descends_further() const;
  // With soft rows (poles, rest pull) on and the run stopped off target: lowers them 10x (to 0
  // below 1e-3: dropped for the rest of the solve) and goes on from the current point (a new
  // run; E_, r_ and the best point's E re-evaluated).
  void lower_soft_terms();
  // The soft rows' scale after `scale` when a run stops off target: 10x lower, 0 below 1e-3.
  static double lowered_soft_scale(double scale);
  // Once per solve, with the soft rows dropped and the run stopped off target: a new run from
  // the start angles without them (the plain solve), so that soft rows never lower the success rate.
  void retry_without_soft_terms();
  // A new run from the start angles (E_, r_ there).
  void run_from_start();
  // set_preferred_move()'s move; pending until the next start(), on until its first step.
  Eigen::VectorXd preferred_;
  bool preferred_pending_ = false, preferred_on_ = false;
  bool soft_retried_ = false;
  // The iteration at which this solve's hard goals were first on target with soft rows on (-1:
  // not yet): soft_iterations counts from it.
  int soft_on_target_since_ = -1;
  Eigen::VectorXd start_;  // the solve's start angles, projected
  // Moves to the next quasi-random start inside the limits (a new run) if restarts are left.
  // Returns false when none is left or E is not finite there.
  bool restart();
  // From a stationary point off target, outside paper mode with escape_saddles: moves to a lower
  // point along negative curvature (saddle_escape.h). Returns false if there is none.
  bool escape();
  // From a local minimum off target, outside paper mode: a new run from the best point with the
  // off-target chains moved (chain_restart.h). Returns false if none is left or worth trying.
  bool chain_restart();
  // Strict priority (solver_priority.cpp). With nothing left to try off target: gives up the
  // next goal (Priority::give_up_next at the best point) and starts a priority run from the
  // start angles. Returns false when no goal can be given up.
  bool give_up_next_goal();
  // At the best point: is some off-target effector's target beyond what its chain reaches with
  // the effectors on target kept there (ChainRestart::beyond_any)? Outside paper mode, with
  // strict_priority.
  bool beyond_reach();
  // In priority mode: are the held goals met at the current point?
  bool held() const;
  // Could give_up_next_goal() still give a goal up (a budget stop is then not the last word)?
  bool could_give_up() const;
  // One iteration of the priority run: the damped task-priority step (priority.h), judged first
  // by the held goals (while they are beyond kHoldShare of their tolerance), then by the
  // given-up ones with the held ones kept there.
  Progress priority_iterate();
  // How far off a goal may be and count as met (the options' tolerances).
  GoalTolerance goal_tolerance() const;
  // The soft rows' residual at the current point is under kSoftMetShare of the tip tolerance.
  bool soft_rows_met() const;
  // soft_iterations (> 0) taken since the hard goals were first on target.
  bool soft_iterations_spent() const;
  // The current point's rank: 2 on target, 1 the held goals met (priority mode), 0 otherwise.
  int rank() const;
  // Sets the summary's out_of_reach flags for the best point, whose residual is `r`.
  void note_given_up(const Eigen::Ref<const Eigen::VectorXd>& r);
  // After an accepted step off target with nothing but a give-up left to try (no restart left,
  // outside paper mode): has the run settled (settling.h) on a closest point? Its distance: of
  // the given-up goals in priority mode, else sqrt(2 E).
  bool settles();
  Settling settling_;  // also: whether the last run ended by settling, not by a stop test
  // At the end of a solve that used a chain restart or resumed a move, with max_joint_move > 0
  // outside paper mode: a best point farther than allowed_move_ from the start is replaced by the pose partway there
  // (JointMotion::limit), stopped with joint_speed, E, the gradient norm and the tip distance measured there.
  void bound_motion();
  // With max_joint_move > 0, a chain restart's answer on target that moved the joints farther
  // than allowed_move_ is kept as a candidate and the next chain restart tried from where the
  // first one started (stuck_), up to kNearerTries answers and kSeekRestarts chain restarts
  // (those that end off target included): the nearest answer is the solve's
  // (take_nearest(), at the end), which bound_motion() may still cut partway. Returns true when
  // a chain restart began (`reason`: the stop test at its start).
  bool seek_nearer(StopReason& reason);
  // Makes a_ the solve's answer: E, the gradient norm and the tip distance measured there, the
  // stop reason converged_E on target, else `otherwise`. False (the answer unchanged) when E or
  // its gradient is not finite there.
  bool answer_here(StopReason otherwise);
  void take_nearest();
  static constexpr int kNearerTries = 4;
  static constexpr int kRestoreSteps = 8;   // priority steps that bring a partway pose's held goals back
  static constexpr int kRestoreRounds = 3;  // partway poses sought, each towards the last one restored
  static constexpr int kSeekRestarts = 16;
  int nearer_tries_ = 0;
  int seek_limit_ = 0;  // summary_.chain_restarts at which the search ends
  double nearest_move_ = 0;
  Eigen::VectorXd nearest_, stuck_;
  JointMotion motion_;
  // How far a joint may move in this solve: max_joint_move plus the largest goal residual block
  // at the start (how far the targets moved from the tips), rig units.
  double allowed_move_ = 0;
  Eigen::VectorXd moved_from_;  // the solve's start angles (start_ is the run's start, which a resumed move replaces)
  // After a joint_speed stop: the answer it was heading to, and the pose it returned. A solve
  // starting at that pose resumes the move: its run starts from the answer.
  Eigen::VectorXd heading_to_, partway_;
  bool heading_ = false;
  bool resumed_ = false;  // this solve resumed such a move
  // After a budget stop (max_iterations, timeout) off target in the middle of a chain restart's
  // run, with joint speed bounded: the run's point. A solve from the pose the last one returned
  // (summary_.angles, its best point, not the run's) towards the same goals carries the run on from
  // its point, the pose staying the best point until the run beats it: a frame too short for a
  // chain restart's run no longer throws the run away and draws the next one (a 6-joint arm's
  // tool turned onto another branch of solutions drew all 64 chain restarts, 5 iterations each,
  // and gave up its orientation goal as out of reach).
  Eigen::VectorXd carried_run_;
  bool carrying_ = false;
  bool chain_run_going_ = false;  // the current run began at a chain restart, or carries one on
  // At the end of a solve, before anything moves a_: is its run one to carry on (above)?
  bool carries_run() const;
  // At the start of a solve that carries a run on: the run goes on from carried_run_.
  void carry_run_on();
  // Everything a solve does when it stops, in order: back from a run of the goals as equals
  // (end_together()), the nearest answer a search found (take_nearest()), the out_of_reach flags
  // (finish()), the speed bound (bound_motion()), the summary's rules (keep_contract()).
  void conclude();
  // At the end of a solve: the out_of_reach flags (from the given-up goals, or without any, from
  // a run that ended at a stationary or settled point off target).
  void finish();
  // Last of all when a solve stops (solver_contract.cpp): the summary obeys SolverSummary's rules
  // whatever happened on the way: no NaN among its numbers (one that overflowed reads +infinity,
  // with numerical_failure), and stop_reason converged_E exactly when reached.
  void keep_contract();
  Priority priority_;
  NielsenDamping priority_damping_;
  int best_rank_ = 0;
  double best_given_up_E_ = 0;
  bool chain_run_ = false;  // the priority run began at a chain restart, not at the start angles
  // A priority run with a yielding goal (the dragged one) stopped off target, the held goals
  // met, the target not beyond its chain's reach: once per solve, a run of every goal as an
  // equal from the start angles (priority_ suspended), which moves on as a plain solve does
  // (escapes, chain restarts: the priority run keeps those left) and by reweight_together().
  // Where holding the others exactly leaves the yielding goal no way on, letting them move
  // within their tolerance finds the pose that meets every goal. Only an answer on target counts (rank 2 beats the
  // priority run's); when nothing is left to try, end_together() goes back to the priority run's
  // best point. Returns false (nothing begun) when it does not apply.
  bool begin_together();
  // When the chain restarts are spent, from the run's best point: every goal within
  // kReweightNear times its tolerance, some beyond (the least-squares point shares the error
  // out, the tip test asks each goal to be within its tolerance), those beyond weigh more
  // (goals_'s block scales) and the run goes on, up to kReweights times. After that, or when
  // the point is not near, the goals' own weights come back (restore_weights()) and it returns
  // false.
  bool reweight_together();
  void restore_weights();
  void end_together();
  static constexpr int kReweights = 4;
  static constexpr double kReweightNear = 10;
  bool together_ = false;  // that run is under way
  bool together_tried_ = false;
  // Its lowest-E point (where its chain restarts start from; summary_ keeps the priority run's).
  Eigen::VectorXd together_best_;
  double together_best_E_ = 0;
  int reweights_ = 0;  // so far; -1: no more
  // Chain restarts of a run of the goals as equals that ended off target: the priority run from
  // the start that follows it follows E down from there (no branch change to bound).
  int discarded_chain_restarts_ = 0;

  // After a run stopped off target with `reason` (zero_step, converged_grad, or running for a
  // stall): leaves the point by an escape (not for a stall) or a restart, counting it as an
  // iteration, and sets `reason` to the stop test at the new point (or numerical_failure).
  // Returns false when neither applies; `reason` is then unchanged, or max_iterations / timeout
  // when the budget is spent while restarts (whole or chain) are left.
  bool move_on(StopReason& reason);
  // After a move to a new point (a softened run, a restart, an escape, a chain restart), counted
  // as an iteration: its derivatives, history and best-point bookkeeping; returns the stop test
  // there, or numerical_failure (with the message) when E or its gradient is not finite.
  StopReason measure_new_start();
  // Joint speed is bounded: max_joint_move > 0, outside paper mode.
  bool bounds_joints() const { return opt_.max_joint_move > 0 && !opt_.paper_mode; }

  // The stop reason reported for the best point when the solve ends with `reason` (describing
  // the current iterate): see SolverSummary::stop_reason.
  StopReason settle(StopReason reason) const;
  // Sizes the workspace for the rig's current effectors.
  void resize_workspace();

  SolverSummary summary_;
  std::vector<double> history_;
  int history_size_ = 0;
  // Finite-difference workspace (paper mode).
  Eigen::VectorXd fd_scratch_, fd_plus_, fd_minus_;
  const char* failure_ = nullptr;
  Restarts restarts_;
  SaddleEscape escape_;
  ChainRestart chain_restart_;
  long chain_index_ = 0;  // chain restarts drawn, in this solve and the ones it continues
  // start() towards incoming_ (set by the caller); `close`: read the clock at the end (solve()
  // leaves it to the first step). `goals_problem`: what is wrong with incoming_, if anything.
  StopReason begin(const Eigen::Ref<const Eigen::VectorXd>& angles, const std::string& goals_problem, bool close);
  GoalSet incoming_;  // the goals given to start() / solve(), checked by begin()
  // solve() towards incoming_.
  const SolverSummary& run(const Eigen::Ref<const Eigen::VectorXd>& angles, const std::string& goals_problem);
  // step() from `begin`, the time its call started.
  bool advance(TimeBudget::Clock::time_point begin);
  TimeBudget clock_;
  bool cut_short_ = false;  // this step's iteration gave up because the time budget ran out
};

}  // namespace ik
