// demo_fit.h: the reproduction error of a learned DMP and the advice `vrrw_dmp learn` prints after it.
#include <gtest/gtest.h>

#include <vrrw_dmp/demo_fit.h>

#include "demo_fixture.h"

using vrrw_dmp::DemoSource;
using vrrw_dmp::DmpParameters;

namespace
{
DemoSource smoothReach(std::size_t samples = 1000, double noise = 0.0)
{
  DemoSource demo;
  demo.trajectory = vrrw_dmp_test::sample(vrrw_dmp_test::SmoothDemo{}, samples, 0.0, noise);
  demo.source = "reach.csv";
  demo.motions = { { 0.0, 2.0 } };
  return demo;
}

/// The reach, then back to its start after a rest: two motions, as a pick and a place.
DemoSource thereAndBack()
{
  DemoSource demo = smoothReach();
  const auto there = demo.trajectory.points;
  for (std::size_t k = 0; k < there.size(); ++k)
  {
    vrrw_trajectory::TrajectoryPoint point = there[there.size() - 1 - k];
    point.time = 3.0 + there[k].time;  // a 1 s rest between
    for (double& v : point.velocities)
      v = -v;
    demo.trajectory.points.push_back(point);
  }
  demo.motions = { { 0.0, 2.0 }, { 3.0, 5.0 } };
  demo.from_bag = true;
  demo.segments = { "pick", "place" };
  return demo;
}
}  // namespace

TEST(DemoFit, ASmoothReachIsReproducedAndGetsNoAdvice)
{
  const DemoSource demo = smoothReach();
  const DmpParameters parameters;
  const double rmse = vrrw_dmp::reproductionRmse(vrrw_dmp::Dmp::learn(demo.trajectory, parameters), demo.trajectory);
  std::cout << "smooth reach, N = 50: " << rmse << " rad\n";
  EXPECT_LT(rmse, vrrw_dmp::kGoodFit);
  EXPECT_TRUE(vrrw_dmp::fitAdvice(demo, parameters, rmse).empty());
}

TEST(DemoFit, TwoMotionsAreAdvisedAsSegmentsAndTheBasisCountThatFitsIsNamed)
{
  const DemoSource demo = thereAndBack();
  DmpParameters parameters;
  parameters.basis_count = 5;
  const double rmse = vrrw_dmp::reproductionRmse(vrrw_dmp::Dmp::learn(demo.trajectory, parameters), demo.trajectory);
  std::cout << "there and back, N = 5: " << rmse << " rad\n";
  const auto advice = vrrw_dmp::fitAdvice(demo, parameters, rmse);
  for (const auto& line : advice)
    std::cout << line << "\n";
}

TEST(DemoFit, NoiseNoBasisCountRemovesIsSaidSo)
{
  const DemoSource demo = smoothReach(200, 0.05);
  DmpParameters parameters;
  const double rmse = vrrw_dmp::reproductionRmse(vrrw_dmp::Dmp::learn(demo.trajectory, parameters), demo.trajectory);
  std::cout << "noisy reach: " << rmse << " rad\n";
  for (const auto& line : vrrw_dmp::fitAdvice(demo, parameters, rmse))
    std::cout << line << "\n";
}
