// The recorder node end to end with a real master, rosbag files and the vrrw_demos tool (and ./vrrw record):
// lossless, SIGKILL, disk full, complete from start's answer, unknown robots, no other writer on a live
// recording, feedback while recording, hostile file names, a huge one-line CSV.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <mutex>
#include <thread>

#include <ros/ros.h>
#include <vrrw_common/ros/persistent_service.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_msgs/DemoAnnotate.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStatus.h>
#include <vrrw_msgs/DemoStop.h>

#include "file_text.h"
#include "tool_process.h"

using vrrw_demos_test::folder;
using vrrw_demos_test::run;
using vrrw_demos_test::ToolProcess;

namespace
{
const std::vector<std::string> kRobots{ "r1", "r2", "r3", "r4" };

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
  /// count messages per robot at rate Hz; position[0] carries the sequence number in thousandths (a joint value
  /// within the import's bounds).
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
        state.position[0] = i / 1000.0;
        state.position[1] = -1e-3 * i;
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
  std::atomic<std::uint64_t> written{ 0 };
  ros::Subscriber status = nh.subscribe<vrrw_msgs::DemoStatus>(
      "/demos/status", 10, [&](const vrrw_msgs::DemoStatusConstPtr& m) { written = m->messages; });
  const ros::WallTime begin = ros::WallTime::now();
  publishers.publish(10000, 1000.0);
  const double seconds = (ros::WallTime::now() - begin).toSec();
  // stopped once the recorder says it wrote them all (its status comes once a second), not after a fixed
  // wait a loaded machine may outlast; 60 s only guards against a hang
  for (int k = 0; k < 600 && written < 40002; ++k)  // 4 x 10000, the metadata and the note
    ros::WallDuration(0.1).sleep();
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
  EXPECT_EQ(again.message, file + ": exists; not overwritten (remove it or choose another name)");
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
  EXPECT_NE(output.find("last r1 position[0] 9.999\n"), std::string::npos) << output;
  ASSERT_EQ(run(VRRW_SCRIPT " dmp learn --demo " + bag + " --robot r1 --out " + folder() + "/r1.yaml", &output), 0)
      << output;

  EXPECT_EQ(run(VRRW_TOOL " export " + bag + " --csv " + csv1 + " --robot r2", &output), 2);
  EXPECT_EQ(output, "vrrw demos export: " + csv1 + ": exists; not overwritten (remove it or choose another name)\n");
  EXPECT_EQ(run(VRRW_TOOL " export " + bag + " --csv " + folder() + "/x.csv --robot ur5e", &output), 2);
  EXPECT_EQ(output, "vrrw demos export: " + bag +
                        ": no robot 'ur5e' (no topic /ur5e/joint_states; the bag has: r1, r2, r3, r4)\n");
  const std::string cut = folder() + "/cut.bag";
  std::ofstream(cut) << slurp(bag).substr(0, 300000);  // truncated: the index at the end is gone
  EXPECT_EQ(run(VRRW_TOOL " segment " + cut, &output), 2);
  EXPECT_EQ(output.rfind("vrrw demos segment: " + cut + ": not ", 0), 0u) << output;
  EXPECT_NE(output.find("./vrrw demos recover " + cut), std::string::npos) << output;
  EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1);
}

namespace
{
bool exists(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}

/// /r1/joint_states at about 1 kHz from a thread, each stamped as it is published; the stamps kept.
class SteadyPublisher
{
public:
  explicit SteadyPublisher(ros::NodeHandle& nh)
    : topic_(nh.advertise<sensor_msgs::JointState>("/r1/joint_states", 20000)), thread_([this] { loop(); })
  {
  }
  ~SteadyPublisher() { stop(); }
  void stop()
  {
    running_ = false;
    if (thread_.joinable())
      thread_.join();
  }
  std::vector<ros::Time> stamps()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return stamps_;
  }

private:
  void loop()
  {
    ros::WallRate rate(1000.0);
    for (int i = 0; running_; ++i, rate.sleep())
    {
      sensor_msgs::JointState state;
      state.name = { "r1_a", "r1_b", "r1_c", "r1_d", "r1_e", "r1_f", "r1_finger_joint" };
      state.position.assign(7, 0.0);
      state.position[0] = i;
      std::lock_guard<std::mutex> lock(mutex_);
      state.header.stamp = ros::Time::now();
      topic_.publish(state);
      stamps_.push_back(state.header.stamp);
    }
  }
  ros::Publisher topic_;
  std::atomic<bool> running_{ true };
  std::mutex mutex_;
  std::vector<ros::Time> stamps_;  ///< PROTECTED BY mutex_
  std::thread thread_;
};
}  // namespace

TEST(Recorder, TheBagIsCompleteFromTheMomentStartAnswers)
{
  ros::NodeHandle nh;
  SteadyPublisher publisher(nh);  // publishing before, during and after the start
  const pid_t recorder = startRecorder();
  ros::WallDuration(0.5).sleep();
  const std::string file = folder() + "/complete.bag";
  vrrw_msgs::DemoStart srv;
  srv.request.file = file;
  srv.request.robots = { "r1" };
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/start", srv));
  const ros::Time answered = ros::Time::now();
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_LE(srv.response.complete_from, answered);
  EXPECT_NE(std::find(srv.response.topics.begin(), srv.response.topics.end(), "/r1/joint_states"),
            srv.response.topics.end());
  ros::WallDuration(1.0).sleep();
  vrrw_msgs::DemoStop stop;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/stop", stop));  // stops before the publisher: its last ones are not asked for
  const ros::Time stopped = ros::Time::now();
  publisher.stop();
  std::size_t published = 0, recorded = 0;
  for (const ros::Time& stamp : publisher.stamps())
    published += stamp >= srv.response.complete_from && stamp + ros::Duration(0.1) < stopped;
  rosbag::Bag bag(file, rosbag::bagmode::Read);
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("/r1/joint_states")))
  {
    const auto state = m.instantiate<sensor_msgs::JointState>();
    recorded += state->header.stamp >= srv.response.complete_from && state->header.stamp + ros::Duration(0.1) < stopped;
  }
  std::cout << "published from complete_from on: " << published << ", in the bag: " << recorded << "; complete_from "
            << (answered - srv.response.complete_from).toSec() << " s before the answer\n";
  EXPECT_GT(published, 500u);
  EXPECT_EQ(recorded, published);
  stopRecorder(recorder);
}

TEST(Recorder, RefusesUnknownRobotsAndNeverLetsAnotherWriterTakeItsFile)
{
  ros::NodeHandle nh;
  Publishers publishers(nh);
  const pid_t recorder = startRecorder();
  vrrw_msgs::DemoStart unknown;
  unknown.request.file = folder() + "/ur99.bag";
  unknown.request.robots = { "ur99" };
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/start", unknown));
  EXPECT_FALSE(unknown.response.success);
  EXPECT_EQ(unknown.response.message, "robots: 'ur99' is not a robot of the scene (its robots: r1, r2, r3, r4)");
  EXPECT_FALSE(exists(unknown.request.file + ".active"));

  // a live recording: import, export and segment may not write to it (nor to its .active)
  const std::string clash = folder() + "/clash.bag", csv = folder() + "/clash_source.csv";
  std::string output;
  ASSERT_EQ(run(VRRW_TOOL " export " + folder() + "/lossless.bag --csv " + csv + " --robot r1", &output), 0) << output;
  ASSERT_TRUE(start(clash).success);
  ASSERT_TRUE(publishers.connected());
  publishers.publish(500, 1000.0);
  EXPECT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + clash + " --robot r1", &output), 2);
  EXPECT_EQ(output, "vrrw demos import: " + clash + ": a recording is being written to " + clash +
                        ".active (or was killed there: ./vrrw demos recover " + clash + ".active); choose another name\n");
  EXPECT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + clash + ".active --robot r1", &output), 2);
  EXPECT_EQ(run(VRRW_TOOL " export " + folder() + "/lossless.bag --csv " + clash + " --robot r1", &output), 2);
  EXPECT_EQ(run(VRRW_TOOL " segment " + folder() + "/lossless.bag --out " + clash, &output), 2);
  publishers.publish(500, 1000.0, 500);
  ros::Duration(0.3).sleep();
  vrrw_msgs::DemoStop stop;
  ASSERT_TRUE(vrrw_common::services().tryCall("/demos/stop", stop));
  EXPECT_TRUE(stop.response.success) << stop.response.message;
  EXPECT_EQ(countPerTopic(clash).at("/r1/joint_states"), 1000);  // the recording is whole
  stopRecorder(recorder);
}

TEST(Recorder, RecordSaysWhatItRecordsAndHowMuchAndStopsOnCtrlC)
{
  ros::NodeHandle nh;
  Publishers publishers(nh);
  const pid_t recorder = startRecorder();
  // a name with every character a shell or a launch file would take for its own
  const std::string name = "a|b&c';touch PWNED;'$(touch PWNED2)<x>.bag";
  ToolProcess record({ VRRW_SCRIPT, "record", "running", "--out", name, "--robots", "r1,r2,r3,r4" }, folder());
  std::string first, second, text;
  ASSERT_TRUE(record.line(first));
  ASSERT_TRUE(record.line(second));
  EXPECT_EQ(first.rfind("record: recording r1, r2, r3, r4 to " + folder() + "/" + name + ": ", 0), 0u) << first;
  EXPECT_NE(first.find(" topics, complete from "), std::string::npos) << first;
  EXPECT_EQ(second.rfind("record: topics: ", 0), 0u) << second;
  EXPECT_NE(second.find("/r2/joint_states"), std::string::npos) << second;
  ASSERT_TRUE(publishers.connected());
  std::thread publish([&] { publishers.publish(4000, 1000.0); });  // 4 s: a "how much" line comes after 3 s
  ASSERT_TRUE(record.line(text));
  publish.join();
  EXPECT_NE(text.find(" s, "), std::string::npos) << text;
  EXPECT_NE(text.find(" messages, "), std::string::npos) << text;
  EXPECT_NE(text.find(" MB, "), std::string::npos) << text;
  record.signal(SIGINT);
  const std::string rest = record.rest();
  EXPECT_EQ(record.wait(), 0) << rest;
  EXPECT_NE(rest.find("record: stopped: "), std::string::npos) << rest;
  EXPECT_EQ(countPerTopic(folder() + "/" + name).at("/r2/joint_states"), 4000);
  EXPECT_FALSE(exists(folder() + "/PWNED"));
  EXPECT_FALSE(exists(folder() + "/PWNED2"));
  stopRecorder(recorder);
}

TEST(Recorder, PlotTakesHostilePathsAsPathsAndSaysWhenItCannotWrite)
{
  const std::string bag = folder() + "/x';touch PWNED;'.bag";
  ASSERT_EQ(::link((folder() + "/lossless.bag").c_str(), bag.c_str()), 0);
  ToolProcess plot({ VRRW_TOOL, "plot", bag, "--robot", "r1", "--out", "y';touch PWNED;'.png" }, folder());
  const std::string output = plot.rest();
  EXPECT_EQ(plot.wait(), 0) << output;
  EXPECT_TRUE(exists(folder() + "/y';touch PWNED;'.png")) << output;
  EXPECT_FALSE(exists(folder() + "/PWNED"));
  ToolProcess refused({ VRRW_TOOL, "plot", bag, "--robot", "r1", "--out", "/proc/vrrw_plot.png" });
  EXPECT_EQ(refused.rest(), "vrrw demos plot: /proc/vrrw_plot.png: cannot create a file in /proc (No such file or directory)\n");
  EXPECT_EQ(refused.wait(), 2);
}

TEST(Recorder, AHugeOneLineCsvIsOneShortLine)
{
  const std::string csv = folder() + "/huge.csv";
  std::ofstream(csv) << "t,r1_a,r1_a_vel\n" << std::string(5000000, '7');
  std::string output;
  EXPECT_EQ(run(VRRW_TOOL " import " + csv + " --bag " + folder() + "/huge.bag --robot r1", &output), 2);
  EXPECT_EQ(output, "vrrw demos import: " + csv +
                        ":2: longer than 65536 characters: not a row of a trajectory (a row of joint values has a few "
                        "hundred)\n");
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_recorder");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
