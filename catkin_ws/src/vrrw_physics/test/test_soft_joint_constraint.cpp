#include <vrrw_physics/physics_world.h>
#include <vrrw_physics/soft_joint_constraint.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "pendulum_fixture.h"

using namespace vrrw_physics;

namespace
{
const double kInertia = 0.51;  // about the hinge axis, see test/data/pendulum.urdf

vrrw_scene::Scene pendulumScene()
{
  vrrw_scene::Scene scene;
  scene.name = "pendulum";
  scene.urdf = vrrw_physics_test::pendulumUrdf();
  vrrw_scene::Robot p;
  p.name = "p";
  p.base_link = "p_base_link";
  p.arm_joints = { "p_hinge" };
  scene.robots.push_back(p);
  return scene;
}

/// Analytic response of I q'' + D q' + K q = K q_step from rest at 0.
double analytic(double t, double k, double d, double step)
{
  const double wn = std::sqrt(k / kInertia);
  const double zeta = d / (2.0 * std::sqrt(k * kInertia));
  if (zeta < 1.0)
  {
    const double wd = wn * std::sqrt(1.0 - zeta * zeta);
    return step * (1.0 - std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t)));
  }
  const double root = wn * std::sqrt(zeta * zeta - 1.0);
  const double s1 = -zeta * wn + root, s2 = -zeta * wn - root;
  return step * (1.0 + (s2 * std::exp(s1 * t) - s1 * std::exp(s2 * t)) / (s1 - s2));
}

struct Response
{
  double max_error = 0.0;
  double overshoot_sim = 0.0, overshoot_ref = 0.0;
  double settle_sim = 0.0, settle_ref = 0.0;
};

Response stepResponse(double k, double d, double step, double seconds, DriveScheme scheme)
{
  WorldOptions options;
  options.drive_scheme = scheme;
  PhysicsWorld world(pendulumScene(), options);
  world.setGains("p", { "p_hinge" }, { k }, { d }, {});
  world.setDriveTargets("p", { "p_hinge" }, { step }, {});
  Response r;
  const int n = int(std::lround(seconds / world.options().dt));
  for (int i = 0; i < n; ++i)
  {
    EXPECT_TRUE(world.step()) << world.lastError();
    const double t = world.time();
    const double q = world.jointStates("p").position[0];
    const double ref = analytic(t, k, d, step);
    r.max_error = std::max(r.max_error, std::abs(q - ref));
    r.overshoot_sim = std::max(r.overshoot_sim, q - step);
    r.overshoot_ref = std::max(r.overshoot_ref, ref - step);
    if (std::abs(q - step) > 0.02 * step)
      r.settle_sim = t;
    if (std::abs(ref - step) > 0.02 * step)
      r.settle_ref = t;
  }
  return r;
}
}  // namespace

TEST(ImplicitSpringDamper, ErpAndCfmFollowTheDerivation)
{
  const Softness s = implicitSpringDamper(0.001, 1e5, 8e4);
  EXPECT_NEAR(s.erp, 100.0 / 80100.0, 1e-15);
  EXPECT_NEAR(s.cfm, 1.0 / (0.001 * 80100.0), 1e-12);
  const Softness spring_only = implicitSpringDamper(0.001, 100.0, 0.0);
  EXPECT_DOUBLE_EQ(spring_only.erp, 1.0);
  EXPECT_NEAR(spring_only.cfm, 1.0 / (0.001 * 0.1), 1e-9);
}

class DriveStep : public testing::TestWithParam<DriveScheme>
{
};

TEST_P(DriveStep, UnderdampedStepMatchesSecondOrderResponse)
{
  const double step = 0.5;
  const double k = 100.0, d = 0.2 * 2.0 * std::sqrt(k * kInertia);  // zeta = 0.2
  const Response r = stepResponse(k, d, step, 3.0, GetParam());
  EXPECT_GT(r.overshoot_ref, 0.5 * step);
  // deterministic: 1.26 % of the step and overshoot 0.2575 vs 0.2633 rad measured (README: within 2 %)
  EXPECT_LT(r.max_error, 0.013 * step);
  EXPECT_NEAR(r.overshoot_sim, r.overshoot_ref, 0.007);
  // The 2 % settling time jumps by half a period when a peak grazes the band; implicit Euler's
  // numerical damping (h*wn^2/2 = 0.1/s against zeta*wn = 2.8/s) moves it by one peak here.
  EXPECT_NEAR(r.settle_sim, r.settle_ref, 0.15 * r.settle_ref);
  std::cout << "underdamped: max error " << r.max_error / step * 100 << " % of step, overshoot " << r.overshoot_sim
            << " vs " << r.overshoot_ref << ", settling " << r.settle_sim << " s vs " << r.settle_ref << " s\n";
}

TEST_P(DriveStep, RigidGainsStableAndMatchOverdampedResponse)
{
  const double step = 0.5;
  const Response r = stepResponse(1e5, 8e4, step, 4.0, GetParam());
  // deterministic: 0.023 % of the step and settling 3.131 s vs 3.129 s measured, both schemes (the README's
  // target is 2 %; these bounds catch a regression well below it)
  EXPECT_LT(r.max_error, 0.0003 * step);
  EXPECT_LT(r.overshoot_sim, 1e-6);
  EXPECT_NEAR(r.settle_sim, r.settle_ref, 0.002 * r.settle_ref);
  std::cout << "rigid: max error " << r.max_error / step * 100 << " % of step, settling " << r.settle_sim << " s vs "
            << r.settle_ref << " s\n";
}

TEST_P(DriveStep, ForceLimitCapsTheEffort)
{
  WorldOptions options;
  options.drive_scheme = GetParam();
  PhysicsWorld world(pendulumScene(), options);
  world.setGains("p", { "p_hinge" }, { 1e5 }, { 100.0 }, { 5.0 });
  world.setDriveTargets("p", { "p_hinge" }, { 1.0 }, {});
  for (int i = 0; i < 100; ++i)
    world.step();
  // Torque saturated at 5 Nm: q = 0.5 * (5 / I) * t^2 after 0.1 s.
  const double expected = 0.5 * 5.0 / kInertia * 0.01;
  EXPECT_NEAR(world.jointStates("p").position[0], expected, 0.02 * expected);
  EXPECT_NEAR(std::abs(world.jointStates("p").effort[0]), 5.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Schemes, DriveStep, testing::Values(DriveScheme::StablePd, DriveScheme::Constraint),
                         [](const testing::TestParamInfo<DriveScheme>& info) {
                           return info.param == DriveScheme::StablePd ? std::string("StablePd") : std::string("Constraint");
                         });
