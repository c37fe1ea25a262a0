// Requests whose output would not fit are refused up front, with the limit in the message.
#include <gtest/gtest.h>

#include <vrrw_dmp/dmp.h>
#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/dmp_yaml.h>

#include "demo_fixture.h"

using vrrw_dmp::Dmp;
using vrrw_dmp::DmpParameters;
using vrrw_dmp::RolloutRequest;
using vrrw_dmp_test::errorOf;

namespace
{
const Dmp& learned()
{
  static const Dmp dmp = Dmp::learn(vrrw_dmp_test::sample(vrrw_dmp_test::SmoothDemo{}, 200, 0.2), DmpParameters{});
  return dmp;
}
}  // namespace

TEST(DmpLimits, RolloutsBeyondTheSampleLimitAreRefused)
{
  RolloutRequest slow;
  slow.tau = 1e6;
  slow.dt = 0.008;
  EXPECT_EQ(errorOf([&] { learned().rollout(slow); }),
            "tau = 1e+06 s at dt = 0.008 s needs up to 5e+08 samples (4 tau / dt, settling included), more than "
            "the limit of 1000000: raise dt or shorten tau");
  RolloutRequest fine;
  fine.dt = 1e-7;
  EXPECT_NE(errorOf([&] { learned().rollout(fine); }).find("more than the limit of 1000000"), std::string::npos);
  RolloutRequest absurd;
  absurd.tau = 1e300;
  absurd.dt = 1e-300;
  EXPECT_NE(errorOf([&] { learned().rollout(absurd); }).find("needs up to inf samples"), std::string::npos);
}

TEST(DmpLimits, RolloutAtTheSampleLimitRuns)
{
  // 249999 steps of dt: 4 * 249999 + 1 = 999997 samples at the most, just inside the limit
  RolloutRequest edge;
  edge.dt = 1e-5;
  edge.tau = 249999 * edge.dt;
  const auto trajectory = learned().rollout(edge);
  EXPECT_GE(trajectory.points.size(), 250000u);
  EXPECT_LE(trajectory.points.size(), Dmp::kMaxRolloutSamples);
  edge.tau = 250000 * edge.dt;
  EXPECT_NE(errorOf([&] { learned().rollout(edge); }).find("needs up to 1e+06 samples"), std::string::npos);
}

TEST(DmpLimits, BasisCountAboveTheLimitIsRefusedByLearnAndByTheModelLoader)
{
  DmpParameters parameters;
  parameters.basis_count = 1000000000;
  const auto demo = vrrw_dmp_test::sample(vrrw_dmp_test::SmoothDemo{}, 20, 0.0);
  EXPECT_EQ(errorOf([&] { Dmp::learn(demo, parameters); }), "basis count N = 1000000000: more than the limit of 10000");
  parameters.basis_count = DmpParameters::kMaxBasisCount;
  EXPECT_EQ(Dmp::learn(demo, parameters).basis().size(), DmpParameters::kMaxBasisCount);

  std::string text = vrrw_dmp::toYaml(learned());
  const std::string field = "basis_count: 50";
  ASSERT_NE(text.find(field), std::string::npos);
  text.replace(text.find(field), field.size(), "basis_count: 20000");
  EXPECT_EQ(errorOf([&] { vrrw_dmp::fromYaml(text, "model.yaml"); }),
            "model.yaml: parameters.basis_count: 20000 must be > 0 and at most the limit of 10000");
}
