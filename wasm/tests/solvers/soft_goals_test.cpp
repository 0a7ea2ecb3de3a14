// Soft terms (bend hints and the rest pull, goals.h) in the Solver: a pole chooses a limb's bend
// without moving its tip (also from a straight limb), the rest pull lowers the distance from the
// rest pose at equal success, stiffness holds a bone back, every method stays on target with
// them (as often as without), restWeight 0 changes nothing, and paper mode refuses them. The
// figures (tip error with and without poles, mean |angle - rest| with and without the rest pull,
// success counts) are printed to stdout.
#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>
#include <limits>

#include "../sanitizers.h"
#include "../small_rigs.h"
#include "goal_residual.h"
#include "registered_methods.h"
#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// Which side of the S-T axis M lies on, relative to P: the cosine between their projections.
double bend_cosine(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                   const Eigen::Vector3d& P) {
  const Eigen::Vector3d u = (T - S).normalized();
  const Eigen::Vector3d v = (M - S) - (M - S).dot(u) * u, q = (P - S) - (P - S).dot(u) * u;
  return v.dot(q) / (v.norm() * q.norm());
}

Goals position_goals(const Eigen::VectorXd& target) {
  Goals goals;
  goals.effectors.resize(target.size() / 3);
  for (size_t e = 0; e < goals.effectors.size(); ++e) goals.effectors[e].position_target = target.segment<3>(3 * e);
  return goals;
}

// A pole for every effector bone with a parent and a bend at `angles` (the goal pose): its elbow
// pushed one limb length further out along its bend, so that the goal pose satisfies it.
std::vector<PoleGoal> poles_of(Kinematics& kin, const Eigen::VectorXd& angles) {
  kin.forward(angles);
  std::vector<PoleGoal> poles;
  for (int bone : kin.rig().effectors) {
    const int parent = kin.rig().bones[bone].parent;
    if (parent < 0) continue;
    const Eigen::Vector3d S = kin.joint_origin(parent), M = kin.joint_origin(bone), T = kin.tip(bone);
    const Eigen::Vector3d u = (T - S).normalized(), v = (M - S) - (M - S).dot(u) * u;
    if (v.norm() < 1e-3 * (T - S).norm()) continue;  // straight: no side to hint
    poles.push_back({bone, M + (T - S).norm() * v.normalized(), 1.0});
  }
  return poles;
}

bool within_limits(const Kinematics& kin, const Eigen::VectorXd& a) {
  return (a.array() >= kin.lower().array()).all() && (a.array() <= kin.upper().array()).all();
}

// start() and step() to the end, checking the limits at every iterate.
const SolverSummary& stepped_solve(Solver& solver, const Eigen::VectorXd& start, const Goals& goals,
                                   bool& limits_held) {
  solver.start(start, goals);
  limits_held = within_limits(solver.kinematics(), solver.angles());
  while (solver.step()) limits_held = limits_held && within_limits(solver.kinematics(), solver.angles());
  limits_held = limits_held && within_limits(solver.kinematics(), solver.summary().angles);
  return solver.summary();
}

// Tips within 1e-4 rig units, and a gradient tolerance to match (the default 1e-4 rig units^2
// per degree stops gd and newton about 1e-3 off on this small rig).
SolverOptions tight_options() {
  SolverOptions o;
  o.time_budget_s = 0;
  o.tip_tolerance = 1e-4;
  o.gradient_tolerance = 1e-10;
  return o;
}

// Two bones of length 1 bent by 60 degrees at the elbow (in the xy plane, elbow on one side);
// the pole on the other side: the elbow mirrored in the shoulder-wrist axis (in the bend plane,
// where a tilt-free residual would be flat), or moved `out_of_plane` rig units off that plane.
TEST(SoftGoals, APoleFlipsTheBendWithoutMovingTheTip) {
  Kinematics kin(test::two_bones());
  Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());
  start[4] = 60;
  kin.forward(start);
  const Eigen::Vector3d S = kin.joint_origin(0), M = kin.joint_origin(1), T = kin.tip(1);
  const Eigen::Vector3d u = (T - S).normalized();
  const Eigen::Vector3d mirrored = (M - S).dot(u) * u - ((M - S) - (M - S).dot(u) * u);  // M reflected in S-T
  for (const std::string& method : test::kMethods) {
    for (double out_of_plane : {0.0, 0.3, -0.5, 1.5}) {
      Goals goals = position_goals(T);
      goals.poles.push_back({1, mirrored + Eigen::Vector3d(0, 0, out_of_plane), 1});
      auto solver = make_solver(method, kin, tight_options());
      const SolverSummary& s = solver->solve(start, goals);
      kin.forward(s.angles);
      const double side = bend_cosine(kin.joint_origin(0), kin.joint_origin(1), kin.tip(1), goals.poles[0].point);
      std::cout << "pole flip " << method << " out of plane " << out_of_plane << ": tip moved "
                << (kin.tip(1) - T).norm() << ", bend cosine to the pole " << bend_cosine(S, M, T, goals.poles[0].point)
                << " -> " << side << ", iterations " << s.iterations << "\n";
      EXPECT_TRUE(s.reached) << method;
      EXPECT_LT((kin.tip(1) - T).norm(), 1e-4) << method;
      EXPECT_GT(side, 0.99) << method << " " << out_of_plane;
    }
  }
}

// soft_iterations caps the iterations a run takes towards the soft terms once the tip is on
// target: each one more takes one more iteration, never more than without a cap, always on target
// with E no higher than the one before. lm on a straight chain of three bones whose tip is
// brought in a little, a light pole beside its last two: the tip is on target after 4 iterations,
// and bending the limb on to the pole (an avatar's knee starting to crouch) takes 3 more.
TEST(SoftGoals, SoftIterationsCapThePolishOnTarget) {
  Kinematics kin(test::straight_chain(3, {2}));
  const Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());
  Goals goals = position_goals(Eigen::Vector3d(2.95, 0, 0));
  goals.poles.push_back({2, Eigen::Vector3d(2, 0, 2), 0.02});
  SolverOptions options = tight_options();
  options.tip_tolerance = 1e-2;
  auto uncapped = make_solver("lm", kin, options);
  const SolverSummary free_run = uncapped->solve(start, goals);
  std::cout << "soft iterations: uncapped " << free_run.iterations << " iterations, E " << free_run.E << "\n";
  int first = -1;
  double previous_E = std::numeric_limits<double>::infinity();
  for (int cap = 1; cap <= 2; ++cap) {
    options.soft_iterations = cap;
    auto solver = make_solver("lm", kin, options);
    const SolverSummary& s = solver->solve(start, goals);
    std::cout << "soft iterations " << cap << ": " << s.iterations << " iterations, E " << s.E << "\n";
    EXPECT_TRUE(s.reached) << cap;
    EXPECT_EQ(s.stop_reason, StopReason::converged_E) << cap;
    if (first < 0) first = s.iterations;
    EXPECT_EQ(s.iterations, first + cap - 1) << cap;
    EXPECT_LE(s.E, previous_E) << cap;
    previous_E = s.E;
  }
  EXPECT_GT(free_run.iterations, first + 1);  // the case is worth testing: uncapped, it polishes on
  EXPECT_LE(free_run.E, previous_E);
}

TEST(SoftGoals, APoleBendsAStraightLimbTowardsIt) {
  Kinematics kin(test::two_bones());
  const Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());  // straight along +x
  const Eigen::Vector3d target(1.2, 0.5, 0.3);
  for (const std::string& method : test::kMethods) {
    for (const Eigen::Vector3d& pole : {Eigen::Vector3d(0.5, 0, 2), Eigen::Vector3d(0.5, 0, -2),
                                        Eigen::Vector3d(0.5, -2, 0), Eigen::Vector3d(0.5, 2, 0)}) {
      Goals goals = position_goals(target);
      goals.poles.push_back({1, pole, 1});
      auto solver = make_solver(method, kin, tight_options());
      const SolverSummary& s = solver->solve(start, goals);
      kin.forward(s.angles);
      const double side = bend_cosine(kin.joint_origin(0), kin.joint_origin(1), kin.tip(1), pole);
      std::cout << "pole from straight " << method << " pole " << pole.transpose() << ": bend cosine to the pole "
                << side << ", tip " << (kin.tip(1) - target).norm() << "\n";
      EXPECT_TRUE(s.reached) << method;
      EXPECT_LT((kin.tip(1) - target).norm(), 1e-4) << method;
      // gd creeps along the swivel (a narrow valley) and stops on target before it is done.
      EXPECT_GT(side, method == "gd" ? 0.5 : 0.99) << method << " pole " << pole.transpose();
    }
  }
}

struct Tally {
  int reached = 0, solves = 0;
  double largest_tip = 0;     // over the solves that reached
  double mean_deviation = 0;  // mean |angle - 0| over every angle of every solve, degrees
};

// Solves `cases` with `method`, the goal poses' poles if `poles`, and `options`.
Tally solve_all(Kinematics& kin, const std::string& method, const SolverOptions& options,
                const std::vector<test::TargetCase>& cases, bool poles, bool& limits_held) {
  auto solver = make_solver(method, kin, options);
  Tally t;
  limits_held = true;
  for (const auto& c : cases) {
    Goals goals = position_goals(c.target);
    if (poles) goals.poles = poles_of(kin, c.goal);
    bool held = false;
    const SolverSummary& s = stepped_solve(*solver, c.start, goals, held);
    limits_held = limits_held && held;
    ++t.solves;
    t.reached += s.reached;
    if (s.reached) t.largest_tip = std::max(t.largest_tip, s.tip_distance);
    t.mean_deviation += s.angles.cwiseAbs().mean();
  }
  t.mean_deviation /= std::max(1, t.solves);
  return t;
}

int max_iterations(const std::string& method) { return method == "gd" || method == "bfgs" ? 20000 : 500; }

// Every method, every rig, incremental targets: with poles (at the goal poses' bends) and a rest
// pull, as many solves reach their targets as without, and the limits hold at every iterate.
// (The first 3 of the 6 targets under the sanitizers.)
TEST(SoftGoals, EveryMethodStaysOnTargetWithThem) {
  for (const std::string& method : test::kMethods) {
    for (const test::TestRig& r : test::test_rigs()) {
      const std::string name = method + " " + r.label();
      Kinematics kin(r.rig);
      SolverOptions plain = test::report_options(r);
      plain.max_iterations = max_iterations(method);
      plain.restarts = 0;
      if (method == "gd") plain.gradient_tolerance *= 1e-3;
      SolverOptions soft = plain;
      soft.rest_weight = 0.02;
      soft.rest_from_start = true;
      const auto cases = test::incremental_targets(kin, test::sanitized_count(6, 3), 17);
      bool held_plain = false, held_soft = false;
      const Tally without = solve_all(kin, method, plain, cases, false, held_plain);
      const Tally with = solve_all(kin, method, soft, cases, true, held_soft);
      std::printf(
          "soft goals: %-7s %-18s reached %d of %d without, %d of %d with poles + rest pull "
          "(largest tip %.2g vs %.2g)\n",
          method.c_str(), r.label().c_str(), without.reached, without.solves, with.reached, with.solves,
          without.largest_tip, with.largest_tip);
      EXPECT_TRUE(held_soft) << name;
      EXPECT_GE(with.reached, without.reached) << name;
    }
  }
}

// The pole costs no tip accuracy on reachable targets: lm towards the incremental targets with
// tip_tolerance 1e-4 with and without poles, the tips' largest distance printed. (The first 5
// of the 10 targets under the sanitizers.)
TEST(SoftGoals, PolesCostNoTipAccuracyOnReachableTargets) {
  for (const test::TestRig& r : test::test_rigs()) {
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.tip_tolerance = 1e-4;
    const auto cases = test::incremental_targets(kin, test::sanitized_count(10, 5), 23);
    bool held = false;
    const Tally without = solve_all(kin, "lm", options, cases, false, held);
    const Tally with = solve_all(kin, "lm", options, cases, true, held);
    std::printf(
        "pole tip cost: lm %-18s reached %d / %d without, %d / %d with poles; largest tip distance %.3g vs %.3g\n",
        r.label().c_str(), without.reached, without.solves, with.reached, with.solves, without.largest_tip,
        with.largest_tip);
    EXPECT_GE(with.reached, without.reached) << r.label();
    EXPECT_LT(with.largest_tip, 1e-4) << r.label();
  }
}

// The rest pull on random targets from the rest pose: mean |angle - rest| with and without it,
// and the success counts, printed; it must lower the first at equal success.
void rest_pull_lowers_deviation(const test::TestRig& r) {
  Kinematics kin(r.rig);
  SolverOptions options = test::report_options(r);
  const auto cases = test::random_targets(kin, 30, 12);
  for (const char* method : {"lm", "gn"}) {
    bool held = false;
    const Tally without = solve_all(kin, method, options, cases, false, held);
    SolverOptions pulled = options;
    pulled.rest_weight = 0.05;
    const Tally with = solve_all(kin, method, pulled, cases, false, held);
    std::cout << "rest pull " << method << " " << r.label() << ": mean |angle - rest| " << without.mean_deviation
              << " deg without, " << with.mean_deviation << " deg with restWeight " << pulled.rest_weight
              << "; reached " << without.reached << " / " << without.solves << " without, " << with.reached << " / "
              << with.solves << " with\n";
    EXPECT_EQ(with.reached, without.reached) << method;
    EXPECT_LT(with.mean_deviation, without.mean_deviation) << method;
  }
}

TEST(SoftGoals, RestPullLowersTheDeviationOnTheProjectKnight) {
  for (const test::TestRig& r : test::test_rigs())
    if (!r.a7 && r.name == "knight") rest_pull_lowers_deviation(r);
}

using SoftGoalsA7 = test::NeedsA7;

TEST_F(SoftGoalsA7, RestPullLowersTheDeviationOnTheKnight) {
  for (const test::TestRig& r : test::test_rigs())
    if (r.a7 && r.name == "knight") rest_pull_lowers_deviation(r);
}

TEST(SoftGoals, AStiffBoneMovesLess) {
  Kinematics kin(test::straight_chain(4, {3}));
  const auto cases = test::random_targets(kin, 20, 8);
  SolverOptions options = tight_options();
  options.rest_weight = 0.1;
  auto solver = make_solver("lm", kin, options);
  double soft_turn = 0, stiff_turn = 0;
  int reached = 0;
  for (const auto& c : cases) {
    Goals goals = position_goals(c.target);
    goals.stiffness = {1, 1, 1, 1};
    const SolverSummary& s = solver->solve(c.start, goals);
    reached += s.reached;
    soft_turn += s.angles.head<3>().cwiseAbs().sum();
    goals.stiffness = {10, 1, 1, 1};
    const SolverSummary& t = solver->solve(c.start, goals);
    reached += t.reached;
    stiff_turn += t.angles.head<3>().cwiseAbs().sum();
  }
  std::cout << "stiffness: bone 0 turns " << soft_turn / cases.size()
            << " deg (sum of |angles|, mean) with stiffness 1, " << stiff_turn / cases.size() << " with 10; reached "
            << reached << " of " << 2 * cases.size() << "\n";
  EXPECT_EQ(reached, 2 * static_cast<int>(cases.size()));
  EXPECT_LT(stiff_turn, 0.8 * soft_turn);
}

// restWeight 0 (stiffness given or not, restFromStart either way) leaves plain goals on the
// original code path: the same iterates, bit for bit.
TEST(SoftGoals, RestWeightZeroChangesNothing) {
  for (const std::string& method : test::kMethods) {
    for (const test::TestRig& r : test::rigs_like("knight")) {
      Kinematics kin(r.rig);
      SolverOptions options = test::report_options(r);
      options.max_iterations = max_iterations(method);
      SolverOptions flagged = options;
      flagged.rest_from_start = true;
      auto solver = make_solver(method, kin, flagged), plain = make_solver(method, kin, options);
      for (const auto& c : test::incremental_targets(kin, 3, 7)) {
        Goals goals = position_goals(c.target);
        goals.stiffness.assign(kin.num_bones(), 2.0);
        const SolverSummary& with = solver->solve(c.start, goals);
        const SolverSummary& without = plain->solve(c.start, c.target);
        EXPECT_EQ(with.angles, without.angles) << method << " " << r.label();
        EXPECT_EQ(with.E, without.E) << method << " " << r.label();
        EXPECT_EQ(with.iterations, without.iterations) << method << " " << r.label();
      }
    }
  }
}

TEST(SoftGoals, PaperModeRefusesThem) {
  for (const test::TestRig& r : test::rigs_like("knight")) {
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.paper_mode = true;
    const auto c = test::incremental_targets(kin, 1, 5)[0];
    auto solver = make_solver("bfgs", kin, options);
    Goals goals = position_goals(c.target);
    EXPECT_NE(solver->start(c.start, goals), StopReason::invalid_input);
    goals.poles = {{kin.rig().effectors[0], Eigen::Vector3d(0, 1, 0), 1}};
    if (kin.rig().bones[goals.poles[0].bone].parent < 0) continue;
    EXPECT_EQ(solver->start(c.start, goals), StopReason::invalid_input);
    EXPECT_NE(solver->summary().message.find("paper mode"), std::string::npos) << solver->summary().message;
    goals.poles.clear();
    options.rest_weight = 0.1;
    solver->set_options(options);
    EXPECT_EQ(solver->start(c.start, goals), StopReason::invalid_input);
    EXPECT_NE(solver->summary().message.find("restWeight"), std::string::npos) << solver->summary().message;
    EXPECT_EQ(solver->start(c.start, c.target), StopReason::invalid_input);
  }
}

}  // namespace
}  // namespace ik
