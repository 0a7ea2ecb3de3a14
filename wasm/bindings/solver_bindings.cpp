// embind bindings for the solvers: a Solver is one method (solver_registry.h) on one Rig.
// Arrays cross as typed arrays in bulk; a result crosses one way, through the solve buffer
// (io_view(): solve_io() and result_io() write it, summary_numbers.def lists its numbers). A failed call returns null
// ("", false, -1) and leaves the message for takeError() (js_arrays.h says why nothing is thrown). The Rig must outlive
// the Solver; JavaScript must call delete() on the Solver (the TS wrapper's dispose() does).
#include <emscripten/bind.h>

#include <algorithm>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "goal_input.h"
#include "js_arrays.h"
#include "rig_binding.h"
#include "solver_options.h"
#include "solvers/solver_registry.h"

namespace ik::js {

using emscripten::val;

class SolverBinding {
 public:
  // A solver of `method` on `rig` (JavaScript owns it), or null for an unknown method or a
  // malformed options object.
  static SolverBinding* create(RigBinding& rig, const std::string& method, const val& options) {
    return guarded([&] { return new SolverBinding(rig, make_solver(method, rig.kinematics(), read_options(options))); },
                   static_cast<SolverBinding*>(nullptr));
  }

  // The registered method names, in display order.
  static val methods() {
    val names = val::array();
    for (const SolverEntry& e : solver_registry()) names.call<void>("push", std::string(e.name));
    return names;
  }

  // One line describing `method`; "" for an unknown name.
  static std::string describe(const std::string& method) {
    return guarded([&] { return std::string(entry(method).description); }, std::string());
  }

  // The short human name of `method` ("Levenberg–Marquardt"); "" for an unknown name.
  static std::string label(const std::string& method) {
    return guarded([&] { return std::string(entry(method).label); }, std::string());
  }

  std::string method() const { return solver_->name(); }
  bool running() const { return solver_->running(); }

  // Replaces the options (same object shape as create()'s); they apply from the next start().
  // False (the old options kept) for a malformed object.
  bool set_options(const val& options) {
    return guarded(
        [&] {
          solver_->set_options(read_options(options));
          return true;
        },
        false);
  }

  // The options of the current solve, every field.
  val options() const { return write_options(solver_->options()); }

  // The default options, every field (their names are the options a solver takes).
  static val default_options() { return write_options(SolverOptions()); }

  // A buffer of `length` numbers for set_goals_io(), and a Float64Array view on it (stale,
  // length 0, when the WebAssembly memory grows: ask again). Null on failure.
  val goals_view(int length) {
    return guarded(
        [&] {
          if (length < 0) throw RigError("a negative goals length");
          if (goals_io_.size() != static_cast<size_t>(length)) goals_io_.assign(static_cast<size_t>(length), 0.0);
          return val(emscripten::typed_memory_view(goals_io_.size(), goals_io_.data()));
        },
        val::null());
  }

  // Goals beyond plain positions for the following start() and solve_io() calls, read from
  // goals_view()'s buffer: `packed_length` numbers of goals (goal_input.h: kGoalStride per end
  // effector), then `poles_length` of bend hints (kPoleStride each), then `stiffness_length` of
  // stiffness (one per bone, or none); length_scale rig units per radian, 0: the rig's reach. The
  // target still gives the positions. No JavaScript value crosses, and nothing is allocated once
  // the sizes settle (a tracked avatar's goals turn every frame). False (the old goals kept) if
  // refused.
  bool set_goals_io(int packed_length, int poles_length, int stiffness_length, double length_scale) {
    return guarded(
        [&] {
          if (packed_length < 0 || poles_length < 0 || stiffness_length < 0) throw RigError("a negative array length");
          const size_t total = static_cast<size_t>(packed_length) + poles_length + stiffness_length;
          if (total > goals_io_.size())
            throw RigError("the goals buffer holds " + std::to_string(goals_io_.size()) + " numbers, " +
                           std::to_string(total) + " were sent (goalsView sizes it)");
          const double* at = goals_io_.data();
          goal_numbers_.assign(at, at + packed_length);
          at += packed_length;
          pole_numbers_.assign(at, at + poles_length);
          at += poles_length;
          stiffness_numbers_.assign(at, at + stiffness_length);
          goal_input_.set(rig_.kinematics(), goal_numbers_, pole_numbers_, stiffness_numbers_, length_scale);
          has_goals_ = true;
          return true;
        },
        false);
  }

  // A buffer of #angles numbers for set_preferred_io(), and a Float64Array view on it (stale,
  // length 0, when the WebAssembly memory grows: ask again). Null on failure.
  val preferred_view() {
    return guarded(
        [&] {
          const size_t n = static_cast<size_t>(rig_.kinematics().num_angles());
          if (preferred_io_.size() != n) preferred_io_.assign(n, 0.0);
          return val(emscripten::typed_memory_view(preferred_io_.size(), preferred_io_.data()));
        },
        val::null());
  }

  // The next solve's preferred move (Solver::set_preferred_move()) from preferred_view()'s buffer:
  // degrees per angle, then a floating root's translation in rig units. Throws for a buffer of
  // the wrong length or a value that is not finite: false, the message for takeError(), no move
  // kept. No JavaScript value crosses.
  bool set_preferred_io() {
    return guarded(
        [&] {
          const Eigen::Map<const Eigen::VectorXd> move(preferred_io_.data(),
                                                       static_cast<Eigen::Index>(preferred_io_.size()));
          if (!solver_->set_preferred_move(move))
            throw RigError("the preferred move has " + std::to_string(preferred_io_.size()) + " values, expected " +
                           std::to_string(rig_.kinematics().num_angles()) + " finite ones (preferredView sizes it)");
          return true;
        },
        false);
  }

  // Back to plain position goals of weight 1.
  void clear_goals() { has_goals_ = false; }

  bool has_goals() const { return has_goals_; }

  // Begins a solve: angles (3 per bone, degrees), target (3 per end effector, rig units).
  // Returns the stop reason after the start ("running" unless already converged), "" on failure.
  std::string start(const val& angles, const val& target) {
    return guarded(
        [&] {
          begin(angles, target);
          return std::string(stop_reason_name(solver_->summary().stop_reason));
        },
        std::string());
  }

  // One iteration; true while still running. No allocation on the C++ side.
  bool step() { return solver_->step(); }

  // The solve so far (or the finished one) into the solve buffer, as solve_io() writes a solve's:
  // its best angles over the start angles, the result numbers after the target. For step-wise
  // solves (start(), step()); io_view() must have been asked for the rig's current effectors.
  // Returns the stop reason's index, or -1 on failure.
  int result_io() {
    return guarded(
        [&] {
          check_io_lengths();
          write_result(solver_->summary());
          return static_cast<int>(solver_->summary().stop_reason);
        },
        -1);
  }

  // The current solve's message: why, for invalid_input and numerical_failure; "" otherwise.
  std::string message() const { return solver_->summary().message; }

  // E at the start and after each iteration so far, with no JavaScript values crossing:
  // history_io() copies it into a buffer kept across calls (it only grows) and returns how many
  // numbers that is, or -1 on failure; history_view() is a Float64Array view of the whole buffer,
  // to ask for again whenever it is shorter than history_io()'s count (the buffer grew, or the
  // WebAssembly memory did and left the old view empty).
  int history_io() {
    return guarded(
        [&] {
          const auto h = solver_->error_history();
          const size_t n = static_cast<size_t>(h.size());
          // Grown at once to what a solve with these options keeps, so that a stream of solves
          // (a frame's) asks for a new view once, not at each longer history.
          const SolverOptions& o = solver_->options();
          const size_t most = static_cast<size_t>(std::min(o.max_iterations, o.history_capacity - 1)) + 1;
          if (history_.size() < n) history_.resize(std::max(n, most));
          std::copy(h.data(), h.data() + n, history_.begin());
          return static_cast<int>(n);
        },
        -1);
  }

  val history_view() { return val(emscripten::typed_memory_view(history_.size(), history_.data())); }

  // The current iterate (Float64Array copy, degrees).
  val angles() const { return copy_out(solver_->angles().data(), solver_->angles().size()); }

  // The whole solve in one call with no JavaScript values crossing (the TS wrapper's solve()).
  // io_view() sizes a buffer of #angles | #residuals target numbers | kIoStats result numbers
  // for the rig's current effectors and returns a Float64Array view on it (it goes stale, length
  // 0, when the WebAssembly memory grows: ask again). JavaScript writes the start angles
  // (degrees) and target (rig units) there; solve_io() solves and writes the best angles over
  // the start angles and the result numbers after the target (see IoStat). Returns the stop
  // reason as its enumerator index (stop_reasons() names them), or -1 on failure.
  val io_view() {
    return guarded(
        [&] {
          const Kinematics& kin = rig_.kinematics();
          const size_t size = static_cast<size_t>(kin.num_angles() + kin.num_residuals()) + kIoStats;
          if (io_.size() != size)
            io_.assign(size, 0.0);  // kept otherwise: a view asked anew after growth reads the result
          io_n_ = kin.num_angles();
          io_m_ = kin.num_residuals();
          return val(emscripten::typed_memory_view(io_.size(), io_.data()));
        },
        val::null());
  }

  int solve_io() {
    return guarded(
        [&] {
          check_io_lengths();
          write_result(solve_on(io_.data(), io_.data() + io_n_));
          return static_cast<int>(solver_->summary().stop_reason);
        },
        -1);
  }

  // The stop reasons' names, indexed by solve_io()'s return value.
  static val stop_reasons() {
    val names = val::array();
    for (int i = 0; i <= static_cast<int>(StopReason::joint_speed); ++i)
      names.call<void>("push", std::string(stop_reason_name(static_cast<StopReason>(i))));
    return names;
  }

  // Where solve_io() and result_io() write each result number, after the target
  // (summary_numbers.def); io_stats() names them in this order, so JavaScript reads the offsets
  // from here instead of repeating them.
  enum IoStat {
#define IK_SUMMARY_NUMBER(field, js_name) k_##field,
#include "solvers/summary_numbers.def"
#undef IK_SUMMARY_NUMBER
    kIoStats
  };

  // The result numbers' names (as in the result object), indexed by IoStat.
  static val io_stats() {
    val names = val::array();
#define IK_SUMMARY_NUMBER(field, js_name) names.call<void>("push", std::string(js_name));
#include "solvers/summary_numbers.def"
#undef IK_SUMMARY_NUMBER
    return names;
  }

  // The names of the result numbers that are flags (bools, written as 1 or 0).
  static val io_flags() {
    val names = val::array();
#define IK_SUMMARY_NUMBER(field, js_name) \
  if (std::is_same_v<decltype(SolverSummary::field), bool>) names.call<void>("push", std::string(js_name));
#include "solvers/summary_numbers.def"
#undef IK_SUMMARY_NUMBER
    return names;
  }

 private:
  SolverBinding(RigBinding& rig, std::unique_ptr<Solver> solver) : rig_(rig), solver_(std::move(solver)) {}

  // The registry's entry for `method`; throws RigError for an unknown name.
  static const SolverEntry& entry(const std::string& method) {
    for (const SolverEntry& e : solver_registry())
      if (method == e.name) return e;
    throw RigError("unknown solver method \"" + method + "\"");
  }

  // Copies the arrays in and starts; throws for wrong lengths and for invalid_input.
  void begin(const val& angles, const val& target) {
    take(angles, target);
    const Eigen::Map<const Eigen::VectorXd> a(angles_.data(), angles_.size());
    if (has_goals_)
      solver_->start(a, goal_input_.with_positions(rig_.kinematics(), target_.data()));
    else
      solver_->start(a, Eigen::Map<const Eigen::VectorXd>(target_.data(), target_.size()));
    throw_if_invalid();
  }

  // Copies the arrays into angles_ and target_; throws for wrong lengths.
  void take(const val& angles, const val& target) {
    const Kinematics& kin = rig_.kinematics();
    copy_in(angles, kin.num_angles(), angles_, "angles");
    copy_in(target, kin.num_residuals(), target_, "target");  // the rig's effectors right now
  }

  // Solver::solve() from `angles` (#angles, degrees) towards `target` (#residuals, rig units),
  // lengths already checked; throws for invalid_input.
  const SolverSummary& solve_on(const double* angles, const double* target) {
    const Kinematics& kin = rig_.kinematics();
    const Eigen::Map<const Eigen::VectorXd> a(angles, kin.num_angles());
    if (has_goals_)
      solver_->solve(a, goal_input_.with_positions(kin, target));
    else
      solver_->solve(a, Eigen::Map<const Eigen::VectorXd>(target, kin.num_residuals()));
    throw_if_invalid();
    return solver_->summary();
  }

  // invalid_input (bad options or numbers) as an exception, with the options' JavaScript names.
  void throw_if_invalid() const {
    if (solver_->summary().stop_reason == StopReason::invalid_input)
      throw RigError(with_js_option_names(solver_->summary().message));
  }

  // The solve buffer's angles and target are the rig's current sizes (io_view() was asked since
  // the effectors last changed); throws otherwise.
  void check_io_lengths() const {
    const Kinematics& kin = rig_.kinematics();
    check_length(io_n_, kin.num_angles(), "angles");
    check_length(io_m_, kin.num_residuals(), "target");
  }

  // `s`'s best angles over the buffer's start angles (none before a first solve, or after a
  // refused one: invalid_input), its numbers after the target.
  void write_result(const SolverSummary& s) {
    if (s.angles.size() == io_n_) std::copy(s.angles.data(), s.angles.data() + io_n_, io_.begin());
    double* stats = io_.data() + io_n_ + io_m_;
#define IK_SUMMARY_NUMBER(field, js_name) stats[k_##field] = static_cast<double>(s.field);
#include "solvers/summary_numbers.def"
#undef IK_SUMMARY_NUMBER
  }

  static void check_length(int given, int expected, const char* what) {
    if (given != expected)
      throw RigError(std::string(what) + " has " + std::to_string(given) + " values, expected " +
                     std::to_string(expected));
  }

  RigBinding& rig_;
  std::unique_ptr<Solver> solver_;
  std::vector<double> angles_, target_;
  std::vector<double> io_;            // solve_io(): angles | target | result numbers
  std::vector<double> history_;       // history_io()
  std::vector<double> preferred_io_;  // preferred_view()'s buffer
  GoalInput goal_input_;
  std::vector<double> goals_io_;                                         // goals_view()'s buffer
  std::vector<double> goal_numbers_, pole_numbers_, stiffness_numbers_;  // set_goals_io()'s copies
  bool has_goals_ = false;
  int io_n_ = 0, io_m_ = 0;
};

}  // namespace ik::js

EMSCRIPTEN_BINDINGS(ik_solvers) {
  using ik::js::SolverBinding;
  emscripten::class_<SolverBinding>("Solver")
      .class_function("create", &SolverBinding::create, emscripten::allow_raw_pointers())
      .class_function("methods", &SolverBinding::methods)
      .class_function("describe", &SolverBinding::describe)
      .class_function("label", &SolverBinding::label)
      .class_function("defaultOptions", &SolverBinding::default_options)
      .property("method", &SolverBinding::method)
      .property("running", &SolverBinding::running)
      .function("setOptions", &SolverBinding::set_options)
      .function("options", &SolverBinding::options)
      .function("goalsView", &SolverBinding::goals_view)
      .function("setGoalsIo", &SolverBinding::set_goals_io)
      .function("clearGoals", &SolverBinding::clear_goals)
      .function("preferredView", &SolverBinding::preferred_view)
      .function("setPreferredIo", &SolverBinding::set_preferred_io)
      .property("hasGoals", &SolverBinding::has_goals)
      .function("start", &SolverBinding::start)
      .function("step", &SolverBinding::step)
      .function("resultIo", &SolverBinding::result_io)
      .function("message", &SolverBinding::message)
      .function("historyIo", &SolverBinding::history_io)
      .function("historyView", &SolverBinding::history_view)
      .function("angles", &SolverBinding::angles)
      .function("ioView", &SolverBinding::io_view)
      .function("solveIo", &SolverBinding::solve_io)
      .class_function("stopReasons", &SolverBinding::stop_reasons)
      .class_function("ioStats", &SolverBinding::io_stats)
      .class_function("ioFlags", &SolverBinding::io_flags);
}
