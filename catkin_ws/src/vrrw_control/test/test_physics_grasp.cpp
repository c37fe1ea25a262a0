// Node test (rostest, real master): physics mode, the controller inside vrrw_physics' physics_node
// (lockstep; the test steps simulated time). The gripper closes on a fixed block between its fingers and
// reports stalled; GripperCommand max_effort bounds the pad force measured by the physics node's contacts;
// opening reaches its goal.
#include <vrrw_common/ros/action_client.h>
#include <control_msgs/GripperCommandAction.h>
#include <gtest/gtest.h>
#include <mutex>
#include <ros/ros.h>
#include <vrrw_physics/Contacts.h>

#include "lockstep_client.h"

using GripperClient = vrrw_common::ActionClient<control_msgs::GripperCommandAction>;
using State = actionlib::SimpleClientGoalState;

namespace
{
/// Normal force of the block on the left and on the right finger links, from /physics/contacts.
class PadForces
{
public:
  explicit PadForces(ros::NodeHandle& nh) : sub_(nh.subscribe("/physics/contacts", 10, &PadForces::onContacts, this)) {}
  std::pair<double, double> latest()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return forces_;
  }
  /// Waits (wall clock, bounded) for the contacts of simulated time `stamp`.
  bool waitFor(const ros::Time& stamp)
  {
    for (int i = 0; i < 500; ++i, ros::WallDuration(0.01).sleep())
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stamp_ == stamp)
        return true;
    }
    return false;
  }

private:
  void onContacts(const vrrw_physics::Contacts& msg)
  {
    std::pair<double, double> forces{ 0.0, 0.0 };
    for (const auto& c : msg.contacts)
    {
      const std::string& link = c.body_a == "block" ? c.body_b : c.body_a;
      if (c.body_a != "block" && c.body_b != "block")
        continue;
      (link.rfind("ur5e_left_", 0) == 0 ? forces.first : forces.second) += c.normal_force;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    forces_ = forces;
    stamp_ = msg.header.stamp;
  }
  ros::Subscriber sub_;
  std::mutex mutex_;
  std::pair<double, double> forces_;
  ros::Time stamp_;
};

/// Sends a goal while the simulation waits and steps until the controller is idle.
control_msgs::GripperCommandResult command(vrrw_control_test::Lockstep& sim, GripperClient& gripper, double position,
                                           double max_effort)
{
  control_msgs::GripperCommandGoal g;
  g.command.position = position;
  g.command.max_effort = max_effort;
  gripper.sendGoal(g);
  EXPECT_TRUE(vrrw_control_test::waitAccepted(gripper));
  if (gripper.getState() == State::ACTIVE)
    sim.step(10.0, true);
  EXPECT_TRUE(gripper.waitForResult(ros::Duration(10.0)));  // on its way (wall clock)
  return *gripper.getResult();
}
}  // namespace

TEST(PhysicsGrasp, ClosingOnABlockStallsWithThePadForceOfMaxEffort)
{
  ros::NodeHandle nh;
  PadForces pads(nh);
  GripperClient gripper("/ur5e/gripper_controller/gripper_cmd");
  ASSERT_TRUE(gripper.waitForServer(ros::Duration(20.0)));
  vrrw_control_test::Lockstep sim;
  ASSERT_TRUE(sim.waitForPhysics());
  sim.step(0.5);
  for (const double force : { 20.0, 40.0 })
  {
    const auto closed = command(sim, gripper, 0.8, force);  // 0.8: fully closed without the block
    EXPECT_EQ(gripper.getState(), State::SUCCEEDED);
    EXPECT_TRUE(closed.stalled);
    EXPECT_FALSE(closed.reached_goal);
    EXPECT_GT(closed.position, 0.1);
    EXPECT_LT(closed.position, 0.7);
    const ros::Time settled = sim.step(0.5);  // the squeeze settles while the gripper holds the goal's limit
    ASSERT_TRUE(pads.waitFor(settled));
    const auto [left, right] = pads.latest();
    // the fixed block takes the difference of the two pads; a free object would feel their mean on both
    const double grip = 0.5 * (left + right);
    std::cout << "max_effort " << force << " N: stalled at " << closed.position << " rad, pad forces " << left
              << " N (left), " << right << " N (right), grip " << grip << " N" << std::endl;
    EXPECT_GT(std::min(left, right), 0.0) << "one pad short of the block";
    // lockstep: 18.72 N and 40.22 N measured with issue 22's joint rows after the contacts (6.4 %, 0.5 %; 20.48 N,
    // 41.10 N before): the 15 % target is within 3x of it
    EXPECT_NEAR(grip, force, 0.15 * force);
    command(sim, gripper, 0.1, 0.0);  // open again, away from the joint's stop at 0
    EXPECT_EQ(gripper.getState(), State::SUCCEEDED);
    EXPECT_TRUE(gripper.getResult()->reached_goal);
    EXPECT_FALSE(gripper.getResult()->stalled);
  }
  command(sim, gripper, 0.5, 300.0);
  EXPECT_EQ(gripper.getState(), State::REJECTED);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_grasp");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
