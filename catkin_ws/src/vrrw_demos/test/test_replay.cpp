// `vrrw demos replay` against running controllers: a scripted pick-and-place (CSV -> bag) replayed whole,
// then one segment; the tool's JSON line carries the error against the de-jittered path. Progress through a
// pipe while the arm moves, bad input that sends nothing, --speed, Ctrl-C.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <actionlib_msgs/GoalStatusArray.h>
#include <atomic>
#include <control_msgs/FollowJointTrajectoryActionGoal.h>
#include <csignal>
#include <mutex>
#include <ros/ros.h>
#include <vrrw_demos/demo_csv.h>

#include "scripted_demo.h"
#include "tool_process.h"

using vrrw_demos_test::folder;
using vrrw_demos_test::run;
using vrrw_demos_test::ToolProcess;

namespace
{
std::string g_mode = "fake";

double field(const std::string& output, const std::string& key)
{
  const auto at = output.rfind("\"" + key + "\": ");
  return at == std::string::npos ? 1e9 : std::stod(output.substr(at + key.size() + 4));
}

std::string scriptedBag()
{
  const std::string csv = folder() + "/scripted.csv", bag = folder() + "/scripted.bag";
  if (::access(bag.c_str(), F_OK) == 0)
    return bag;
  vrrw_demos::exportCsv(vrrw_demos_test::scriptedPickPlace(250.0, 2e-4).demo.robots[0], csv);
  std::string output;
  EXPECT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + bag + " --robot ur5e", &output), 0) << output;
  return bag;
}
}  // namespace

TEST(Replay, WholeDemonstrationFollowsTheDejitteredPath)
{
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode, &output), 0) << output;
  std::cout << output;
  EXPECT_NE(output.find("\"result\": \"SUCCEEDED\""), std::string::npos) << output;
  EXPECT_LE(field(output, "dejitter_max"), 1e-3);
  EXPECT_GT(field(output, "samples"), 500);
  if (g_mode == "fake")
    EXPECT_LE(field(output, "max_error"), 1e-9) << output;
  else
    EXPECT_LE(field(output, "rms_error"), 2e-3) << output;
  // The imported bag has no gripper goals: the gripper's own close and open become two goals.
  std::size_t goals = 0;
  for (auto at = output.find("replay: gripper -> "); at != std::string::npos; at = output.find("replay: gripper -> ", at + 1))
    ++goals;
  EXPECT_EQ(goals, 2u) << output;
}

TEST(Replay, OneSegmentAndBadInput)
{
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --segment pick", &output), 0) << output;
  EXPECT_NE(output.find("\"result\": \"SUCCEEDED\""), std::string::npos) << output;
  EXPECT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --segment wave", &output), 2);
  EXPECT_NE(output.find("has no segment 'wave' (found: near_pick, pick, close_gripper, back_to_near_pick, final, "
                        "open_gripper)"),
            std::string::npos)
      << output;
  EXPECT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode real", &output), 2);
  EXPECT_NE(output.find("--mode real, but /ur5e/controller runs in mode '" + g_mode + "'"), std::string::npos) << output;
  const std::string csv = folder() + "/other.csv", bag = folder() + "/other.bag";
  auto other = vrrw_demos_test::scriptedPickPlace(50.0).demo.robots[0];
  for (auto& name : other.joint_names)
    name = "ur5e_x" + name.substr(4);  // the robot's prefix, but not its joints
  vrrw_demos::exportCsv(other, csv);
  ASSERT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + bag + " --robot ur5e", &output), 0) << output;
  EXPECT_EQ(run(VRRW_TOOL " replay " + bag + " --mode " + g_mode, &output), 2);
  EXPECT_NE(output.find("of the running scene has joints [ ur5e_shoulder_pan_joint"), std::string::npos) << output;
}

namespace
{
/// The arm controller's goals as its action topics show them.
class ArmGoals
{
public:
  explicit ArmGoals(ros::NodeHandle& nh)
  {
    status_ = nh.subscribe<actionlib_msgs::GoalStatusArray>(
        "/ur5e/arm_controller/follow_joint_trajectory/status", 10, [this](const actionlib_msgs::GoalStatusArrayConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex_);
          latest_ = *m;
        });
    goals_ = nh.subscribe<control_msgs::FollowJointTrajectoryActionGoal>(
        "/ur5e/arm_controller/follow_joint_trajectory/goal", 100,
        [this](const control_msgs::FollowJointTrajectoryActionGoalConstPtr&) { ++sent_; });
  }
  /// A goal is pending or active now (the status is published at the controller's rate).
  bool active()
  {
    ros::WallDuration(0.1).sleep();  // a status newer than what was read before
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& s : latest_.status_list)
      if (s.status == actionlib_msgs::GoalStatus::ACTIVE || s.status == actionlib_msgs::GoalStatus::PENDING)
        return true;
    return false;
  }
  int sent() const { return sent_; }

private:
  std::mutex mutex_;
  actionlib_msgs::GoalStatusArray latest_;  ///< PROTECTED BY mutex_
  std::atomic<int> sent_{ 0 };
  ros::Subscriber status_, goals_;  ///< last: destroyed first (their shutdown waits for a running callback)
};
}  // namespace

TEST(Replay, ProgressReachesAPipeWhileTheArmMoves)
{
  ros::NodeHandle nh;
  ArmGoals goals(nh);
  ToolProcess tool({ VRRW_TOOL, "replay", scriptedBag(), "--mode", g_mode });
  std::string text, progress;
  bool moving = false;
  while (tool.line(text))
    if (progress.empty() && text.find(" s left") != std::string::npos &&
        text.find("to the recorded start") == std::string::npos)  // the demonstration's, not the approach's
    {
      progress = text;
      moving = goals.active();
    }
  EXPECT_EQ(tool.wait(), 0);
  ASSERT_FALSE(progress.empty()) << "no progress line of the replay";
  EXPECT_TRUE(moving) << "the progress line came only after the motion: " << progress;
}

TEST(Replay, BadSpeedsAndTolerancesSendNothing)
{
  ros::NodeHandle nh;
  ArmGoals goals(nh);
  ros::WallDuration(0.5).sleep();
  const int before = goals.sent();
  std::string output;
  for (const char* speed : { "1e-300", "0", "-1", "11" })
  {
    EXPECT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --speed " + speed, &output), 2) << speed;
    EXPECT_EQ(output, std::string("vrrw demos replay: --speed: ") + speed + " outside [0.1, 10]\n");
  }
  for (const char* speed : { "inf", "nan" })
  {
    EXPECT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --speed " + speed, &output), 2) << speed;
    EXPECT_EQ(output, std::string("vrrw demos replay: --speed: '") + speed + "' is not a finite number\n");
  }
  EXPECT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --tolerance 1e9", &output), 2);
  EXPECT_EQ(output, "vrrw demos replay: --tolerance: 1e9 outside [0, 0.01] rad\n");
  ros::WallDuration(0.5).sleep();
  EXPECT_EQ(goals.sent(), before);  // not even the approach
}

TEST(Replay, SpeedChangesThePaceWhereTheLimitsAllow)
{
  // at 0.8 the scripted motions stay well within the UR5e's limits (wrist_1 peaks at 2.31 * 0.8^2 = 1.5 rad/s^2
  // of 3.14): exactly 10 / 0.8 s; at 2 they would not (9.2 rad/s^2): only those stretches slow, the rest keeps
  // the pace
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --speed 0.8", &output), 0) << output;
  EXPECT_NEAR(field(output, "recorded"), 10.0, 0.01) << output;
  EXPECT_NEAR(field(output, "duration"), 10.0 / 0.8, 0.001) << output;
  EXPECT_EQ(field(output, "stretches"), 0.0) << output;
  ASSERT_EQ(run(VRRW_TOOL " replay " + scriptedBag() + " --mode " + g_mode + " --speed 2", &output), 0) << output;
  EXPECT_GT(field(output, "duration"), 5.0) << output;
  EXPECT_LT(field(output, "duration"), 10.0) << output;
  EXPECT_GT(field(output, "stretches"), 0.0) << output;
  EXPECT_NE(output.find("stretches slowed into the limits"), std::string::npos) << output;
}

TEST(Replay, CtrlCCancelsTheRunningGoal)
{
  ros::NodeHandle nh;
  ArmGoals goals(nh);
  ToolProcess tool({ VRRW_TOOL, "replay", scriptedBag(), "--mode", g_mode, "--speed", "0.2" });
  std::string text, all;
  while (tool.line(text) && text.find("replay: near_pick") == std::string::npos)
    all += text;
  ASSERT_TRUE(goals.active()) << all;
  tool.signal(SIGINT);
  while (tool.line(text))
    all += text;
  EXPECT_EQ(tool.wait(), 1) << all;
  EXPECT_NE(all.find("replay: CANCELLED (cancelled by the user; the controller: PREEMPTED"), std::string::npos) << all;
  EXPECT_FALSE(goals.active()) << "the goal outlived the tool";
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_replay");
  ros::AsyncSpinner spinner(1);  // the goal status and goal counters
  spinner.start();
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "fake" || std::string(argv[i]) == "physics" || std::string(argv[i]) == "real")
      g_mode = argv[i];
  return RUN_ALL_TESTS();
}
