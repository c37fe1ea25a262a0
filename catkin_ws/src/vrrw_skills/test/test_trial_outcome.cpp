#include <vrrw_skills/trial_outcome.h>

#include <gtest/gtest.h>

using namespace vrrw_skills;

namespace
{
Eigen::Isometry3d at(double x, double y, double yaw = 0.0)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, 0.75);
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

TrialObservation carried()
{
  TrialObservation seen;
  seen.object_start = at(0.2, 0.3);
  seen.object_end = at(0.05, 0.01, 0.1);
  seen.max_lift = 0.12;
  seen.gripper_open_at_end = true;
  return seen;
}
}  // namespace

TEST(TrialOutcome, SuccessNeedsLiftReleaseAndTheFinalAreaWithinThreeCentimetres)
{
  const Eigen::Isometry3d demo_end = at(0.05, 0.0);
  TrialOutcome ok = judgeTrial(carried(), demo_end);
  EXPECT_TRUE(ok.success) << ok.reason;
  EXPECT_NEAR(ok.final_error_m, 0.01, 1e-12);
  EXPECT_NEAR(ok.final_angle_deg, 0.1 * 180 / M_PI, 1e-9);

  TrialObservation far = carried();
  far.object_end = at(0.05, 0.031);
  EXPECT_FALSE(judgeTrial(far, demo_end).success);
  EXPECT_NE(judgeTrial(far, demo_end).reason.find("3.1 cm"), std::string::npos);

  TrialObservation dragged = carried();
  dragged.max_lift = 0.01;  // pushed along the table, never lifted
  EXPECT_EQ(judgeTrial(dragged, demo_end).reason.rfind("not lifted", 0), 0u);

  TrialObservation held = carried();
  held.gripper_open_at_end = false;
  EXPECT_EQ(judgeTrial(held, demo_end).reason, "not released");

  TrialObservation toppled = carried();
  toppled.object_end.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_EQ(judgeTrial(toppled, demo_end).reason, "toppled: tilted 90 deg at the end");

  TrialObservation hit = carried();
  hit.arm_contacts.insert("table|ur5e_wrist_3_link");
  EXPECT_EQ(judgeTrial(hit, demo_end).reason, "arm collision: table|ur5e_wrist_3_link");
}

TEST(TrialOutcome, FingersMayTouchTheOtherLinksMayNot)
{
  const std::set<std::string> obstacles = { "table", "drill" };
  EXPECT_FALSE(isArmCollision("drill", "ur5e_left_inner_finger_pad", "ur5e", obstacles));
  EXPECT_FALSE(isArmCollision("drill", "ur5e_right_outer_knuckle", "ur5e", obstacles));
  EXPECT_TRUE(isArmCollision("drill", "ur5e_robotiq_arg2f_base_link", "ur5e", obstacles));
  EXPECT_TRUE(isArmCollision("table", "ur5e_wrist_3_link", "ur5e", obstacles));
  EXPECT_FALSE(isArmCollision("drill", "table", "ur5e", obstacles));
  EXPECT_FALSE(isArmCollision("floor", "ur5e_wrist_3_link", "ur5e", obstacles));
  EXPECT_FALSE(isArmCollision("table", "ur5e2_wrist_3_link", "ur5e", obstacles));
}
