// A pick-and-place in physics, demonstrated through the controllers while the recorder runs, then
// replayed from the reset scene with `vrrw demos replay --mode physics`: the joint error against the
// de-jittered path and where the block ends, against where the demonstration left it. Replayed twice, in
// lockstep at rtf max (the tool's default): both replays' joint states are bit-identical (issue 20).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>

#include <vrrw_common/ros/action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <Eigen/Geometry>
#include <ros/ros.h>
#include <vrrw_common/ros/persistent_service.h>
#include <ros/topic.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/run_program.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStop.h>

namespace
{
using ArmClient = vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction>;
using GripperClient = vrrw_common::ActionClient<control_msgs::GripperCommandAction>;

Eigen::Isometry3d toEigen(const geometry_msgs::Transform& t)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(t.translation.x, t.translation.y, t.translation.z);
  pose.linear() = Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).toRotationMatrix();
  return pose;
}

/// The block's latest pose from /tf (physics publishes world -> block).
class BlockPose
{
public:
  explicit BlockPose(ros::NodeHandle& nh) : sub_(nh.subscribe("/tf", 1000, &BlockPose::onTf, this)) {}
  Eigen::Isometry3d latest()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return pose_;
  }

private:
  void onTf(const tf2_msgs::TFMessage& msg)
  {
    for (const auto& t : msg.transforms)
      if (t.child_frame_id == "block")
      {
        std::lock_guard<std::mutex> lock(mutex_);
        pose_ = toEigen(t.transform);
      }
  }
  ros::Subscriber sub_;
  std::mutex mutex_;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
};

/// The arm's joint states as published, by stamp; since() gives those after the last time the simulation
/// was reset (its clock went back).
class JointStateLog
{
public:
  explicit JointStateLog(ros::NodeHandle& nh) : sub_(nh.subscribe("/ur5e/joint_states", 100000, &JointStateLog::onState, this))
  {
  }
  /// \brief The states since the last reset, and forgets them.
  std::map<ros::Time, std::vector<double>> takeSinceReset()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::map<ros::Time, std::vector<double>> taken;
    taken.swap(since_reset_);
    return taken;
  }

private:
  void onState(const sensor_msgs::JointState& msg)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!since_reset_.empty() && msg.header.stamp < since_reset_.rbegin()->first)
      since_reset_.clear();  // the clock went back: a reset
    std::vector<double> values = msg.position;
    values.insert(values.end(), msg.velocity.begin(), msg.velocity.end());
    values.insert(values.end(), msg.effort.begin(), msg.effort.end());
    since_reset_[msg.header.stamp] = values;
  }
  std::mutex mutex_;
  std::map<ros::Time, std::vector<double>> since_reset_;  ///< PROTECTED BY mutex_
  ros::Subscriber sub_;  ///< last: destroyed first
};

Eigen::Isometry3d lastBlockPoseIn(const std::string& path)
{
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("/tf")))
    if (const auto tf = m.instantiate<tf2_msgs::TFMessage>())
      for (const auto& t : tf->transforms)
        if (t.child_frame_id == "block")
          pose = toEigen(t.transform);
  return pose;
}

bool gripper(GripperClient& client, double position)
{
  control_msgs::GripperCommandGoal goal;
  goal.command.position = position;
  goal.command.max_effort = 40.0;
  client.sendGoal(goal);
  return client.waitForResult(ros::Duration(10.0));
}

/// Lift (shoulder), pan by -0.6 rad, lower: the block goes from one post to the other.
control_msgs::FollowJointTrajectoryGoal carry(const sensor_msgs::JointState& now, bool retreat)
{
  control_msgs::FollowJointTrajectoryGoal goal;
  const std::vector<std::string> names{ "ur5e_shoulder_pan_joint", "ur5e_shoulder_lift_joint", "ur5e_elbow_joint",
                                        "ur5e_wrist_1_joint",      "ur5e_wrist_2_joint",       "ur5e_wrist_3_joint" };
  const std::vector<double> q = vrrw_common::inRobotOrder(now.position, vrrw_common::jointMapping(now.name, names));
  goal.trajectory.joint_names = names;
  auto add = [&](double t, double pan, double lift) {
    trajectory_msgs::JointTrajectoryPoint p;
    p.positions = q;
    p.positions[0] += pan;
    p.positions[1] += lift;
    p.velocities.assign(6, 0.0);
    p.time_from_start = ros::Duration(t);
    goal.trajectory.points.push_back(p);
  };
  add(0.0, 0, 0);
  add(1.5, 0, -0.25);
  if (!retreat)
  {
    add(3.5, -0.6, -0.25);
    add(5.0, -0.6, 0.0);
  }
  return goal;
}

/// The demos tool with \a arguments; its standard output and error in \a output.
int runTool(const std::vector<std::string>& arguments, std::string& output)
{
  std::vector<std::string> argv{ VRRW_TOOL };
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  output.clear();
  return vrrw_common::runProgram(argv, { nullptr, &output, &output, false });
}

double field(const std::string& output, const std::string& key)
{
  const auto at = output.rfind("\"" + key + "\": ");
  return at == std::string::npos ? 1e9 : std::stod(output.substr(at + key.size() + 4));
}
}  // namespace

TEST(ReplayPhysics, PickAndPlaceEndsWhereTheDemonstrationLeftTheBlock)
{
  ros::NodeHandle nh;
  BlockPose block(nh);
  JointStateLog states(nh);
  ArmClient arm("/ur5e/arm_controller/follow_joint_trajectory");
  GripperClient hand("/ur5e/gripper_controller/gripper_cmd");
  ASSERT_TRUE(arm.waitForServer(ros::Duration(30.0)));
  ASSERT_TRUE(hand.waitForServer(ros::Duration(30.0)));
  ASSERT_TRUE(ros::service::waitForService("/demos/start", ros::Duration(30.0)));
  ros::Duration(1.0).sleep();
  const Eigen::Isometry3d start_pose = block.latest();

  char folder[] = "/tmp/vrrw_replay_physics_XXXXXX";
  const std::string bag = std::string(::mkdtemp(folder)) + "/carry.bag";
  vrrw_msgs::DemoStart start;
  start.request.file = bag;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/start", start) && start.response.success) << start.response.message;
  ros::Duration(0.5).sleep();
  ASSERT_TRUE(gripper(hand, 0.8));  // stalls on the block
  auto now = ros::topic::waitForMessage<sensor_msgs::JointState>("/ur5e/joint_states", ros::Duration(5.0));
  arm.sendGoal(carry(*now, false));
  ASSERT_TRUE(arm.waitForResult(ros::Duration(20.0)));
  ASSERT_TRUE(gripper(hand, 0.1));
  now = ros::topic::waitForMessage<sensor_msgs::JointState>("/ur5e/joint_states", ros::Duration(5.0));
  arm.sendGoal(carry(*now, true));
  ASSERT_TRUE(arm.waitForResult(ros::Duration(20.0)));
  ros::Duration(0.5).sleep();
  vrrw_msgs::DemoStop stop;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/stop", stop) && stop.response.success) << stop.response.message;

  const Eigen::Isometry3d demonstrated = lastBlockPoseIn(bag);
  const double carried = (demonstrated.translation() - start_pose.translation()).norm();
  std::cout << "demonstration: the block moved " << carried << " m\n";
  ASSERT_GT(carried, 0.2) << "the demonstration did not carry the block";

  std::string output;
  EXPECT_EQ(runTool({ "segment", bag }, output), 0) << output;
  std::cout << output;
  EXPECT_NE(output.find("close_gripper"), std::string::npos);
  std::map<ros::Time, std::vector<double>> replays[2];
  for (auto& replayed_states : replays)
  {
    ASSERT_EQ(runTool({ "replay", bag, "--mode", "physics" }, output), 0) << output;
    std::cout << output;
    EXPECT_LE(field(output, "rms_error"), 2e-3) << output;
    ros::Duration(1.0).sleep();
    const Eigen::Isometry3d replayed = block.latest();
    const double distance = (replayed.translation() - demonstrated.translation()).norm();
    const double angle = Eigen::AngleAxisd(replayed.linear() * demonstrated.linear().transpose()).angle();
    std::cout << "replayed block vs demonstrated: " << distance * 1e3 << " mm, " << angle * 180 / M_PI << " deg\n";
    EXPECT_LE(distance, 0.005);
    EXPECT_LE(angle, 3.0 * M_PI / 180);
    replayed_states = states.takeSinceReset();
  }
  // Determinism: the states both replays published at the same simulated instants are bit-identical, from
  // the reset to the end of the shorter log (after the replay the simulation runs on, paced)
  std::size_t common = 0, differing = 0;
  for (const auto& [stamp, values] : replays[0])
  {
    const auto other = replays[1].find(stamp);
    if (other == replays[1].end())
      continue;
    ++common;
    differing += other->second != values;
  }
  const double replay_seconds = field(output, "duration");
  std::cout << "two replays: " << replays[0].size() << " and " << replays[1].size() << " joint states since the reset, "
            << common << " at the same instants, " << differing << " differ\n";
  EXPECT_GT(common, static_cast<std::size_t>(0.9 * 500 * replay_seconds));  // published at 500 Hz
  EXPECT_EQ(differing, 0u);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_replay_physics");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
