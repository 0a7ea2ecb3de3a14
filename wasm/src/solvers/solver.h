// The interface every IK method implements: options with defaults, a summary, the stop reasons,
// and a start / step / solve cycle over one Kinematics.
//
// Units everywhere: angles in DEGREES (3 per bone, XZX), tips and targets in rig units,
// E = 1/2 |x(A) - x_b|^2 in rig units^2, gradients in rig units^2 per degree, time in seconds.
//
// Each method lives in its own file (gd.cpp, bfgs.cpp, ...) and is listed in
// solver_registry.cpp. Workspace is allocated by start() (only when the rig's sizes changed);
// step() allocates nothing.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "chain_restart.h"
#include "deadline.h"
#include "kinematics.h"
#include "quasi_random.h"
#include "saddle_escape.h"

namespace ik {

enum class StopReason {
  running,            // no test below has fired; step() may be called
  converged_E,        // on target: E < error_tolerance, or with tip_tolerance > 0 every effector's tip
                      // within tip_tolerance of its target
  converged_grad,     // |g| < gradient_tolerance, not on target; g = grad E without the components of fixed
                      // angles and of angles on a bound that the gradient pushes outward (paper mode: the
                      // full grad E). Outside paper mode no direction of negative curvature was found there
                      // (a local minimum: the closest point the solver can reach from here)
  zero_step,          // the line search (or damping loop) found no point with lower E: the trial point
                      // equalled A, or max_backtracks tries failed; restarts exhausted if enabled
  max_iterations,     // iterations >= max_iterations
  timeout,            // time spent inside start() and step() since start() >= time_budget_s
  invalid_input,      // start() got a wrong length, a non-finite angle or target, or a bad option; or the rig's
                      // effector list changed between start() and step() (see message)
  numerical_failure,  // E or a derivative became non-finite, or a factorisation failed at every damping
};

// "running", "converged_E", ... exactly the enumerator names.
const char* stop_reason_name(StopReason reason);

struct SolverOptions {
  // Stopping tests. Defaults are PROTOCOL.md's for every rig but beast (which uses 0.01, 0.002).
  double gradient_tolerance = 1e-4;  // rig units^2 per degree
  double error_tolerance = 2e-4;     // rig units^2
  int max_iterations = 100000;
  double time_budget_s = 1.0;        // seconds; 0 or infinity: no limit
  // Rig units. > 0: "on target" means every effector's tip lies within this distance of its
  // target, and replaces the E test (error_tolerance is then unused). 0: the E test.
  double tip_tolerance = 0;
  int history_capacity = 10000;      // E values kept per solve (the first ones; see error_history())

  // Reproduce the original program (shiinamiyuki/CSC466_Project): its central difference with
  // step fd_step_deg clamped to the limits, divided by h as it did (twice the derivative away
  // from the limits), the full |grad E| in the gradient test, and its line searches (Armijo on
  // alpha grad.p, halving until the step is 0). Counting differs by one: the original counted the
  // final call that found a stopping test true; iterations here counts accepted steps.
  bool paper_mode = false;
  double fd_step_deg = 1e-7;

  // Projected backtracking (gd, bfgs, gn, newton). GD starts at gd_initial_step, the others at 1.
  double gd_initial_step = 57.29577951308232;  // 180 / pi
  double backtrack_factor = 0.5;
  double armijo_c1 = 1e-3;                     // gd uses simple decrease (c1 = 0), as the report
  int max_backtracks = 60;                     // outside paper mode; paper mode runs until the step is 0

  // Gauss-Newton: singular values of J below this times the largest count as 0 in the
  // pseudo-inverse (outside paper mode; paper mode uses the original's max(rows, cols) * eps, with
  // which a nearly singular J sends the step thousands of degrees along its weakest direction).
  double gn_singular_cutoff = 3e-3;
  // Gauss-Newton, outside paper mode: the step is scaled down so that no angle moves more than
  // this many degrees. A full step from a straight chain can swing a joint by hundreds of degrees
  // into another basin (random targets, native: lamp 10.6 -> 7.0 us mean, knight 825 -> 428 us).
  double gn_max_step_deg = 60.0;

  // Newton: largest step per angle, degrees.
  double newton_max_step_deg = 45.0;

  // Levenberg-Marquardt (and Newton's shift): damping lambda = mu * (|r| / reach)^2 * s +
  // lm_damping_floor * s, where s is the mean diagonal of J J^T (Newton: of Hess E) over the free
  // angles, reach the rig's longest effector chain, and mu starts at lm_initial_mu.
  double lm_initial_mu = 1.0;
  double lm_damping_floor = 1e-12;
  int lm_max_rejections = 30;   // damping increases per iteration before zero_step

  // Restarts (every method, outside paper mode): when a run stalls above error_tolerance (zero
  // step, a stationary point, or best E down < 10% in stall_iterations) it restarts from a
  // quasi-random point inside the limits, keeping the best, until this many restarts or the time
  // budget are spent. On by default (every target of the benchmarks is reachable); set 0 while a
  // user drags, where a restart would make the pose jump.
  int restarts = 1000;
  int stall_iterations = 30;     // a run whose best E fell by < 10% over this many iterations stalls
  std::uint32_t seed = 1;        // quasi-random sequence offset; same seed, same restarts

  // Outside paper mode: a run that stops at a stationary point off target (a straight limb whose
  // target moved along it, a tip pointing away from its target) first looks for a direction of
  // negative curvature of E there and, if E falls along it, goes on from the lower point
  // (saddle_escape.h). The pose moves only as far as E keeps falling: no jump. While restarts
  // are left they come first (restarts = 0 while a user drags). false: stop at once, as before.
  bool escape_saddles = true;
  // Outside paper mode, with no restart left: a run that ends at a local minimum off target that
  // no escape leaves starts again from the best point with only the off-target chains moved
  // (chain_restart.h), at most this many times per solve. The other chains keep their pose;
  // an effector whose target is beyond its chain's reach gets none. A solve that starts where
  // the previous one ended, towards the same target, goes on with the restarts that one left
  // (a held drag whose frame budget ran out); otherwise the same start, target and options give
  // the same chain restarts. 64: the drag and reach experiments on every project and A7 rig
  // (8 left 0.9-2.5% of reachable reach steps off target on five rigs, 32 on the hand).
  int chain_restarts = 64;
};

struct SolverSummary {
  Eigen::VectorXd angles;       // best angles found (#angles, degrees, inside the limits)
  double initial_E = 0;         // E at the start angles (after projection into the limits)
  double E = 0;                 // E at `angles`
  double gradient_norm = 0;     // |g| at `angles` as the gradient test measures it
  double tip_distance = 0;      // largest distance of an effector's tip from its target at `angles`, rig units
  bool reached = false;         // `angles` is on target (the test of converged_E)
  int iterations = 0;           // accepted steps (a restart counts as one)
  int function_evaluations = 0; // forward-kinematics evaluations of E (line-search trials included)
  int jacobian_evaluations = 0; // Jacobian evaluations (one finite-difference Jacobian counts once)
  int restarts = 0;             // restarts performed
  int escapes = 0;              // steps along negative curvature out of a stationary point (escape_saddles)
  int chain_restarts = 0;       // restarts of the off-target chains only (chain_restarts)
  // Describes `angles`: converged_E if and only if `reached`; converged_grad only with
  // gradient_norm < gradient_tolerance; with restarts, taken from the best point, not the last run.
  StopReason stop_reason = StopReason::invalid_input;
  std::string message;          // why, for invalid_input and numerical_failure
  double elapsed_s = 0;         // seconds spent inside start() and step()
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

  // One iteration. Returns true while the solve is still running. No allocation. Between steps
  // the Kinematics may be used by others (posed elsewhere): every method re-poses what it reads.
  bool step();

  // start() and step() until stopped. Returns the summary.
  const SolverSummary& solve(const Eigen::Ref<const Eigen::VectorXd>& angles,
                             const Eigen::Ref<const Eigen::VectorXd>& target);

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
  // Marks a numerical failure with `message` (a string literal); returns Progress::failed.
  Progress fail(const char* message);
  // Is the solve over its time budget right now?
  bool out_of_time() const;
  // For the long loops inside one iteration: out_of_time(), and if so the iteration's `stuck`
  // reports timeout, not zero_step.
  bool time_is_up();
  // When the time budget runs out (never, without a budget).
  Deadline deadline() const;
  // Is the current iterate (E_, r_) on target (the test of converged_E)?
  bool on_target() const;

  Kinematics& kin_;
  SolverOptions opt_;       // the current solve's
  SolverOptions next_opt_;  // from set_options(), copied into opt_ by start()
  int n_ = 0;  // #angles
  int m_ = 0;  // #residuals
  std::vector<int> effectors_;  // the rig's effector list the workspace was sized for
  Eigen::VectorXd target_, a_, trial_, r_, r_trial_, g_;
  Eigen::MatrixXd J_;
  double E_ = 0;
  double gradient_norm_ = 0;
  // Free angles at a_: not fixed (min == max) and not on a bound that grad E pushes outward.
  std::vector<int> free_;         // indices of the free angles, the first num_free_ entries
  Eigen::VectorXd free_mask_;     // 1 for a free angle, 0 otherwise
  int num_free_ = 0;
  double reach_ = 1;              // longest effector chain (sum of bone lengths), rig units
  // The largest #angles the method takes with `residuals` residuals (its dense matrices grow
  // with #angles squared); the base class applies kMaxDenseAngles in paper mode.
  virtual int angle_limit(int /*residuals*/) const { return kNoAngleLimit; }
  static constexpr int kNoAngleLimit = 1 << 30;

 private:
  StopReason check_stop() const;
  bool has_budget() const;  // a finite time budget is set
  void record();
  void note_best();
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
  // Moves to the next quasi-random start inside the limits (a new run) if restarts are left.
  // Returns false when none is left or E is not finite there.
  bool restart();
  // From a stationary point off target, outside paper mode with escape_saddles: moves to a lower
  // point along negative curvature (saddle_escape.h). Returns false if there is none.
  bool escape();
  // From a local minimum off target, outside paper mode: a new run from the best point with the
  // off-target chains moved (chain_restart.h). Returns false if none is left or worth trying.
  bool chain_restart();
  // After a run stopped off target with `reason` (zero_step, converged_grad, or running for a
  // stall): leaves the point by an escape (not for a stall) or a restart, counting it as an
  // iteration, and sets `reason` to the stop test at the new point (or numerical_failure).
  // Returns false when neither applies; `reason` is then unchanged, or max_iterations / timeout
  // when the budget is spent while restarts (whole or chain) are left.
  bool move_on(StopReason& reason);
  // The stop reason reported for the best point when the solve ends with `reason` (describing
  // the current iterate): see SolverSummary::stop_reason.
  StopReason settle(StopReason reason) const;
  bool validate(const Eigen::Ref<const Eigen::VectorXd>& angles, const Eigen::Ref<const Eigen::VectorXd>& target);

  SolverSummary summary_;
  std::vector<double> history_;
  int history_size_ = 0;
  // Finite-difference workspace (paper mode).
  Eigen::VectorXd fd_scratch_, fd_plus_, fd_minus_;
  const char* failure_ = nullptr;
  // Restarts.
  QuasiRandom sequence_;
  std::uint32_t sequence_seed_ = 0;
  long restart_index_ = 0;
  int run_iterations_ = 0, run_best_iteration_ = 0;
  double run_best_E_ = 0;
  Eigen::VectorXd unit_;
  SaddleEscape escape_;
  ChainRestart chain_restart_;
  long chain_index_ = 0;  // chain restarts drawn, in this solve and the ones it continues
  // start(); `close`: read the clock at the end (solve() leaves it to the first step).
  StopReason begin(const Eigen::Ref<const Eigen::VectorXd>& angles, const Eigen::Ref<const Eigen::VectorXd>& target,
                   bool close);
  // step() from `begin`, the time its call started.
  bool advance(std::chrono::steady_clock::time_point begin);
  std::chrono::steady_clock::time_point call_start_, last_read_;
  double elapsed_before_call_ = 0;
  bool cut_short_ = false;  // this step's iteration gave up because the time budget ran out
};

}  // namespace ik
