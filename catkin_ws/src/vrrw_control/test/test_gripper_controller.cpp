#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vrrw_control/fake_robot.h>
#include <vrrw_control/gripper_controller.h>

using namespace vrrw_control;

namespace
{
/// Fingers close on an object at `block`: the joint cannot pass it.
class BlockedGripper : public RobotHardware
{
public:
  BlockedGripper(double block) : RobotHardware({ "g_finger_joint" }), block_(block) {}
  void read(double, double) override {}
  void write(double, double) override { state_.positions[0] = std::min(command_.positions[0], block_); }

private:
  double block_;
};

GripperController::Cycle run(RobotHardware& hw, GripperController& g, double target, double& t)
{
  g.start(target, t);
  GripperController::Cycle c;
  for (; t < 20.0 && !c.done; t += 0.01)
  {
    hw.read(t, 0.01);
    c = g.update(t);
    hw.write(t, 0.01);
  }
  return c;
}
}  // namespace

TEST(GripperController, FakeReachesGoal)
{
  FakeRobot hw({ "g_finger_joint" });
  GripperController g(hw, "g_finger_joint", {});
  double t = 0.0;
  const auto c = run(hw, g, 0.6, t);
  EXPECT_TRUE(c.reached_goal);
  EXPECT_FALSE(c.stalled);
  EXPECT_NEAR(c.position, 0.6, 0.01);  // measured one cycle before the command reached 0.6
  EXPECT_EQ(hw.command().positions[0], 0.6);
  EXPECT_NEAR(t, 0.9, 0.03);  // 1.5 * 0.6 / 1.0 rad/s
}

TEST(GripperController, StallsOnAnObject)
{
  BlockedGripper hw(0.4);
  GripperController g(hw, "g_finger_joint", {});
  double t = 0.0;
  const auto c = run(hw, g, 0.8, t);
  EXPECT_TRUE(c.stalled);
  EXPECT_FALSE(c.reached_goal);
  EXPECT_NEAR(c.position, 0.4, 1e-9);
  EXPECT_LT(t, 1.2 + 0.2 + 0.05);
}

TEST(GripperController, RejectsOutOfRange)
{
  FakeRobot hw({ "g_finger_joint" });
  GripperController g(hw, "g_finger_joint", {});
  EXPECT_NE(g.check(0.9).find("outside limits"), std::string::npos);
  EXPECT_TRUE(g.check(0.5).empty());
}

TEST(GripperController, MaxEffortBecomesTheActuatedJointsDriveLimit)
{
  FakeRobot hw({ "g_finger_joint" });
  GripperOptions o;
  o.lever_arm = 0.0182;  // robotiq_2f_85.yaml
  o.max_grip_force = 235.0;
  GripperController g(hw, "g_finger_joint", o);
  EXPECT_TRUE(g.check(0.5, 100.0).empty());
  g.start(0.5, 0.0, 100.0);
  g.update(0.01);
  EXPECT_NEAR(hw.effortLimits()[0], 1.82, 1e-12);
  g.start(0.2, 1.0, 0.0);  // 0: the rated grip force (issue 22: the drive's own limit squeezed 625 N per pad)
  g.update(1.01);
  EXPECT_NEAR(hw.effortLimits()[0], 235.0 * 0.0182, 1e-12);
  o.max_grip_force = 0.0;  // no rating: 0 leaves the configured drive limit
  GripperController unrated(hw, "g_finger_joint", o);
  unrated.start(0.2, 2.0, 0.0);
  unrated.update(2.01);
  EXPECT_EQ(hw.effortLimits()[0], 0.0);
  EXPECT_EQ(g.check(0.5, 300.0), "max_effort 300 N exceeds the gripper's rated grip force 235 N");
  EXPECT_EQ(g.check(0.5, -1.0), "max_effort -1: must be a finite grip force >= 0 N (0: the default)");
  EXPECT_NE(g.check(0.5, std::nan("")).find("max_effort nan"), std::string::npos);
}
