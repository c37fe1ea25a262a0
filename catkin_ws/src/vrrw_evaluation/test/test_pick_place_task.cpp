#include <vrrw_evaluation/pick_place_task.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace vrrw_evaluation;

TEST(PickPlaceTask, GraspPoseFollowsTheDrillAndPointsDown)
{
  GraspGeometry grasp;
  Eigen::Isometry3d drill = Eigen::Isometry3d::Identity();
  drill.translation() = Eigen::Vector3d(0.15, 0.25, 0.75);
  drill.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Isometry3d tcp = tcpAtGrasp(drill, grasp);
  EXPECT_NEAR((tcp.translation() - drill * grasp.grasp_point).norm(), 0.0, 1e-12);
  EXPECT_NEAR(tcp.rotation().col(2).z(), -1.0, 1e-12);
  EXPECT_NEAR(tcp.rotation().col(1).dot(drill.rotation().col(1)), 1.0, 1e-12);
  EXPECT_NEAR(tcpAtNearPick(drill, grasp).translation().z() - tcp.translation().z(), grasp.approach, 1e-12);
  // Carried by the TCP, the drill keeps its pose relative to it.
  Eigen::Isometry3d moved = tcp;
  moved.translation() += Eigen::Vector3d(0.1, -0.2, 0.3);
  const Eigen::Isometry3d held = drillInHand(moved, drill, tcp);
  EXPECT_NEAR((held.translation() - drill.translation() - Eigen::Vector3d(0.1, -0.2, 0.3)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(minimumJerk(0.5), 0.5, 1e-12);
  EXPECT_NEAR((interpolatePose(tcp, moved, 0.25).translation() - tcp.translation()).norm(),
              0.25 * std::sqrt(0.01 + 0.04 + 0.09), 1e-12);
}
