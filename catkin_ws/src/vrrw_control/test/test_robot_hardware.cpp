// FakeRobot, PhysicsRobot and RealRobot: the read/write split.
#include <gtest/gtest.h>
#include <memory>
#include <vrrw_control/fake_robot.h>
#include <vrrw_control/physics_robot.h>
#include <vrrw_control/real_robot.h>

using namespace vrrw_control;

namespace
{
class StubLink : public DriveLink
{
public:
  bool latestState(const std::vector<std::string>&, JointSample& state, std::vector<double>& efforts) override
  {
    if (!measured)
      return false;
    state = *measured;
    efforts.assign(state.size(), 1.5);
    return true;
  }
  std::unique_ptr<JointSample> measured;
};

JointSample at(std::vector<double> q)
{
  JointSample s(q.size());
  s.positions = q;
  return s;
}
}  // namespace

TEST(RobotHardware, FakeStateEqualsCommand)
{
  FakeRobot r({ "a", "b" });
  EXPECT_EQ(r.index("b"), 1);
  EXPECT_EQ(r.index("c"), -1);
  r.command().positions = { 0.1, 0.2 };
  r.read(0.0, 0.01);
  r.write(0.0, 0.01);
  EXPECT_EQ(r.state().positions, (std::vector<double>{ 0.1, 0.2 }));
}

TEST(RobotHardware, PhysicsIsReadyOnceMeasuredAndFirstHoldsWhatItMeasures)
{
  PhysicsRobot r({ "a", "b" });
  r.read(0.0, 0.001);
  EXPECT_FALSE(r.ready());
  EXPECT_EQ(r.fault(), "no state measured by physics yet");
  r.measure({ 0.4, -0.3 }, { 0.1, 0.0 }, { 2.0, 1.5 });
  r.read(0.001, 0.001);
  EXPECT_TRUE(r.ready());
  EXPECT_EQ(r.state().velocities[0], 0.1);
  EXPECT_EQ(r.command().positions, (std::vector<double>{ 0.4, -0.3 }));  // holds where it is, at rest
  EXPECT_EQ(r.command().velocities, (std::vector<double>{ 0.0, 0.0 }));
  EXPECT_EQ(r.efforts()[1], 1.5);
  r.command().positions[0] = 0.5;
  r.effortLimits()[1] = 5.7;
  r.measure({ 0.41, -0.3 }, { 0.0, 0.0 }, { 0.0, 0.0 });
  r.read(0.002, 0.001);
  EXPECT_EQ(r.command().positions[0], 0.5);  // the command is the controller's from now on
  EXPECT_EQ(r.effortLimits()[1], 5.7);
}

TEST(RobotHardware, PhysicsHoldsTheMeasuredPoseAfterAJump)
{
  PhysicsRobot r({ "a" });
  r.measure({ 0.4 }, { 0.0 }, { 0.0 });
  r.read(0.0, 0.001);
  r.command().positions[0] = 0.9;
  r.holdMeasured();  // the simulation was reset
  r.measure({ -0.2 }, { 0.0 }, { 0.0 });
  r.read(0.001, 0.001);
  EXPECT_EQ(r.command().positions[0], -0.2);
}

TEST(RobotHardware, RealMeasuresAndNeverSends)
{
  StubLink link;
  RealRobot r({ "a" }, link);
  link.measured = std::make_unique<JointSample>(at({ 1.25 }));
  r.read(0.0, 0.01);
  r.command().positions[0] = 9.0;
  r.write(0.0, 0.01);
  EXPECT_TRUE(r.ready());
  EXPECT_EQ(r.state().positions[0], 1.25);
}
