// Node test (rostest, real master): real mode relays a goal to a stand-in driver only after it ran in
// simulation and a confirmation arrived, byte-identical except for the documented prefix strip.
#include <algorithm>
#include <actionlib/client/simple_action_client.h>
#include <actionlib/server/action_server.h>
#include <gtest/gtest.h>
#include <std_srvs/Trigger.h>
#include <vrrw_common/ros/persistent_service.h>
#include "ros_test_helpers.h"

using namespace vrrw_control_test;
using Action = control_msgs::FollowJointTrajectoryAction;
using ArmClient = actionlib::SimpleActionClient<Action>;
using State = actionlib::SimpleClientGoalState;

namespace
{
/// Plays ur_robot_driver: publishes unprefixed joint_states, accepts a goal, reports one feedback,
/// ends `offset` rad short on shoulder_pan (a real arm that stopped elsewhere) and succeeds.
class StandInDriver
{
public:
  explicit StandInDriver(ros::NodeHandle& nh)
    : server_(nh, "/stand_in/scaled_pos_joint_traj_controller/follow_joint_trajectory",
              [this](actionlib::ServerGoalHandle<Action> gh) { onGoal(gh); }, false)
    , states_(nh.advertise<sensor_msgs::JointState>("/stand_in/joint_states", 10))
    , timer_(nh.createWallTimer(ros::WallDuration(0.02), [this](const ros::WallTimerEvent&) { publish(); }))
  {
    pose_.name = { "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                   "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint" };
    pose_.position.assign(6, 0.0);
    server_.start();
  }
  static constexpr double offset = 0.05;
  std::vector<double> pose() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return pose_.position;
  }
  std::vector<control_msgs::FollowJointTrajectoryGoal> received() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return goals_;
  }

private:
  void onGoal(actionlib::ServerGoalHandle<Action> gh)
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      goals_.push_back(*gh.getGoal());
      const auto& g = *gh.getGoal();
      for (size_t k = 0; k < g.trajectory.joint_names.size(); ++k)
        for (size_t j = 0; j < 6; ++j)
          if (pose_.name[j] == g.trajectory.joint_names[k])
            pose_.position[j] = g.trajectory.points.back().positions[k] - (j == 0 ? offset : 0.0);
    }
    gh.setAccepted();
    control_msgs::FollowJointTrajectoryFeedback f;
    f.joint_names = gh.getGoal()->trajectory.joint_names;
    gh.publishFeedback(f);
    control_msgs::FollowJointTrajectoryResult r;
    r.error_string = "stand-in executed";
    gh.setSucceeded(r);
  }
  void publish()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pose_.header.stamp = ros::Time::now();
    states_.publish(pose_);
  }
  mutable std::mutex mutex_;
  std::vector<control_msgs::FollowJointTrajectoryGoal> goals_;
  sensor_msgs::JointState pose_;
  actionlib::ActionServer<Action> server_;
  ros::Publisher states_;
  ros::WallTimer timer_;
};

StandInDriver* driver = nullptr;
ArmClient* arm = nullptr;
JointStateLog* states = nullptr;

bool confirm(std::string& message)
{
  std_srvs::Trigger t;
  EXPECT_TRUE(vrrw_common::services().tryCall("/ur5e/arm_controller/confirm_real_execution", t));
  message = t.response.message;
  return t.response.success;
}

std::vector<uint8_t> bytes(const control_msgs::FollowJointTrajectoryGoal& g)
{
  const auto m = ros::serialization::serializeMessage(g);
  return std::vector<uint8_t>(m.message_start, m.message_start + m.num_bytes - 4);
}

/// The real arm's pose, once the controller publishes it: after a preview ends the controller takes a
/// few cycles to go back to the measured arm, and a goal built before then would start elsewhere.
std::vector<double> armNow()
{
  const std::vector<double> real = driver->pose();
  sensor_msgs::JointState s;
  for (int attempt = 0; attempt < 250; ++attempt)
  {
    EXPECT_TRUE(states->waitLatest(s));
    if (std::equal(real.begin(), real.end(), s.position.begin()))
      return real;
    ros::Duration(0.02).sleep();
  }
  ADD_FAILURE() << "the controller never published the real arm's pose";
  return real;
}
}  // namespace

TEST(RealMode, RelaysOnlyAfterSimulationAndConfirmationByteIdentical)
{
  // 3 s of simulated run: the first confirmation comes while it runs, however slow the machine
  const auto goal = move("ur5e_", armNow(), { 0.2, -0.1, 0.1, 0.0, 0.3, 0.0 }, 3.0);
  std::vector<std::string> feedback_names;
  arm->sendGoal(goal, ArmClient::SimpleDoneCallback(), ArmClient::SimpleActiveCallback(),
                [&](const control_msgs::FollowJointTrajectoryFeedbackConstPtr& f) { feedback_names = f->joint_names; });
  for (int i = 0; i < 500 && arm->getState() == State::PENDING; ++i)
    ros::WallDuration(0.002).sleep();
  std::string message;
  EXPECT_FALSE(confirm(message));
  EXPECT_NE(message.find("still running in simulation"), std::string::npos) << message;
  // asked again until the simulated run is over: until then every answer says it still runs and nothing is sent
  bool confirmed = false;
  for (int i = 0; i < 500 && !confirmed; ++i, ros::WallDuration(0.02).sleep())
  {
    EXPECT_EQ(driver->received().size(), 0u) << "sent without confirmation";
    EXPECT_EQ(arm->getState(), State::ACTIVE);
    confirmed = confirm(message);
    if (!confirmed)
    {
      ASSERT_NE(message.find("still running in simulation"), std::string::npos) << message;
    }
  }
  EXPECT_TRUE(confirmed) << message;
  ASSERT_TRUE(arm->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(arm->getState(), State::SUCCEEDED);
  EXPECT_EQ(arm->getResult()->error_string, "stand-in executed");
  const auto received = driver->received();
  ASSERT_EQ(received.size(), 1u);

  auto expected = goal;  // the validated goal with the documented change: names without "ur5e_"
  for (auto& n : expected.trajectory.joint_names)
    n = n.substr(5);
  EXPECT_EQ(received[0].trajectory.joint_names[0], "shoulder_pan_joint");
  EXPECT_EQ(bytes(received[0]), bytes(expected));
  ASSERT_EQ(feedback_names.size(), 6u);
  EXPECT_EQ(feedback_names[0], "ur5e_shoulder_pan_joint");  // driver feedback comes back prefixed

  ros::Duration(0.2).sleep();  // the virtual arm now shows where the real arm stopped
  const auto q = armNow();
  const double end = goal.trajectory.points.back().positions[0];
  EXPECT_NEAR(q[0], end - StandInDriver::offset, 1e-12);
  // so a goal planned from the simulated end, not from the real arm, fails the start tolerance
  auto from_sim_end = move("ur5e_", goal.trajectory.points.back().positions, { 0.1, 0, 0, 0, 0, 0 }, 0.5);
  arm->sendGoal(from_sim_end);
  ASSERT_TRUE(arm->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(arm->getState(), State::REJECTED);
  EXPECT_NE(arm->getResult()->error_string.find("joint ur5e_shoulder_pan_joint: starts 0.05"), std::string::npos)
      << arm->getResult()->error_string;
}

TEST(RealMode, GoalsAreCheckedAgainstTheRealArmNotThePreview)
{
  const size_t before = driver->received().size();
  const auto first = move("ur5e_", armNow(), { 0.3, 0, 0, 0, 0, 0 }, 0.3);
  arm->sendGoal(first);
  ros::Duration(0.8).sleep();
  ASSERT_EQ(arm->getState(), State::ACTIVE);  // previewed, awaiting confirmation; the real arm is still
  ArmClient second_client("/ur5e/arm_controller/follow_joint_trajectory", true);
  ASSERT_TRUE(second_client.waitForServer(ros::Duration(5.0)));
  second_client.sendGoal(move("ur5e_", first.trajectory.points.back().positions, { 0.1, 0, 0, 0, 0, 0 }, 0.3));
  ASSERT_TRUE(second_client.waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(second_client.getState(), State::REJECTED);
  EXPECT_NE(second_client.getResult()->error_string.find("starts 0.3"), std::string::npos)
      << second_client.getResult()->error_string;
  EXPECT_EQ(arm->getState(), State::ACTIVE);
  arm->cancelGoal();
  ASSERT_TRUE(arm->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(driver->received().size(), before);
}

TEST(RealMode, CancelBeforeConfirmationSendsNothing)
{
  const size_t before = driver->received().size();
  arm->sendGoal(move("ur5e_", armNow(), { -0.2, 0, 0, 0, 0, 0 }, 0.3));
  ros::Duration(0.8).sleep();
  EXPECT_EQ(arm->getState(), State::ACTIVE);
  arm->cancelGoal();
  ASSERT_TRUE(arm->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(arm->getState(), State::PREEMPTED);
  std::string message;
  EXPECT_FALSE(confirm(message));
  EXPECT_NE(message.find("no goal awaits confirmation"), std::string::npos) << message;
  ros::Duration(0.3).sleep();
  EXPECT_EQ(driver->received().size(), before);
}

TEST(RealMode, RejectedGoalNeverReachesTheDriver)
{
  const size_t before = driver->received().size();
  auto bad = move("ur5e_", armNow(), { 0, 0, 4.0, 0, 0, 0 }, 3.0);  // elbow beyond pi
  arm->sendGoal(bad);
  ASSERT_TRUE(arm->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(arm->getState(), State::REJECTED);
  std::string message;
  EXPECT_FALSE(confirm(message));
  EXPECT_EQ(driver->received().size(), before);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_real_mode");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  StandInDriver d(nh);
  ArmClient a("/ur5e/arm_controller/follow_joint_trajectory", false);
  JointStateLog s(nh, "/ur5e/joint_states");
  driver = &d;
  arm = &a;
  states = &s;
  if (!a.waitForServer(ros::Duration(15.0)) ||
      !ros::service::waitForService("/ur5e/arm_controller/confirm_real_execution", ros::Duration(15.0)))
    return 1;
  ros::Duration(0.5).sleep();  // the controller's relay client connects to the stand-in
  return RUN_ALL_TESTS();
}
