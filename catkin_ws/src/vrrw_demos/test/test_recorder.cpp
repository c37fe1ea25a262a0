// The recorder node end to end with a real master, rosbag files and the vrrw_demos tool.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <ros/ros.h>
#include <vrrw_common/ros/persistent_service.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_msgs/DemoAnnotate.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStop.h>

namespace
{
const std::vector<std::string> kRobots{ "r1", "r2", "r3", "r4" };

std::string folder()
{
  static const std::string path = [] {
    char name[] = "/tmp/vrrw_recorder_test_XXXXXX";
    return std::string(::mkdtemp(name));
  }();
  return path;
}

/// Starts recorder_node as a child; a file size limit (bytes) makes "disk full" without root.
pid_t startRecorder(rlim_t file_size_limit = RLIM_INFINITY)
{
  const pid_t pid = ::fork();
  if (pid == 0)
  {
    ::setpgid(0, 0);
    const rlimit limit{ file_size_limit, file_size_limit };
    ::setrlimit(RLIMIT_FSIZE, &limit);
    std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG, as on a full disk
    ::execl(VRRW_RECORDER_NODE, VRRW_RECORDER_NODE, "__name:=demo_recorder", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  EXPECT_TRUE(ros::service::waitForService("/demos/start", ros::Duration(20.0)));
  return pid;
}

void stopRecorder(pid_t pid, int signal = SIGINT)
{
  ::kill(pid, signal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  for (int k = 0; k < 50 && ros::service::exists("/demos/start", false); ++k)
    ros::Duration(0.1).sleep();
}

vrrw_msgs::DemoStart::Response start(const std::string& file)
{
  vrrw_msgs::DemoStart srv;
  srv.request.file = file;
  EXPECT_TRUE(vrrw_common::services().tryCall("/demos/start", srv));
  return srv.response;
}

struct Publishers
{
  std::vector<ros::Publisher> topics;
  explicit Publishers(ros::NodeHandle& nh)
  {
    for (const std::string& robot : kRobots)
      topics.push_back(nh.advertise<sensor_msgs::JointState>("/" + robot + "/joint_states", 20000));
  }
  /// Waits until the recorder subscribed every topic.
  bool connected() const
  {
    for (int k = 0; k < 100; ++k)
    {
      bool all = true;
      for (const auto& p : topics)
        all = all && p.getNumSubscribers() > 0;
      if (all)
        return true;
      ros::Duration(0.05).sleep();
    }
    return false;
  }
  /// count messages per robot at rate Hz; position[0] carries the sequence number.
  void publish(int count, double rate, int first = 0)
  {
    ros::WallRate loop(rate);
    for (int i = first; i < first + count; ++i)
    {
      for (std::size_t r = 0; r < topics.size(); ++r)
      {
        sensor_msgs::JointState state;
        state.header.stamp = ros::Time::now();
        for (const char* j : { "_a", "_b", "_c", "_d", "_e", "_f", "_finger_joint" })
          state.name.push_back(kRobots[r] + j);
        state.position.assign(7, 0.0);
        state.velocity.assign(7, 0.0);
        state.position[0] = i;
        state.position[1] = 1e-3 * i;
        topics[r].publish(state);
      }
      loop.sleep();
    }
  }
};

std::map<std::string, int> countPerTopic(const std::string& path)
{
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  std::map<std::string, int> counts;
  for (const rosbag::MessageInstance& m : rosbag::View(bag))
    ++counts[m.getTopic()];
  return counts;
}

int run(const std::string& command, std::string* output = nullptr)
{
  const std::string log = folder() + "/command.log";
  const int status = std::system((command + " >" + log + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  if (output)
    *output = text.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string slurp(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

TEST(Recorder, KeepsEveryMessageOfFourRobotsAt1kHz)
{
  ros::NodeHandle nh;
  Publishers publishers(nh);
  const pid_t recorder = startRecorder();
  const std::string file = folder() + "/lossless.bag";
  ASSERT_TRUE(start(file).success);
  ASSERT_TRUE(publishers.connected());
  vrrw_msgs::DemoAnnotate note;
  note.request.text = "start of the lossless run";
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/annotate", note));
  EXPECT_TRUE(note.response.success);
  const ros::WallTime begin = ros::WallTime::now();
  publishers.publish(10000, 1000.0);
  const double seconds = (ros::WallTime::now() - begin).toSec();
  ros::Duration(0.5).sleep();
  vrrw_msgs::DemoStop stop;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/stop", stop));
  EXPECT_TRUE(stop.response.success) << stop.response.message;
  EXPECT_EQ(stop.response.file, file);
  const auto counts = countPerTopic(file);
  for (const std::string& robot : kRobots)
    EXPECT_EQ(counts.at("/" + robot + "/joint_states"), 10000) << robot;
  EXPECT_EQ(counts.at("/demos/metadata"), 1);
  EXPECT_EQ(counts.at("/demos/events"), 1);
  std::cout << "4 x 10000 joint_states in " << seconds << " s, all " << stop.response.messages << " messages kept\n";

  // The same file again: refused, the bag untouched; the node keeps serving.
  const auto again = start(file);
  EXPECT_FALSE(again.success);
  EXPECT_EQ(again.message, file + ": exists; not overwritten (choose another name)");
  stopRecorder(recorder);
}

TEST(Recorder, RecoversEverythingUpToOneSecondBeforeASigkill)
{
  ros::NodeHandle nh;
  Publishers publishers(nh);
  const pid_t recorder = startRecorder();
  const std::string file = folder() + "/killed.bag";
  ASSERT_TRUE(start(file).success);
  ASSERT_TRUE(publishers.connected());
  publishers.publish(3000, 1000.0);  // 3 s
  stopRecorder(recorder, SIGKILL);
  std::string output;
  ASSERT_EQ(run(VRRW_SCRIPT " demos recover " + file + ".active", &output), 0) << output;
  const auto counts = countPerTopic(file);
  for (const std::string& robot : kRobots)
    EXPECT_GE(counts.at("/" + robot + "/joint_states"), 2000) << robot;  // all but at most the last second
  std::cout << "after SIGKILL at 3000 messages per robot, recovered: " << counts.at("/r1/joint_states") << "\n";
  EXPECT_NE(run(VRRW_SCRIPT " demos recover " + file + ".active", &output), 0);
  EXPECT_NE(output.find(file + ": exists; not overwritten"), std::string::npos) << output;
}

TEST(Recorder, DiskFullStopsKeepsWhatWasWrittenAndSaysSo)
{
  ros::NodeHandle nh;
  Publishers publishers(nh);
  const pid_t recorder = startRecorder(400 * 1024);
  const std::string file = folder() + "/full.bag";
  ASSERT_TRUE(start(file).success);
  ASSERT_TRUE(publishers.connected());
  publishers.publish(1500, 1000.0);  // about 1.2 MB: more than the limit
  vrrw_msgs::DemoStop stop;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/stop", stop));  // the process is alive and answers
  EXPECT_FALSE(stop.response.success);
  EXPECT_NE(stop.response.message.find("disk full?): recording stopped"), std::string::npos) << stop.response.message;
  EXPECT_EQ(stop.response.file, file + ".active");
  stopRecorder(recorder);
  std::string output;
  ASSERT_EQ(run(VRRW_SCRIPT " demos recover " + file + ".active", &output), 0) << output;
  EXPECT_GT(countPerTopic(file).at("/r1/joint_states"), 100);
}

TEST(Recorder, BagToCsvToBagToCsvIsIdenticalAndStandardToolsReadIt)
{
  const std::string bag = folder() + "/lossless.bag", csv1 = folder() + "/one.csv", bag2 = folder() + "/two.bag",
                    csv2 = folder() + "/two.csv";
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " export " + bag + " --csv " + csv1 + " --robot r2", &output), 0) << output;
  ASSERT_EQ(run(VRRW_TOOL " import " + csv1 + " --bag " + bag2 + " --robot r2", &output), 0) << output;
  ASSERT_EQ(run(VRRW_TOOL " export " + bag2 + " --csv " + csv2, &output), 0) << output;
  EXPECT_EQ(slurp(csv1), slurp(csv2));
  const std::string text = slurp(csv1);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 10001);
  ASSERT_EQ(run("rosbag info " + bag, &output), 0);
  EXPECT_NE(output.find("/r4/joint_states   10000 msgs"), std::string::npos) << output;
  ASSERT_EQ(run("rosbag play -q -u 0.5 " + bag, &output), 0) << output;
  ASSERT_EQ(run(VRRW_ROOT "/.venv/bin/python " VRRW_ROOT "/catkin_ws/src/vrrw_demos/test/read_with_rosbags.py " + bag,
                &output), 0) << output;
  EXPECT_NE(output.find("/r4/joint_states 10000\n"), std::string::npos) << output;
  EXPECT_NE(output.find("last r1 position[0] 9999.0\n"), std::string::npos) << output;
  ASSERT_EQ(run(VRRW_SCRIPT " dmp learn --demo " + bag + " --robot r1 --out " + folder() + "/r1.yaml", &output), 0)
      << output;

  EXPECT_EQ(run(VRRW_TOOL " export " + bag + " --csv " + csv1 + " --robot r2", &output), 1);
  EXPECT_EQ(output, "vrrw demos export: " + csv1 + ": exists; not overwritten (remove it or choose another name)\n");
  EXPECT_EQ(run(VRRW_TOOL " export " + bag + " --csv " + folder() + "/x.csv --robot ur5e", &output), 1);
  EXPECT_EQ(output, "vrrw demos export: " + bag +
                        ": no robot 'ur5e' (no topic /ur5e/joint_states; the bag has: r1, r2, r3, r4)\n");
  const std::string cut = folder() + "/cut.bag";
  std::ofstream(cut) << slurp(bag).substr(0, 300000);  // truncated: the index at the end is gone
  EXPECT_EQ(run(VRRW_TOOL " segment " + cut, &output), 1);
  EXPECT_EQ(output.rfind("vrrw demos segment: " + cut + ": not ", 0), 0u) << output;
  EXPECT_NE(output.find("./vrrw demos recover " + cut), std::string::npos) << output;
  EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_recorder");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
