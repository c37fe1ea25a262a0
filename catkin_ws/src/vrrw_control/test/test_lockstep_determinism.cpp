// Node test (rostest, real master): two physics nodes of pick_place_drill, one at rtf max and one paced at
// real time (rtf 1), each with its controller inside in lockstep, get the same commands at the same simulated
// times (goals stamped while paused, the simulation stepped until the controllers are idle); every joint state
// they publish is bit-identical, and so is the number of action status messages (their heartbeat runs on the
// controllers' clock, simulated time, not on the wall clock that lets a paced run send 15 times as many).
#include <vrrw_common/ros/action_client.h>
#include <control_msgs/GripperCommandAction.h>
#include <actionlib_msgs/GoalStatusArray.h>
#include <gtest/gtest.h>
#include <atomic>
#include <set>

#include "lockstep_client.h"

using namespace vrrw_control_test;
using ArmClient = vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction>;
using GripperClient = vrrw_common::ActionClient<control_msgs::GripperCommandAction>;
using State = actionlib::SimpleClientGoalState;

namespace
{
/// One simulated cell under namespace `ns` and what it published.
struct Cell
{
  Cell(ros::NodeHandle& nh, const std::string& ns)
    : sim(ns + "/physics")
    , arm(ns + "/ur5e/arm_controller/follow_joint_trajectory")
    , gripper(ns + "/ur5e/gripper_controller/gripper_cmd")
    , states(nh, ns + "/ur5e/joint_states")
  {
    for (const char* action : { "/ur5e/arm_controller/follow_joint_trajectory", "/ur5e/gripper_controller/gripper_cmd" })
      status_subs.push_back(nh.subscribe<actionlib_msgs::GoalStatusArray>(
          ns + action + "/status", 1000, [this](const actionlib_msgs::GoalStatusArray::ConstPtr&) { ++statuses; }));
  }
  /// Status messages of both actions once they stopped coming (wall clock: those on their way arrive).
  int settledStatuses()
  {
    for (int last = -1; last != statuses;)
    {
      last = statuses;
      ros::WallDuration(0.3).sleep();
    }
    return statuses;
  }
  Lockstep sim;
  ArmClient arm;
  GripperClient gripper;
  JointStateLog states;
  std::vector<ros::Subscriber> status_subs;
  std::atomic<int> statuses{ 0 };
};

/// The script: three arm goals (stamped now, 0.2 s ahead, and a one-point goal timed by the controller), the
/// gripper closing and opening; each time stepped until every controller is idle.
void runScript(Cell& c)
{
  ASSERT_TRUE(c.sim.waitForPhysics());
  ASSERT_TRUE(c.arm.waitForServer(ros::Duration(30.0)) && c.gripper.waitForServer(ros::Duration(30.0)));
  sensor_msgs::JointState s;
  // the latched state where the simulation waits: the log is connected before the first step (on a loaded
  // machine the states of the first 0.5 s at rtf max were published before it was)
  ASSERT_TRUE(c.states.waitLatest(s, 10.0));
  ros::Time now = c.sim.step(0.5);
  ASSERT_TRUE(c.states.waitFor(now, s));
  const std::vector<double> q0(s.position.begin(), s.position.begin() + 6);
  const std::vector<std::vector<double>> deltas = { { 0.4, -0.2, 0.3, 0.1, 0.2, 0.5 }, { -0.2, 0.1, -0.1, 0.3, 0.0, -0.4 } };
  double ahead = 0.0;
  std::vector<double> from = q0;
  for (const auto& delta : deltas)
  {
    auto goal = move("ur5e_", from, delta, 1.2);
    goal.trajectory.header.stamp = now + ros::Duration(ahead);
    c.arm.sendGoal(goal);
    ASSERT_TRUE(waitAccepted(c.arm));
    now = c.sim.step(10.0, true);
    ASSERT_TRUE(c.arm.waitForResult(ros::Duration(10.0)));
    EXPECT_EQ(c.arm.getState(), State::SUCCEEDED) << c.arm.getResult()->error_string;
    for (size_t j = 0; j < 6; ++j)
      from[j] += delta[j];
    ahead = 0.2;
  }
  control_msgs::FollowJointTrajectoryGoal home;
  home.trajectory.joint_names = armJoints("ur5e_");
  home.trajectory.points = { point(0.0, q0) };  // one point: the controller times it to the limits
  c.arm.sendGoal(home);
  ASSERT_TRUE(waitAccepted(c.arm));
  for (const double finger : { 0.6, 0.1 })
  {
    control_msgs::GripperCommandGoal g;
    g.command.position = finger;
    c.gripper.sendGoal(g);
    ASSERT_TRUE(waitAccepted(c.gripper));
    c.sim.step(10.0, true);
    ASSERT_TRUE(c.gripper.waitForResult(ros::Duration(10.0)));
  }
  c.sim.step(10.0, true);
  ASSERT_TRUE(c.states.waitFor(c.sim.step(0.5), s));  // the last states arrived
}
}  // namespace

TEST(LockstepDeterminism, TwoRunsAtDifferentRatesGiveBitIdenticalJointTrajectories)
{
  ros::NodeHandle nh;
  Cell fast(nh, "/fast"), paced(nh, "/paced");
  const ros::WallTime t0 = ros::WallTime::now();
  runScript(fast);
  const double fast_wall = (ros::WallTime::now() - t0).toSec();
  const int fast_statuses = fast.settledStatuses();
  runScript(paced);
  const int paced_statuses = paced.settledStatuses();
  const auto a = fast.states.since(ros::Time(0)), b = paced.states.since(ros::Time(0));
  ASSERT_FALSE(a.empty());
  std::cout << "rtf max: " << a.size() << " joint states, " << (a.back().header.stamp - a.front().header.stamp).toSec()
            << " simulated s in " << fast_wall << " s; rtf 1: " << b.size() << " joint states" << std::endl;
  for (const auto* run : { &a, &b })
  {
    std::set<ros::Time> other;
    for (const auto& m : (run == &a ? b : a))
      other.insert(m.header.stamp);
    for (const auto& m : *run)
      if (!other.count(m.header.stamp))
        std::cout << (run == &a ? "only at rtf max: " : "only at rtf 1: ") << m.header.stamp << std::endl;
  }
  ASSERT_EQ(a.size(), b.size());
  size_t differing = 0;
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k].header.stamp != b[k].header.stamp || a[k].position != b[k].position || a[k].velocity != b[k].velocity ||
        a[k].effort != b[k].effort)
      ++differing;
  std::cout << differing << " of " << a.size() << " joint states differ" << std::endl;
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(a.size(), 400u);
  // two actions, a heartbeat each per 0.2 s of simulated time, besides each goal's transitions
  const double simulated = (a.back().header.stamp - a.front().header.stamp).toSec();
  std::cout << "action status messages: " << fast_statuses << " at rtf max, " << paced_statuses << " at rtf 1 ("
            << simulated << " simulated s)" << std::endl;
  EXPECT_EQ(fast_statuses, paced_statuses);
  EXPECT_GE(fast_statuses, int(2 * simulated / 0.2));
  EXPECT_LE(fast_statuses, int(2 * simulated / 0.2) + 30);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_lockstep_determinism");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
