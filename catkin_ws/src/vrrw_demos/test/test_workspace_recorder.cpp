// `./vrrw up SCENE` runs the demonstration recorder idle beside the workspace: /demos/start is there whenever
// the workspace is, and records its robot, the goals of short-lived tools included.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <sys/wait.h>
#include <unistd.h>

#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStatus.h>
#include <vrrw_msgs/DemoStop.h>

TEST(WorkspaceRecorder, UpStartsTheRecorderIdleAndItRecordsTheScenesRobot)
{
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const pid_t up = ::fork();
  if (up == 0)
  {
    ::setsid();
    ::dup2(ends[1], STDOUT_FILENO);
    ::close(ends[0]);
    ::execl(VRRW_SCRIPT, VRRW_SCRIPT, "up", "pick_place_drill", "--mode", "fake", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(ends[1]);
  FILE* out = ::fdopen(ends[0], "r");
  char line[8192];
  bool ready = false;
  while (!ready && std::fgets(line, sizeof(line), out))
    ready = std::string(line).rfind("ready: ", 0) == 0;
  ASSERT_TRUE(ready);

  ros::NodeHandle nh;
  std::mutex mutex;
  std::vector<vrrw_msgs::DemoStatus> statuses;
  ros::Subscriber status = nh.subscribe<vrrw_msgs::DemoStatus>("/demos/status", 10, [&](const vrrw_msgs::DemoStatusConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    statuses.push_back(*m);
  });
  ASSERT_TRUE(vrrw_common::PersistentServices::waitFor("/demos/start", 20.0));
  for (int k = 0; k < 100 && statuses.empty(); ++k)
    ros::Duration(0.05).sleep();
  {
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_FALSE(statuses.empty());
    EXPECT_FALSE(statuses.front().recording);  // idle
  }
  char folder[] = "/tmp/vrrw_workspace_recorder_XXXXXX";
  const std::string file = std::string(::mkdtemp(folder)) + "/up.bag";
  vrrw_msgs::DemoStart call;
  call.request.file = file;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/start", call));
  EXPECT_TRUE(call.response.success) << call.response.message;
  EXPECT_NE(std::find(call.response.topics.begin(), call.response.topics.end(), "/ur5e/joint_states"),
            call.response.topics.end());
  // recording until its status (once a second) counts more than 50 messages: a second of the fake controller's
  // joint_states at 100 Hz and tf on a quiet machine; 60 s only guards against a hang
  const auto written = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    return statuses.back().recording ? statuses.back().messages : 0u;
  };
  for (int k = 0; k < 600 && written() <= 50u; ++k)
    ros::WallDuration(0.1).sleep();
  // two tools, each a new node that sends one goal and ends: both goals in the bag (the first was lost when the
  // recorder took only topics somebody had published; the second when the tool sent before the recorder connected)
  EXPECT_EQ(std::system("rosrun vrrw_control vrrw_arm send ur5e --gripper 0.8 --effort 70 > /dev/null"), 0);
  EXPECT_EQ(std::system("rosrun vrrw_control vrrw_arm send ur5e --gripper 0 > /dev/null"), 0);
  vrrw_msgs::DemoStop stopped;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/stop", stopped));
  EXPECT_TRUE(stopped.response.success) << stopped.response.message;
  EXPECT_GT(stopped.response.messages, 50u);  // a second of the fake controller's joint_states at 100 Hz, and tf
  rosbag::Bag bag(file, rosbag::bagmode::Read);
  rosbag::View goals(bag, rosbag::TopicQuery("/ur5e/gripper_controller/gripper_cmd/goal"));
  EXPECT_EQ(goals.size(), 2u);

  ::kill(-up, SIGINT);
  int wstatus = 0;
  ::waitpid(up, &wstatus, 0);
  std::fclose(out);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_workspace_recorder");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
