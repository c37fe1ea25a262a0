#pragma once
#include <atomic>
#include <chrono>
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
/// subscribed as they appear, so whatever a node adds later is kept. start() returns only once every
/// publisher of the topics there already lists this node among its subscribers, so the bag is complete
/// from the time it returns. Callbacks only queue (big queues, any type via ShapeShifter); one writer
/// thread writes. The bag is written as FILE.active and linked to FILE when closed; a chunk is closed
/// (and so on disk) at least every kFlushPeriod, so a SIGKILL loses at most that much (`rosbag reindex`
/// restores the index). A write error (disk full) stops the recording, keeps what was written and says so.
/// stop() first takes what is still on its way (published before the stop, on another connection or callback
/// thread): it waits until no message came for kQuietPeriod, at most kDrainTimeout. While a lockstep
/// simulation waits, its topics are quiet, so a seeded run's bag ends with the same message each time.
///
/// Threads: start(), stop(), subscribeNewTopics() and status() run on one thread (the node's spinner);
/// message callbacks on any; the writer on its own.
class BagRecorder
{
public:
  static constexpr double kFlushPeriod = 0.5;     ///< s between forced chunk ends
  static constexpr uint32_t kQueueSize = 100000;  ///< per topic; at 1 kHz 100 s of backlog
  static constexpr double kConnectTimeout = 2.0;  ///< wall s start() waits for the publishers to reach it
  static constexpr double kQuietPeriod = 0.05;    ///< wall s without a message after which stop() ends the bag
  static constexpr double kDrainTimeout = 0.5;    ///< wall s stop() waits at most for that quiet

  /// \brief What is being (or was last) recorded.
  struct Status
  {
    bool recording = false;
    std::string file, active_file;
    std::vector<std::string> robots, topics;
    ros::Time started, complete_from;
    uint64_t messages = 0;
    std::string failure;     ///< why it stopped on its own (disk full)
    std::string incomplete;  ///< which topics are not complete from complete_from, and why; empty: all are
  };

  explicit BagRecorder(ros::NodeHandle nh);
  ~BagRecorder();

  /// \brief Starts a new bag (never over a file, nor over a recording's FILE.active); throws DemoError.
  void start(const std::string& file, std::vector<std::string> robots, const std::string& metadata_yaml);
  /// \brief Stops and closes; returns the messages written. Throws DemoError saying what went wrong and
  /// where the data stays (status().file then names FILE.active).
  uint64_t stop();
  bool recording() const { return recording_; }
  Status status();
  /// \brief The reason recording stopped on its own (disk full), once; empty otherwise.
  std::string takeFailure();
  /// \brief Subscribes topics that appeared since the last call and match the patterns.
  void subscribeNewTopics();

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
  /// The subscribed topics whose publishers (other nodes) do not yet list this node as a subscriber.
  std::vector<std::string> unreachedTopics() const;
  void openActiveFile();

  ros::NodeHandle nh_;
  std::unique_ptr<rosbag::Bag> bag_;  ///< released (never closed) after a write error: closing would write again
  std::vector<std::regex> patterns_;
  std::map<std::string, ros::Subscriber> subscribers_;
  Status status_;             ///< the control thread's view; messages and failure live below
  std::mutex mutex_;          ///< protects queue_, stopping_, failure_, failure_taken_, last_message_
  std::condition_variable wake_;
  std::deque<Queued> queue_;  ///< PROTECTED BY mutex_
  std::thread writer_;
  std::atomic<bool> recording_{ false };
  bool stopping_ = false;      ///< PROTECTED BY mutex_
  std::chrono::steady_clock::time_point last_message_;  ///< PROTECTED BY mutex_: when the last one arrived
  std::atomic<uint64_t> written_{ 0 };
  std::string failure_;        ///< PROTECTED BY mutex_
  bool failure_taken_ = false; ///< PROTECTED BY mutex_
};
}  // namespace vrrw_demos
