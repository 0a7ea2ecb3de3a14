#include "priority.h"

#include <cmath>

#include "free_set.h"
#include "small_cholesky.h"

namespace ik {

// A position block's distance over the tip tolerance, an orientation block's angle over the
// orientation tolerance.
double block_share(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r, int b, const GoalTolerance& tol) {
  const GoalSet::Block& g = goals.block(b);
  const double size = r.segment<3>(3 * b).norm() / g.scale;  // rig units, or radians
  return g.orientation ? size / (kRadPerDeg * tol.orientation_deg) : size / tol.tip;
}

void Priority::resize(const GoalSet& goals, int angles) {
  const int m = goals.rows();
  given_up_.assign(goals.num_blocks(), 0);
  off_at_start_.assign(goals.num_blocks(), 0);
  given_up_count_ = 0;
  held_rows_ = goals.hard_rows();
  movable_.resize(angles);
  normal_.resize(m, m);
  system_.resize(m);
  held_normal_.resize(m, m);
  jd_.resize(m);
  y_.resize(m);
  held_y_.resize(m);
  gradient_.resize(angles);
  active_set_.resize(angles);
}

void Priority::note_start(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalTolerance& tol) {
  for (int b = 0; b < goals.num_blocks(); ++b)
    off_at_start_[b] = tol.tip > 0 && tol.orientation_deg > 0 && block_share(goals, r, b, tol) > 1;
}

bool Priority::effector_off_at_start(const GoalSet& goals, int e) const {
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (goals.block(b).effector == e && off_at_start_[b]) return true;
  return false;
}

void Priority::clear() {
  std::fill(given_up_.begin(), given_up_.end(), 0);
  given_up_count_ = suspended_count_ = 0;
}

void Priority::suspend() {
  suspended_count_ = given_up_count_;
  given_up_count_ = 0;
}

void Priority::resume() {
  given_up_count_ = suspended_count_;
  suspended_count_ = 0;
}

void Priority::give_up_yielding(const GoalSet& goals) {
  given_up_count_ = 0;
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    const bool turned = !g.orientation && b + 1 < goals.num_blocks() && goals.block(b + 1).effector == g.effector;
    given_up_[b] = g.yields && !turned;
    given_up_count_ += given_up_[b];
  }
}

bool Priority::give_up_next(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r,
                            const GoalTolerance& tol) {
  if (!(tol.tip > 0 && tol.orientation_deg > 0) || held_share(goals, r, tol) <= 1 ||
      given_up_count_ + 1 >= goals.num_blocks())
    return false;
  // In turn: asked anew (an effector off target at the start, wherever it is now), then beyond
  // its tolerance here; orientations before positions in each.
  int pick = -1;
  for (int pass = 0; pass < 4 && pick < 0; ++pass) {
    const bool orientation = pass % 2 == 0, asked_anew = pass < 2;
    double worst = asked_anew ? -1 : 1;
    for (int b = 0; b < goals.num_blocks(); ++b) {
      const bool anew = orientation ? effector_off_at_start(goals, goals.block(b).effector) : off_at_start_[b];
      if (given_up_[b] || goals.block(b).orientation != orientation || (asked_anew && !anew)) continue;
      const double share = block_share(goals, r, b, tol);
      if (share > worst) worst = share, pick = b;
    }
  }
  if (pick < 0) return false;
  given_up_[pick] = 1;
  ++given_up_count_;
  return true;
}

double Priority::held_share(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r,
                            const GoalTolerance& tol) const {
  double worst = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (!given_up_[b]) worst = std::max(worst, block_share(goals, r, b, tol));
  return worst;
}

double Priority::held_E(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r) const {
  double sum = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (!given_up_[b]) sum += r.segment<3>(3 * b).squaredNorm();
  return 0.5 * sum;
}

double Priority::given_up_E(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r) const {
  return 0.5 * r.squaredNorm() - held_E(goals, r);
}

bool Priority::position_given_up(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r,
                                 const GoalTolerance& tol) const {
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (given_up_[b] && !goals.block(b).orientation && block_share(goals, r, b, tol) > 1) return true;
  return false;
}

bool Priority::orientation_given_up(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r,
                                    const GoalTolerance& tol) const {
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (given_up_[b] && goals.block(b).orientation && block_share(goals, r, b, tol) > 1) return true;
  return false;
}

bool Priority::prepare(const Kinematics& kin, const Eigen::MatrixXd& J, const BlockPattern& pattern) {
  int count = 0;
  movable_.resize(kin.num_angles());  // within the capacity resize() gave
  for (int j = 0; j < kin.num_angles(); ++j)
    if (kin.lower()[j] < kin.upper()[j]) movable_[count++] = j;
  movable_.resize(count);
  normal_.setZero();
  for (int c = 0; c < count; ++c) pattern.accumulate(J, movable_[c], normal_);
  pattern.symmetrize(normal_);
  // The mean diagonal over the rows in use: soft rows the Solver dropped (all 0) do not count.
  int rows = 0;
  for (int i = 0; i < normal_.rows(); ++i) rows += normal_(i, i) > 0 || i < held_rows_;
  scale_ = rows > 0 ? normal_.trace() / rows : 0;
  return std::isfinite(scale_);
}

Priority::Status Priority::step(const Kinematics& kin, const Eigen::MatrixXd& J, const BlockPattern& pattern,
                                const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& r,
                                double lambda, double floor, const Deadline& deadline,
                                Eigen::Ref<Eigen::VectorXd> trial) {
  const int m = static_cast<int>(normal_.rows());
  system_.begin(normal_, r);
  for (int i = 0; i < m; ++i) system_.shift()[i] = held_row(i) ? kHeldDamping * lambda + floor : lambda;
  const auto solve_system = [&] { return system_.solve(); };
  const auto proposed = [&](int i) { return -pattern.weight(i) * pattern.dot(J, i, system_.y()); };
  const auto take_out = [&](int i, double d) { system_.take_out(pattern, J, i, d); };
  switch (active_set_.run(a, kin.lower(), kin.upper(), movable_, static_cast<int>(movable_.size()),
                          ActiveSet::Fix::past_limit, deadline, solve_system, proposed, take_out)) {
    case ActiveSet::Status::solve_failed: return Status::failed;
    case ActiveSet::Status::out_of_time: return Status::out_of_time;
    case ActiveSet::Status::done: break;
  }
  trial = a;
  jd_.setZero();
  for (int j : movable_) {
    const double d = active_set_.step()[j];
    if (d == 0) continue;
    trial[j] += d;
    pattern.add(J, j, d, jd_);
  }
  kin.project(trial);
  return Status::ok;
}

double Priority::predicted_decrease(const Eigen::Ref<const Eigen::VectorXd>& r, bool held) const {
  double sum = 0;
  for (int i = 0; i < r.size(); ++i)
    if (held_row(i) == held) sum -= r[i] * jd_[i] + 0.5 * jd_[i] * jd_[i];
  return sum;
}

double Priority::reduced_gradient_norm(const Kinematics& kin, const Eigen::MatrixXd& J, const BlockPattern& pattern,
                                       const Eigen::Ref<const Eigen::VectorXd>& a,
                                       const Eigen::Ref<const Eigen::VectorXd>& r) {
  const int m = static_cast<int>(normal_.rows());
  // The given-up rows' residual (held rows zeroed) and its gradient over the movable angles.
  y_ = r;
  for (int i = 0; i < m; ++i)
    if (held_row(i)) y_[i] = 0;
  gradient_.setZero();
  for (int j : movable_) gradient_[j] = pattern.dot(J, j, y_);
  // Less its part in the held rows' row space, in the steps' metric (W, BlockPattern::weight):
  // g - Jh^T (Jh W Jh^T)^-1 Jh W g.
  held_normal_ = normal_;
  for (int i = 0; i < m; ++i) {
    if (held_row(i)) {
      held_normal_(i, i) += 1e-12 * scale_ + 1e-300;
      continue;
    }
    held_normal_.row(i).setZero();
    held_normal_.col(i).setZero();
    held_normal_(i, i) = 1;
  }
  held_y_.setZero();
  for (int j : movable_) pattern.add(J, j, pattern.weight(j) * gradient_[j], held_y_);
  for (int i = 0; i < m; ++i)
    if (!held_row(i)) held_y_[i] = 0;
  if (small_cholesky(held_normal_, m)) {
    small_cholesky_solve(held_normal_, m, held_y_);  // 0 stays 0 on the rows not held
    for (int j : movable_) gradient_[j] -= pattern.dot(J, j, held_y_);
  }
  // An angle on a limit that the descent direction -g pushes outward cannot move.
  double sum = 0;
  for (int j : movable_) {
    const double g = gradient_[j];
    if (pushed_past_limit(a[j], kin.lower()[j], kin.upper()[j], -g)) continue;
    sum += g * g;
  }
  return std::sqrt(sum);
}

}  // namespace ik
