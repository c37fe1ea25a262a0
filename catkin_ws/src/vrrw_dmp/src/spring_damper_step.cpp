#include <vrrw_dmp/spring_damper_step.h>

#include <cmath>

namespace vrrw_dmp
{
void SpringDamperStep::prepare(double K, double D, double tau, double h)
{
  h_ = h;
  tau_ = tau;
  // A = [[0, a], [-k, -d]], input B = (0, a): dx/dt = v / tau, dv/dt = (-K e - D v + c f) / tau.
  const double a = 1.0 / tau;
  const double k = K / tau;
  const double d = D / tau;
  const double mu = -0.5 * d;
  const double nu2 = 0.25 * d * d - a * k;
  const double z = nu2 * h * h;
  double C;  // cosh(nu h)
  double S;  // sinh(nu h) / nu
  if (std::abs(z) < 1e-4)
  {
    C = 1.0 + z / 2.0 + z * z / 24.0 + z * z * z / 720.0;
    S = h * (1.0 + z / 6.0 + z * z / 120.0 + z * z * z / 5040.0);
  }
  else if (nu2 > 0.0)
  {
    const double nu = std::sqrt(nu2);
    C = std::cosh(nu * h);
    S = std::sinh(nu * h) / nu;
  }
  else
  {
    const double w = std::sqrt(-nu2);
    C = std::cos(w * h);
    S = std::sin(w * h) / w;
  }
  const double decay = std::exp(mu * h);
  phi_[0][0] = decay * (C - mu * S);
  phi_[0][1] = decay * S * a;
  phi_[1][0] = -decay * S * k;
  phi_[1][1] = decay * (C + (-d - mu) * S);

  // A^-1 = [[-d, -a], [k, 0]] / (a k)
  const double det = a * k;
  auto solve = [det, a, k, d](const double in[2], double out[2]) {
    out[0] = (-d * in[0] - a * in[1]) / det;
    out[1] = (k * in[0]) / det;
  };
  const double minus_identity_b[2] = { phi_[0][1] * a, (phi_[1][1] - 1.0) * a };  // (Phi - I) B
  double gamma0[2];
  solve(minus_identity_b, gamma0);
  const double phi_b[2] = { phi_[0][1] * a, phi_[1][1] * a };
  double inv_phi_b[2];
  solve(phi_b, inv_phi_b);
  double inv_gamma0[2];
  solve(gamma0, inv_gamma0);
  for (int i = 0; i < 2; ++i)
  {
    const double gamma1 = gamma0[i] - inv_phi_b[i] + inv_gamma0[i] / h;
    hold1_[i] = gamma1;
    hold0_[i] = gamma0[i] - gamma1;
  }
}
}  // namespace vrrw_dmp
