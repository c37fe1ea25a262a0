// Node test (rostest, real master, real nodes, fake controller, planning node): the hostile inputs of issue 21
// items 6-8. A plan too long is refused naming the limit (ghost and planning node alike); executions in flight
// leave the node listening and each says what became of its own goal; a hand in an unknown frame does not slow
// the services; a joint named twice and a target 1e300 m away get the right one-line answers.
#include <algorithm>
#include <atomic>
#include <future>
#include <geometry_msgs/PoseStamped.h>
#include <std_srvs/Trigger.h>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_msgs/GhostExecute.h>
#include <vrrw_msgs/GhostPlan.h>
#include <vrrw_msgs/GhostPreset.h>
#include <vrrw_msgs/GhostSetJoints.h>
#include <vrrw_msgs/GhostSetPose.h>
#include <vrrw_msgs/Plan.h>

#include "interaction_fixture.h"

using namespace vrrw_interaction_test;

namespace
{
ros::NodeHandle* nh = nullptr;

vrrw_msgs::GhostPreset preset(const std::string& name)
{
  vrrw_msgs::GhostPreset srv;
  srv.request.name = name;
  return call("/ur5e/ghost/preset", srv);
}

vrrw_msgs::GhostPlan plan(double scaling)
{
  vrrw_msgs::GhostPlan srv;
  srv.request.time_limit = 2.0;
  srv.request.max_velocity_scaling_factor = scaling;
  srv.request.max_acceleration_scaling_factor = scaling;
  return call("/ur5e/ghost/plan", srv);
}

double seconds(const std::function<void()>& f)
{
  const ros::WallTime start = ros::WallTime::now();
  f();
  return (ros::WallTime::now() - start).toSec();
}
}  // namespace

TEST(InteractionBadInput, APlanTooLongIsRefusedNamingTheLimit)
{
  ASSERT_TRUE(preset("square_left").response.success);
  // 1e-6 of the limits once asked for 47 M points and took the node's memory (issue 21 item 6)
  const auto ghost = plan(1e-6);
  EXPECT_FALSE(ghost.response.success);
  EXPECT_NE(ghost.response.message.find("a plan may last at most 600 s (60001 points)"), std::string::npos)
      << ghost.response.message;
  EXPECT_TRUE(ghost.response.trajectory.points.empty());
  vrrw_msgs::Plan direct;
  direct.request.goal_joints.name = { "ur5e_shoulder_pan_joint", "ur5e_shoulder_lift_joint", "ur5e_elbow_joint",
                                      "ur5e_wrist_1_joint", "ur5e_wrist_2_joint", "ur5e_wrist_3_joint" };
  direct.request.goal_joints.position = { 0.9, -1.2, 1.4, -1.8, -1.57, 0.3 };
  direct.request.max_velocity_scaling_factor = 1e-6;
  direct = call("/ur5e/plan", direct);
  EXPECT_NE(direct.response.message.find("a plan may last at most 600 s (60001 points)"), std::string::npos)
      << direct.response.message;
  EXPECT_TRUE(direct.response.trajectory.points.empty());
  std::cout << "ghost/plan: " << ghost.response.message << "\n/ur5e/plan: " << direct.response.message << "\n";
  const auto fine = plan(1.0);  // and the node is as it was
  EXPECT_TRUE(fine.response.success) << fine.response.message;
}

TEST(InteractionBadInput, ExecutionsInFlightLeaveTheNodeListeningAndEachHearsItsOwnEnd)
{
  Latest<sensor_msgs::JointState> ghost(*nh, "/ur5e/ghost/joint_states");
  std::vector<std::future<vrrw_msgs::GhostExecute>> slow;
  for (const std::string name : { "square_left", "square_right", "square_left", "square_right" })
  {
    ASSERT_TRUE(preset(name).response.success);
    const auto planned = plan(0.01);  // 10-20 s each
    ASSERT_TRUE(planned.response.success) << planned.response.message;
    ASSERT_GT(planned.response.trajectory.points.back().time_from_start.toSec(), 8.0);
    slow.push_back(std::async(std::launch::async, [] {  // as a separate client would, over its own connection
      vrrw_msgs::GhostExecute srv;
      vrrw_common::PersistentServices().tryCall("/ur5e/ghost/execute", srv);
      return srv;
    }));
    ros::WallDuration(0.3).sleep();
  }
  // four motions in flight (they took every spinner thread: issue 21 item 7): the node still answers at once,
  // publishes the reset ghost at once, and its keepalive a second later (the node still takes the live states)
  const double reset = seconds([] { EXPECT_TRUE(call<std_srvs::Trigger>("/ur5e/ghost/reset").response.success); });
  const ros::Time answered = ros::Time::now();  // the reset's state is stamped before its answer, the next after
  ASSERT_TRUE(eventually([&] { return ghost.last().header.stamp > answered; }));
  const auto sent = ghost.all();
  const double keepalive = (sent.back().header.stamp - sent[sent.size() - 2].header.stamp).toSec();
  std::cout << "reset answered in " << reset << " s with four executions in flight; the keepalive " << keepalive
            << " s after the reset's state\n";
  EXPECT_LT(reset, 5.0);  // (it waited for the first motion to end)
  EXPECT_GE(keepalive, 1.0 - 1e-6);  // at the first fake controller state (50 Hz) 1 s or more after
  EXPECT_LT(keepalive, 1.5);
  // the last word: a quick plan from where the arm is now; it preempts the fourth motion and succeeds
  ASSERT_TRUE(preset("home").response.success);
  ASSERT_TRUE(plan(1.0).response.success);
  const auto last = call<vrrw_msgs::GhostExecute>("/ur5e/ghost/execute");
  EXPECT_TRUE(last.response.success) << last.response.message;
  // each earlier execute says its own goal was preempted (ghost/execute said "executed": issue 21 item 8)
  for (auto& f : slow)
  {
    ASSERT_EQ(f.wait_for(std::chrono::seconds(10)), std::future_status::ready);
    const vrrw_msgs::GhostExecute answer = f.get();
    EXPECT_FALSE(answer.response.success);
    EXPECT_EQ(answer.response.message.rfind("execute: PREEMPTED", 0), 0u) << answer.response.message;
  }
}

TEST(InteractionBadInput, AHandInAnUnknownFrameDoesNotSlowTheServices)
{
  ros::Publisher lost = nh->advertise<geometry_msgs::PoseStamped>("/operator/lost/pose", 10);
  std::atomic<bool> stop{ false };
  std::thread stream([&] {
    geometry_msgs::PoseStamped pose;
    pose.header.frame_id = "nowhere";
    pose.pose.orientation.w = 1.0;
    for (ros::WallRate rate(100.0); !stop; rate.sleep())
      lost.publish(pose);
  });
  for (int i = 0; i < 300 && lost.getNumSubscribers() == 0; ++i)
    ros::WallDuration(0.01).sleep();  // the node finds hands once a second
  ASSERT_GT(lost.getNumSubscribers(), 0u);
  ros::WallDuration(0.5).sleep();
  std::vector<double> latencies;
  vrrw_msgs::GhostSetJoints srv;
  srv.request.position = { 0.0, -1.5708, 0.9, -1.5708, 0.0, 0.0 };
  call("/ur5e/ghost/set_joints", srv);  // (the link is opened before the clock starts)
  for (int i = 0; i < 20; ++i)
  {
    srv.request.position[2] = i % 2 ? 1.0 : 0.9;
    latencies.push_back(seconds([&] { EXPECT_TRUE(vrrw_common::services().tryCall("/ur5e/ghost/set_joints", srv) && srv.response.success); }));
  }
  stop = true;
  stream.join();
  std::sort(latencies.begin(), latencies.end());
  std::cout << "set_joints with a hand in an unknown frame at 100 Hz: median " << 1e3 * latencies[10] << " ms\n";
  // each pose waited 0.1 s for tf holding the world: every request waited behind one (median 103 ms measured)
  EXPECT_LT(latencies[10], 0.05);
}

TEST(InteractionBadInput, AJointNamedTwiceAndATargetFarAwayGetTheRightAnswer)
{
  vrrw_msgs::GhostSetJoints twice;
  twice.request.name = { "ur5e_elbow_joint", "ur5e_elbow_joint" };
  twice.request.position = { 0.5, 0.7 };
  twice = call("/ur5e/ghost/set_joints", twice);
  EXPECT_FALSE(twice.response.success);
  EXPECT_EQ(twice.response.message, "name: 'ur5e_elbow_joint' named twice");
  vrrw_msgs::Plan plan_twice;  // the planning node refuses the same
  plan_twice.request.goal_joints.name = twice.request.name;
  plan_twice.request.goal_joints.position = twice.request.position;
  plan_twice = call("/ur5e/plan", plan_twice);
  EXPECT_NE(plan_twice.response.message.find("named twice"), std::string::npos) << plan_twice.response.message;
  vrrw_msgs::GhostSetPose far;
  far.request.pose.header.frame_id = "world";
  far.request.pose.pose.position.x = 1e300;
  far.request.pose.pose.position.z = 1.0;
  far.request.pose.pose.orientation.x = 1.0;
  far = call("/ur5e/ghost/set_pose", far);
  EXPECT_FALSE(far.response.success);
  EXPECT_EQ(far.response.message.rfind("unreachable (residual 1e+300 m, ", 0), 0u) << far.response.message;
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_interaction_bad_input");
  ros::NodeHandle handle;
  nh = &handle;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
