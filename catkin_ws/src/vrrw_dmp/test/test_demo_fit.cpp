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
  EXPECT_LT(rmse, 2.4e-3);  // measured 8.0e-4 rad (deterministic: no noise, uniform samples)
  EXPECT_TRUE(vrrw_dmp::fitAdvice(demo, parameters, rmse).empty());
}

TEST(DemoFit, TwoMotionsAreAdvisedAsSegmentsAndNoBasisCountFitsThem)
{
  const DemoSource demo = thereAndBack();
  DmpParameters parameters;
  parameters.basis_count = 5;
  const double rmse = vrrw_dmp::reproductionRmse(vrrw_dmp::Dmp::learn(demo.trajectory, parameters), demo.trajectory);
  std::cout << "there and back, N = 5: " << rmse << " rad\n";
  EXPECT_GT(rmse, 0.14);  // measured 0.42 rad: one DMP cannot go there and back to its own start
  EXPECT_LT(rmse, 1.26);
  const auto advice = vrrw_dmp::fitAdvice(demo, parameters, rmse);
  ASSERT_EQ(advice.size(), 2u);
  EXPECT_EQ(advice[0], "the demonstration holds 2 motions with rests between them (starting at 0, 3 s); a DMP is one "
                       "motion: learn one instruction at a time with --segment NAME (this bag has pick place)");
  EXPECT_EQ(advice[1], "no basis count up to 1000 reproduces it within 0.01 rad");
}

TEST(DemoFit, TooFewBasisFunctionsGetTheCountThatFits)
{
  const DemoSource demo = smoothReach();
  DmpParameters parameters;
  parameters.basis_count = 3;
  const double rmse = vrrw_dmp::reproductionRmse(vrrw_dmp::Dmp::learn(demo.trajectory, parameters), demo.trajectory);
  std::cout << "smooth reach, N = 3: " << rmse << " rad\n";
  EXPECT_GT(rmse, 0.038);  // measured 0.114 rad
  EXPECT_LT(rmse, 0.34);
  // doubling from 3: 6, 12, 24 (3.3e-3 rad) is the first within 0.01 rad
  EXPECT_EQ(vrrw_dmp::fitAdvice(demo, parameters, rmse),
            std::vector<std::string>{ "--basis 24 reproduces it within 0.00329 rad" });
}
