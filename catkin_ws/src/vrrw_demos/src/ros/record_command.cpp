// `vrrw demos record --out FILE [--robots a,b] [--wait S] [--check]`: records a demonstration with the
// workspace's recorder (/demos/start) until Ctrl-C, saying at once what is recorded and every few seconds
// how much; Ctrl-C (or SIGTERM) stops it through /demos/stop. A workspace without a recorder gets one,
// started here and stopped at the end.
#include "record_command.h"

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <iostream>
#include <mutex>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/new_file.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStatus.h>
#include <vrrw_msgs/DemoStop.h>


extern char** environ;

namespace vrrw_demos
{
namespace
{
constexpr double kReportPeriod = 3.0;  ///< wall s between "recording: ..." lines
constexpr double kRecorderGone = 5.0;  ///< wall s without a status before the recorder counts as gone

struct RecordRequest
{
  std::string file;  ///< absolute
  std::vector<std::string> robots;
  double wait = 2.0;  ///< wall s to wait for a workspace (and its recorder)
  bool check_only = false;
};

std::vector<std::string> splitList(const std::string& text)
{
  std::vector<std::string> items;
  std::string item;
  for (char c : text + ",")
    if (c == ',')
    {
      if (!item.empty())
        items.push_back(item);
      item.clear();
    }
    else
      item += c;
  return items;
}

std::string folderOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == 0 ? "/" : path.substr(0, slash);
}

RecordRequest parseRecordRequest(int argc, char** argv)
{
  const vrrw_common::Options options(argc, argv, 2, { "out", "robots", "wait" }, { "check" });
  options.expectPositional({});
  RecordRequest request;
  request.file = options.text("out");
  if (request.file.empty())
    throw DemoError("--out: empty; give the bag's path");
  if (request.file[0] != '/')
  {
    char cwd[PATH_MAX];
    if (!::getcwd(cwd, sizeof(cwd)))
      throw DemoError("--out: " + request.file + ": the working directory is unreadable");
    request.file = std::string(cwd) + "/" + request.file;
  }
  try
  {
    refuseTaken(request.file);
    std::remove(temporaryBeside(request.file).c_str());  // the folder takes a new file
  }
  catch (const DemoError& e)
  {
    throw DemoError(std::string("--out: ") + e.what());
  }
  request.robots = splitList(options.text("robots", ""));
  request.wait = options.number("wait", request.wait, vrrw_common::Range::closed(0.0, 600.0, "s"));
  request.check_only = options.flag("check");
  return request;
}

/// recorder_node beside this tool, started when the workspace runs none; stopped (SIGINT) and waited for.
class OwnRecorder
{
public:
  OwnRecorder()
  {
    char self[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof(self) - 1);
    const std::string path = n > 0 ? folderOf(std::string(self, static_cast<std::size_t>(n))) + "/recorder_node" : "";
    char* args[] = { const_cast<char*>(path.c_str()), nullptr };
    if (path.empty() || ::posix_spawn(&pid_, path.c_str(), nullptr, nullptr, args, environ) != 0)
      throw DemoError("cannot start recorder_node beside " + std::string(n > 0 ? self : "this tool"));
    std::cout << "record: the workspace runs no recorder: started recorder_node (pid " << pid_ << ")" << std::endl;
  }
  ~OwnRecorder()
  {
    ::kill(pid_, SIGINT);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }

private:
  pid_t pid_ = -1;
};

/// The latest /demos/status, and when it came.
class StatusView
{
public:
  explicit StatusView(ros::NodeHandle& nh)
  {
    sub_ = nh.subscribe<vrrw_msgs::DemoStatus>("/demos/status", 10, [this](const vrrw_msgs::DemoStatusConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      latest_ = *m;
      when_ = ros::WallTime::now();
    });
  }
  std::pair<vrrw_msgs::DemoStatus, ros::WallTime> latest()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return { latest_, when_ };
  }

private:
  std::mutex mutex_;
  vrrw_msgs::DemoStatus latest_;  ///< PROTECTED BY mutex_
  ros::WallTime when_;            ///< PROTECTED BY mutex_
  ros::Subscriber sub_;           ///< last: destroyed first (its shutdown waits for a running callback)
};

bool waitFor(const std::function<bool()>& ready, double seconds, const std::atomic<bool>& interrupted)
{
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); !interrupted;
       ros::WallDuration(0.05).sleep())
    if (ready())
      return true;
    else if (ros::WallTime::now() > end)
      return false;
  return false;
}

std::string megabytes(uint64_t bytes)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}

/// Stops the recording through /demos/stop; prints where it is; the exit code.
int stopRecording(vrrw_common::PersistentServices& services)
{
  vrrw_msgs::DemoStop call;
  std::string error;
  if (!services.tryCall("/demos/stop", call, &error))
  {
    std::cerr << "record: " << error << ": the recording stays in the bag or its .active file (./vrrw demos recover "
                 "FILE.active)\n";
    return 1;
  }
  if (!call.response.success)
  {
    std::cerr << "record: " << call.response.message << "\n";
    return 1;
  }
  std::cout << "record: stopped: " << call.response.messages << " messages in " << call.response.file << std::endl;
  return 0;
}
}  // namespace

int runRecord(int argc, char** argv, const std::atomic<bool>& interrupted)
{
  const RecordRequest request = parseRecordRequest(argc, argv);
  if (request.check_only)
    return 0;
  ros::init(argc, argv, "demo_record", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  const vrrw_common::ToolNode node_registration;
  // a workspace coming up (./vrrw record SCENE) is waited for; a running one is checked within 2 s
  if (request.wait <= 2.0 || !waitFor([] { return vrrw_common::masterAnswers(0.5); }, request.wait, interrupted))
    vrrw_common::checkWorkspace();  // says there is none, in the one way
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  StatusView status(nh);
  std::unique_ptr<OwnRecorder> own;
  if (!waitFor([] { return ros::service::exists("/demos/start", false); }, request.wait, interrupted))
  {
    own = std::make_unique<OwnRecorder>();
    if (!waitFor([] { return ros::service::exists("/demos/start", false); }, 20.0, interrupted))
      throw DemoError("recorder_node did not advertise /demos/start within 20 s");
  }

  // links of this run's own, closed before ROS stops (not a process-wide set closing at exit)
  vrrw_common::PersistentServices services;
  vrrw_msgs::DemoStart call;
  call.request.file = request.file;
  call.request.robots = request.robots;
  services.call("/demos/start", call);
  if (!call.response.success)
    throw DemoError(call.response.message);
  std::string topics;
  for (const std::string& topic : call.response.topics)
    topics += (topics.empty() ? "" : ", ") + topic;
  std::cout << "record: " << call.response.message << std::endl;
  std::cout << "record: topics: " << topics << " (more as they appear); Ctrl-C or kill " << ::getpid() << " stops"
            << std::endl;

  // Every kReportPeriod: how much is recorded, from the recorder's status; the seconds on this tool's wall clock
  // (its ROS clock may not be the recorder's: `record SCENE` starts before the workspace sets /use_sim_time)
  const ros::WallTime recording_since = ros::WallTime::now();
  ros::WallTime next = recording_since + ros::WallDuration(kReportPeriod);
  while (!interrupted)
  {
    ros::WallDuration(0.05).sleep();
    const auto [latest, when] = status.latest();
    if (!latest.failure.empty())
    {
      std::cerr << "record: " << latest.failure << "\n";
      stopRecording(services);
      return 1;
    }
    if ((ros::WallTime::now() - when).toSec() > kRecorderGone && !ros::service::exists("/demos/stop", false))
    {
      std::cerr << "record: the recorder is gone (the workspace stopped?); what it wrote is in " << request.file
                << " or " << request.file << kActiveSuffix << " (./vrrw demos recover " << request.file
                << kActiveSuffix << ")\n";
      return 1;
    }
    if (ros::WallTime::now() < next)
      continue;
    next += ros::WallDuration(kReportPeriod);
    if (latest.recording)
      std::cout << "record: " << static_cast<int>((ros::WallTime::now() - recording_since).toSec()) << " s, "
                << latest.messages << " messages, " << megabytes(latest.bytes) << ", " << latest.topics.size()
                << " topics" << std::endl;
  }
  return stopRecording(services);
}
}  // namespace vrrw_demos
