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
  void sendTargets(const std::vector<std::string>&, const JointSample& targets, double time) override
  {
    sent.push_back(targets);
    last_time = time;
  }
  bool latestState(const std::vector<std::string>&, JointSample& state, std::vector<double>& efforts) override
  {
    if (!measured)
      return false;
    state = *measured;
    efforts.assign(state.size(), 1.5);
    return true;
  }
  std::vector<JointSample> sent;
  std::unique_ptr<JointSample> measured;
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
