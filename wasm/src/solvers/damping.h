// The Levenberg-Marquardt damping factor mu of lm's step and newton's shift, adapted by Nielsen's
// rule (H. B. Nielsen, "Damping parameter in Marquardt's method", 1999) from the gain ratio
//   rho = (E - E_trial) / predicted decrease of the method's model.
// A trial is accepted when E_trial is finite and lower, the model predicted a decrease and
// rho > kMinGain; then mu *= max(1/3, 1 - (2 rho - 1)^3) (at least kMinMu) and nu = 2. After a
// rejection mu *= nu (at most kMaxMu) and nu doubles (at most kMaxNu). The shift itself is
//   lambda = (mu * relative_error2 + floor) * scale,   relative_error2 = (|r| / reach)^2
// (options lm_initial_mu, lm_damping_floor; solver_options.def).
#pragma once

namespace ik {

class NielsenDamping {
 public:
  static constexpr double kMinGain = 1e-4;
  static constexpr double kMinMu = 1e-12;
  static constexpr double kMaxMu = 1e16;
  static constexpr double kMaxNu = 64;

  // A new run: mu = `initial_mu` (dimensionless), nu = 2.
  void reset(double initial_mu) {
    mu_ = initial_mu;
    nu_ = 2;
  }

  // lambda = (mu * relative_error2 + floor) * scale, in the units of `scale` (lm: the mean
  // diagonal of J J^T, rig units^2 per degree^2; newton: that of Hess E).
  double shift(double relative_error2, double floor, double scale) const {
    return (mu_ * relative_error2 + floor) * scale;
  }

  // Judges a trial step from E to `E_trial` (rig units^2) whose model predicted a decrease of
  // `predicted` (rig units^2), and updates mu and nu. Returns true if the step is accepted.
  bool accept(double E, double E_trial, double predicted);

  // The shifted matrix was not positive definite (newton): mu = 4 max(mu, 1e-6), at most kMaxMu.
  void grow_for_indefinite();

  double mu() const { return mu_; }
  double nu() const { return nu_; }

 private:
  double mu_ = 1, nu_ = 2;
};

}  // namespace ik
