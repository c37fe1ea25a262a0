#include <gtest/gtest.h>

#include <cmath>

#include <vrrw_dmp/spring_damper_step.h>

namespace
{
/// Reference: RK4 with 10000 substeps, forcing linear over the step.
void reference(double K, double D, double tau, double h, double goal, double f0, double f1, double& x, double& v)
{
  const int n = 10000;
  const double dt = h / n;
  auto f = [&](double t) { return f0 + (f1 - f0) * t / h; };
  auto acc = [&](double xx, double vv, double t) { return (K * (goal - xx) - D * vv + f(t)) / tau; };
  for (int i = 0; i < n; ++i)
  {
    const double t = i * dt;
    const double k1x = v / tau, k1v = acc(x, v, t);
    const double k2x = (v + 0.5 * dt * k1v) / tau, k2v = acc(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v, t + 0.5 * dt);
    const double k3x = (v + 0.5 * dt * k2v) / tau, k3v = acc(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v, t + 0.5 * dt);
    const double k4x = (v + dt * k3v) / tau, k4v = acc(x + dt * k3x, v + dt * k3v, t + dt);
    x += dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
}
}  // namespace

TEST(SpringDamperStep, MatchesFineIntegrationForEveryDampingRegime)
{
  struct Case
  {
    double K, D, tau, h;
  };
  for (const Case& c : { Case{ 156.25, 25.0, 2.0, 0.01 }, Case{ 156.25, 25.0, 2.0, 0.3 }, Case{ 100.0, 5.0, 1.0, 0.05 },
                         Case{ 100.0, 40.0, 0.5, 0.02 }, Case{ 156.25, 25.0, 3.0, 1e-4 } })
  {
    vrrw_dmp::SpringDamperStep step;
    step.prepare(c.K, c.D, c.tau, c.h);
    double x = 0.3, v = -0.7, xr = 0.3, vr = -0.7;
    step.apply(1.1, 40.0, -25.0, x, v);
    reference(c.K, c.D, c.tau, c.h, 1.1, 40.0, -25.0, xr, vr);
    EXPECT_NEAR(x, xr, 1e-9) << "K " << c.K << " D " << c.D << " h " << c.h;
    EXPECT_NEAR(v, vr, 1e-8) << "K " << c.K << " D " << c.D << " h " << c.h;
  }
}
