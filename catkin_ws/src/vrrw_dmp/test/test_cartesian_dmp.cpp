#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <yaml-cpp/yaml.h>

#include <vrrw_dmp/cartesian_dmp.h>
#include <vrrw_dmp/dmp_yaml.h>
#include <vrrw_dmp/quaternion_maps.h>

#include "demo_fixture.h"

using vrrw_dmp::angleBetween;
using vrrw_dmp::CartesianDmp;
using vrrw_dmp::CartesianPose;
using vrrw_dmp::CartesianRolloutRequest;
using vrrw_dmp::CartesianSample;
using vrrw_dmp::DmpParameters;
using vrrw_dmp_test::errorOf;

namespace
{
constexpr double kDeg = M_PI / 180.0;

/// A TCP reach of T seconds as a person's pick does it: 40 cm across and 20 cm down with a sideways bump,
/// turning 70 deg about z while tilting 25 deg about a swinging horizontal axis and back; starts and ends at
/// rest. Sampled at about `rate` Hz with +-30 % time jitter and `noise` m / rad of Gaussian noise.
std::vector<CartesianSample> reach(double T, double rate = 100.0, double noise = 0.0, unsigned seed = 5)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-0.3, 0.3);
  std::normal_distribution<double> gauss(0.0, noise > 0.0 ? noise : 1.0);
  const auto count = static_cast<std::size_t>(T * rate) + 1;
  std::vector<CartesianSample> path;
  for (std::size_t k = 0; k < count; ++k)
  {
    double u = static_cast<double>(k) / static_cast<double>(count - 1);
    if (k > 0 && k + 1 < count)
      u += uniform(random) / static_cast<double>(count - 1);
    const double m = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
    const double bump = std::pow(std::sin(M_PI * u), 2);
    CartesianSample sample;
    sample.time = u * T;
    sample.pose.position = Eigen::Vector3d(0.4, -0.1, 1.05) + m * Eigen::Vector3d(-0.4, 0.25, -0.2) +
                           bump * Eigen::Vector3d(0.0, 0.0, 0.06);
    const Eigen::Vector3d tilt_axis(std::cos(2.0 * u), std::sin(2.0 * u), 0.0);
    sample.pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(70.0 * kDeg * m, Eigen::Vector3d::UnitZ())) *
                              Eigen::Quaterniond(Eigen::AngleAxisd(25.0 * kDeg * bump, tilt_axis)) *
                              Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0);  // tool pointing down
    if (noise > 0.0)
    {
      sample.pose.position += Eigen::Vector3d(gauss(random), gauss(random), gauss(random));
      sample.pose.orientation = vrrw_dmp::quaternionExp(0.5 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random))) *
                                sample.pose.orientation;
    }
    path.push_back(sample);
  }
  return path;
}

double largestNormError(const std::vector<CartesianSample>& path)
{
  double worst = 0.0;
  for (const CartesianSample& sample : path)
    worst = std::max(worst, std::abs(sample.pose.orientation.coeffs().norm() - 1.0));
  return worst;
}

CartesianPose moved(const CartesianPose& pose, const Eigen::Vector3d& offset, double yaw)
{
  return { pose.position + offset, Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())) * pose.orientation };
}
}  // namespace

TEST(CartesianDmp, ReproducesTheDemonstratedPath)
{
  const auto demo = reach(3.0, 100.0, 2e-5);
  const CartesianDmp dmp = CartesianDmp::learn(demo, DmpParameters{});
  const auto fit = vrrw_dmp::reproductionError(dmp, demo);
  RecordProperty("position_rmse_mm", std::to_string(fit.position_rmse * 1e3));
  RecordProperty("angle_rmse_deg", std::to_string(fit.angle_rmse / kDeg));
  // the targets are 2 mm / 1 deg; with 20 um / 20 urad of noise measured 0.35 mm / 0.064 deg
  EXPECT_LT(fit.position_rmse, 1e-3);
  EXPECT_LT(fit.angle_rmse, 0.2 * kDeg);
  EXPECT_LT(largestNormError(dmp.rollout({})), 1e-12);
}

TEST(CartesianDmp, ReachesANewGoalWithUnitQuaternionsThroughout)
{
  const auto demo = reach(3.0);
  const CartesianDmp dmp = CartesianDmp::learn(demo, DmpParameters{});
  CartesianRolloutRequest request;
  request.dt = 0.008;
  request.start = moved(dmp.demoStart(), Eigen::Vector3d(0.05, 0.02, -0.03), 0.3);
  request.goal = moved(dmp.demoGoal(), Eigen::Vector3d(-0.08, 0.1, 0.02), -0.5);
  const auto rollout = dmp.rollout(request);
  EXPECT_LT((rollout.front().pose.position - request.start->position).norm(), 1e-15);
  const CartesianSample& end = rollout.back();
  const double position_error = (end.pose.position - request.goal->position).norm();
  const double angle_error = angleBetween(end.pose.orientation, request.goal->orientation);
  RecordProperty("goal_error_mm", std::to_string(position_error * 1e3));
  RecordProperty("goal_error_deg", std::to_string(angle_error / kDeg));
  EXPECT_LE(position_error, 5e-4);
  EXPECT_LE(angle_error, 0.1 * kDeg);
  EXPECT_LT(largestNormError(rollout), 1e-9);
  // ends soon after tau: within the tolerances, no creeping (measured 1.19 tau)
  EXPECT_GE(end.time, dmp.demoDuration());
  EXPECT_LE(end.time, 1.25 * dmp.demoDuration());
}

TEST(CartesianDmp, ASlowDemonstrationEndsSoonAfterItsDuration)
{
  // 23 s at a person's pace (the joint DMP of such a segment crept on for 41 s before the rule changed)
  const auto demo = reach(23.0, 60.0, 2e-5);
  const CartesianDmp dmp = CartesianDmp::learn(demo, DmpParameters{});
  CartesianRolloutRequest request;
  request.goal = moved(dmp.demoGoal(), Eigen::Vector3d(0.1, -0.05, 0.0), 0.4);
  const auto rollout = dmp.rollout(request);
  RecordProperty("duration_s", std::to_string(rollout.back().time));
  EXPECT_LE(rollout.back().time, 23.0 * 1.25);  // measured 1.19 tau
  EXPECT_LE((rollout.back().pose.position - request.goal->position).norm(), 5e-4);
  EXPECT_LE(angleBetween(rollout.back().pose.orientation, request.goal->orientation), 0.1 * kDeg);
}

TEST(CartesianDmp, CoarseStepsFollowFineOnes)
{
  const CartesianDmp dmp = CartesianDmp::learn(reach(3.0), DmpParameters{});
  CartesianRolloutRequest fine, coarse;
  fine.dt = 0.001;
  coarse.dt = 0.04;
  const auto a = dmp.rollout(fine);
  const auto b = dmp.rollout(coarse);
  for (std::size_t k = 0; k < b.size() && 40 * k < a.size(); ++k)
  {
    EXPECT_NEAR((a[40 * k].pose.position - b[k].pose.position).norm(), 0.0, 1e-5);
    EXPECT_NEAR(angleBetween(a[40 * k].pose.orientation, b[k].pose.orientation), 0.0, 1e-4);
  }
}

TEST(CartesianDmp, DoublingTauKeepsThePath)
{
  const CartesianDmp dmp = CartesianDmp::learn(reach(3.0), DmpParameters{});
  CartesianRolloutRequest normal, slow;
  normal.dt = 0.004;
  slow.dt = 0.008;
  slow.tau = 2.0 * dmp.demoDuration();
  const auto a = dmp.rollout(normal);
  const auto b = dmp.rollout(slow);
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); k += 10)
  {
    EXPECT_NEAR((a[k].pose.position - b[k].pose.position).norm(), 0.0, 1e-9);
    EXPECT_NEAR(angleBetween(a[k].pose.orientation, b[k].pose.orientation), 0.0, 1e-6);
  }
}

TEST(CartesianDmp, AGoalGivenAsMinusQIsTheSameGoal)
{
  const CartesianDmp dmp = CartesianDmp::learn(reach(3.0), DmpParameters{});
  CartesianRolloutRequest plus, minus;
  plus.goal = moved(dmp.demoGoal(), Eigen::Vector3d::Zero(), 0.2);
  minus.goal = plus.goal;
  minus.goal->orientation.coeffs() = -minus.goal->orientation.coeffs();
  const auto a = dmp.rollout(plus);
  const auto b = dmp.rollout(minus);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
    EXPECT_LT(angleBetween(a[k].pose.orientation, b[k].pose.orientation), 1e-12);
}

TEST(CartesianDmp, BadDemonstrationsAreNamed)
{
  auto demo = reach(1.0);
  demo[7].pose.orientation.coeffs() *= 1.1;
  EXPECT_EQ(errorOf([&] { CartesianDmp::learn(demo, DmpParameters{}); }),
            "orientation demo: sample 7: norm 1.1 is not 1 (a unit quaternion is needed)");
  demo = reach(1.0);
  demo[4].time = demo[3].time;
  EXPECT_NE(errorOf([&] { CartesianDmp::learn(demo, DmpParameters{}); }).find("sample 4: time"), std::string::npos);
  demo = reach(1.0);
  demo[2].pose.position.x() = NAN;
  EXPECT_EQ(errorOf([&] { CartesianDmp::learn(demo, DmpParameters{}); }),
            "Cartesian demo: sample 2: position is not finite");
  const CartesianDmp dmp = CartesianDmp::learn(reach(1.0), DmpParameters{});
  CartesianRolloutRequest request;
  request.goal = dmp.demoGoal();
  request.goal->orientation.coeffs() *= 0.5;
  EXPECT_EQ(errorOf([&] { dmp.rollout(request); }),
            "orientation goal: norm 0.5 is not 1 (a unit quaternion is needed)");
  request = {};
  request.tau = 1e6;
  EXPECT_NE(errorOf([&] { dmp.rollout(request); }).find("more than the limit"), std::string::npos);
}

namespace
{
std::string cartesianYaml(const CartesianDmp& dmp)
{
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap << YAML::Key << "cartesian" << YAML::Value << YAML::BeginMap;
  vrrw_dmp::emitCartesianDmpFields(out, dmp);
  out << YAML::EndMap << YAML::EndMap;
  return out.c_str();
}

CartesianDmp parsed(const std::string& text)
{
  return vrrw_dmp::parseCartesianDmpFields(YAML::Load(text)["cartesian"], "skill.yaml", "cartesian.");
}
}  // namespace

TEST(CartesianDmp, YamlRoundTripIsExact)
{
  const CartesianDmp dmp = CartesianDmp::learn(reach(2.0, 100.0, 1e-4), DmpParameters{});
  const std::string text = cartesianYaml(dmp);
  const CartesianDmp loaded = parsed(text);
  EXPECT_EQ(cartesianYaml(loaded), text);
  CartesianRolloutRequest request;
  request.goal = moved(dmp.demoGoal(), Eigen::Vector3d(0.02, 0.0, 0.01), 0.2);
  const auto a = dmp.rollout(request);
  const auto b = loaded.rollout(request);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    EXPECT_EQ(a[k].pose.position, b[k].pose.position);
    EXPECT_EQ(a[k].pose.orientation.coeffs(), b[k].pose.orientation.coeffs());
  }
}

TEST(CartesianDmp, YamlWithANonUnitQuaternionIsNamed)
{
  const CartesianDmp dmp = CartesianDmp::learn(reach(2.0), DmpParameters{});
  YAML::Node root = YAML::Load(cartesianYaml(dmp));
  root["cartesian"]["orientation"]["goal"][3] = 0.5;
  YAML::Emitter out;
  out << root;
  const std::string error = errorOf([&] { parsed(out.c_str()); });
  EXPECT_EQ(error.rfind("skill.yaml: cartesian.orientation.goal: norm ", 0), 0u) << error;
  EXPECT_NE(error.find("is not 1"), std::string::npos) << error;
}
