#pragma once
#include <atomic>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <ros/ros.h>
#include <rosbag/bag.h>
#include <topic_tools/shape_shifter.h>

namespace vrrw_demos
{
/// \brief Records every message of the demonstration's topics into a bag, losing none.
///
/// Topics are chosen by name pattern (a robot's namespace, /operator/..., /demos/events, /tf, ...) and
/// subscribed as they appear, so whatever a node adds later is kept. Callbacks only queue (big queues,
/// any type via ShapeShifter); one writer thread writes. The bag is written as FILE.active and renamed
/// to FILE when closed; a chunk is closed (and so on disk) at least every kFlushPeriod, so a SIGKILL loses
/// at most that much (`rosbag reindex` restores the index). A write error (disk full) stops the recording,
/// keeps what was written and says so.
class BagRecorder
{
public:
  static constexpr double kFlushPeriod = 0.5;  ///< s between forced chunk ends
  static constexpr uint32_t kQueueSize = 100000;  ///< per topic; at 1 kHz 100 s of backlog

  explicit BagRecorder(ros::NodeHandle nh);
  ~BagRecorder();

  /// \brief Starts a new bag; empty robots: all. Returns "" or the reason it did not start.
  std::string start(const std::string& file, std::vector<std::string> robots, const std::string& metadata_yaml);
  /// \brief Stops and closes; \a messages is the count written. Returns "" or what went wrong.
  std::string stop(std::string& file, uint64_t& messages);
  bool recording() const { return recording_; }
  /// \brief The reason recording stopped on its own (disk full), once; empty otherwise.
  std::string takeFailure();
  /// \brief Subscribes topics that appeared since the last call and match the patterns.
  void subscribeNewTopics();
  const std::vector<std::string>& robots() const { return robots_; }

private:
  struct Queued
  {
    std::string topic;
    ros::Time time;
    topic_tools::ShapeShifter::ConstPtr message;
    boost::shared_ptr<ros::M_string> header;
  };

  void onMessage(const std::string& topic, const ros::MessageEvent<topic_tools::ShapeShifter const>& event);
  void writeLoop();
  bool wanted(const std::string& topic) const;
  void fail(const std::string& reason);

  ros::NodeHandle nh_;
  std::unique_ptr<rosbag::Bag> bag_;  ///< released (never closed) after a write error: closing would write again
  std::string file_, active_file_;
  std::vector<std::string> robots_;
  std::vector<std::regex> patterns_;
  std::map<std::string, ros::Subscriber> subscribers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Queued> queue_;
  std::thread writer_;
  std::atomic<bool> recording_{ false };
  bool stopping_ = false;
  std::atomic<uint64_t> written_{ 0 };
  std::string failure_;
  bool failure_taken_ = false;
};
}  // namespace vrrw_demos
