#pragma once

namespace vrrw_dmp
{
/// \brief The exact discrete-time step of one joint's transformation system
///   tau dv/dt = K (g - x) - D v + c f(t),  tau dx/dt = v
/// over h seconds with f(t) linear between its values at the two ends (first-order hold):
///   (x - g, v)' = Phi (x - g, v) + (Gamma0 - Gamma1) c f0 + Gamma1 c f1.
/// Phi = exp(A h) in closed form (Putzer), Gamma0/Gamma1 from A^-1; no allocation, a few
/// transcendental calls, so it can be recomputed whenever a control loop's period changes.
class SpringDamperStep
{
public:
  /// \brief Prepares the step for spring K > 0, damping D >= 0, tau > 0 and duration h > 0.
  void prepare(double K, double D, double tau, double h);

  /// \brief Advances (x, v) with forcing values f0 (start) and f1 (end), each already multiplied by c.
  void apply(double goal, double f0, double f1, double& x, double& v) const
  {
    const double e = x - goal;
    const double e_next = phi_[0][0] * e + phi_[0][1] * v + hold0_[0] * f0 + hold1_[0] * f1;
    v = phi_[1][0] * e + phi_[1][1] * v + hold0_[1] * f0 + hold1_[1] * f1;
    x = goal + e_next;
  }

  double h() const { return h_; }
  double tau() const { return tau_; }

private:
  double h_ = 0.0;
  double tau_ = 0.0;
  double phi_[2][2] = { { 1.0, 0.0 }, { 0.0, 1.0 } };
  double hold0_[2] = { 0.0, 0.0 };  ///< Gamma0 - Gamma1
  double hold1_[2] = { 0.0, 0.0 };  ///< Gamma1
};
}  // namespace vrrw_dmp
