// FakeRobot, PhysicsRobot and RealRobot: the read/write split over a stub DriveLink.
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
  void sendTargets(const std::vector<std::string>&, const JointSample& targets, const std::vector<double>& limits,
                   double time) override
  {
    sent.push_back(targets);
    sent_limits.push_back(limits);
    last_time = time;
  }
  double stateAge() const override { return age; }
  bool latestState(const std::vector<std::string>&, JointSample& state, std::vector<double>& efforts) override
  {
    if (!measured)
      return false;
    state = *measured;
    efforts.assign(state.size(), 1.5);
    return true;
  }
  std::vector<JointSample> sent;
  std::vector<std::vector<double>> sent_limits;
  std::unique_ptr<JointSample> measured;
  double age = 0.0;
  double last_time = -1.0;
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

TEST(RobotHardware, PhysicsStreamsTargetsOnlyOnceMeasured)
{
  StubLink link;
  PhysicsRobot r({ "a", "b" }, link);
  r.read(0.0, 0.01);
  r.write(0.0, 0.01);
  EXPECT_FALSE(r.ready());
  EXPECT_TRUE(link.sent.empty());
  link.measured = std::make_unique<JointSample>(at({ 0.4, -0.3 }));
  r.read(0.01, 0.01);
  EXPECT_TRUE(r.ready());
  EXPECT_EQ(r.command().positions, (std::vector<double>{ 0.4, -0.3 }));  // holds where it is
  EXPECT_EQ(r.efforts()[1], 1.5);
  r.command().positions[0] = 0.5;
  r.write(0.01, 0.01);
  ASSERT_EQ(link.sent.size(), 1u);
  EXPECT_EQ(link.sent[0].positions[0], 0.5);
  EXPECT_EQ(link.last_time, 0.01);
}

TEST(RobotHardware, PhysicsIsNotReadyWhileItsStatesAreStaleAndHoldsTheirNewPoseAfter)
{
  StubLink link;
  PhysicsRobot r({ "a" }, link, 0.5);
  link.measured = std::make_unique<JointSample>(at({ 0.4 }));
  r.read(0.0, 0.01);
  ASSERT_TRUE(r.ready());
  EXPECT_EQ(r.fault(), "");
  r.command().positions[0] = 0.9;
  link.age = 0.75;  // the physics node stopped publishing
  r.read(0.01, 0.01);
  r.write(0.01, 0.01);
  EXPECT_FALSE(r.ready());
  EXPECT_EQ(r.fault(), "no joint_states for 0.75 s (state_timeout 0.5 s): is the physics node running?");
  EXPECT_TRUE(link.sent.empty());  // nothing is streamed on a state nobody measures
  link.age = 0.0;
  *link.measured = at({ -0.2 });  // restarted elsewhere
  r.read(0.02, 0.01);
  EXPECT_TRUE(r.ready());
  EXPECT_EQ(r.command().positions[0], -0.2);
}

TEST(RobotHardware, PhysicsSendsTheEffortLimitsOfTheCommand)
{
  StubLink link;
  PhysicsRobot r({ "a", "g" }, link);
  link.measured = std::make_unique<JointSample>(at({ 0.0, 0.3 }));
  r.read(0.0, 0.01);
  r.effortLimits()[1] = 5.7;
  r.write(0.0, 0.01);
  ASSERT_EQ(link.sent_limits.size(), 1u);
  EXPECT_EQ(link.sent_limits[0], (std::vector<double>{ 0.0, 5.7 }));
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
  EXPECT_TRUE(link.sent.empty());
}
