#include <vrrw_skills/trial_poses.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace vrrw_skills;

TEST(TrialPoses, SeededDrawsRepeatAndCoverTheSpreadUpToItsRim)
{
  const PlanarPose around{ 0.15, 0.25, 0.1 };
  const TrialSpread spread;
  const auto a = sampleTrialPoses(around, spread, 200, 7);
  const auto b = sampleTrialPoses(around, spread, 200, 7);
  const auto c = sampleTrialPoses(around, spread, 200, 8);
  ASSERT_EQ(a.size(), 200u);
  double largest_x = 0, largest_yaw = 0;
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_EQ(a[i].x, b[i].x);
    EXPECT_EQ(a[i].yaw, b[i].yaw);
    differ += a[i].x != c[i].x;
    EXPECT_LE(std::abs(a[i].x - around.x), spread.x + 1e-12);
    EXPECT_LE(std::abs(a[i].y - around.y), spread.y + 1e-12);
    EXPECT_LE(std::abs(a[i].yaw - around.yaw), spread.yaw + 1e-12);
    largest_x = std::max(largest_x, std::abs(a[i].x - around.x));
    largest_yaw = std::max(largest_yaw, std::abs(a[i].yaw - around.yaw));
  }
  EXPECT_EQ(differ, 200);
  EXPECT_GT(largest_x, 0.95 * spread.x);  // the claimed +-10 cm and +-30 deg are exercised
  EXPECT_GT(largest_yaw, 0.95 * spread.yaw);
}

TEST(TrialPoses, PlaceOnTableKeepsHeightTiltAndSetsYaw)
{
  Eigen::Isometry3d reference = Eigen::Isometry3d::Identity();
  reference.translation() = Eigen::Vector3d(0.1, 0.2, 0.75);
  reference.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Isometry3d moved = placeOnTable(reference, { -0.2, 0.4, -0.5 });
  const PlanarPose planar = planarPose(moved);
  EXPECT_NEAR(planar.x, -0.2, 1e-12);
  EXPECT_NEAR(planar.y, 0.4, 1e-12);
  EXPECT_NEAR(planar.yaw, -0.5, 1e-12);
  EXPECT_NEAR(moved.translation().z(), 0.75, 1e-12);
  EXPECT_NEAR(moved.rotation().col(2).z(), 1.0, 1e-12);
}
