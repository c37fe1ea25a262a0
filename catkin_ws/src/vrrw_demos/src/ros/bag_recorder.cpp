#include "bag_recorder.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <unistd.h>

#include <ros/master.h>
#include <ros/network.h>
#include <std_msgs/String.h>
#include <vrrw_common/ros/topic_graph.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/new_file.h>
#include <xmlrpcpp/XmlRpcClient.h>

namespace vrrw_demos
{
namespace
{
/// The topics on which \a node publishes to \a subscriber, from the node's own XML-RPC getBusInfo (the
/// connections it has: a publisher lists a subscriber once their link is set up, and from then on every
/// message reaches it). nullopt when the node does not answer (it died: nothing to wait for).
std::optional<std::set<std::string>> topicsPublishedTo(const std::string& node, const std::string& subscriber)
{
  XmlRpc::XmlRpcValue args, result, uri;
  args[0] = subscriber;
  args[1] = node;
  std::string host;
  uint32_t port = 0;
  if (!ros::master::execute("lookupNode", args, result, uri, false) || uri.getType() != XmlRpc::XmlRpcValue::TypeString ||
      !ros::network::splitURI(static_cast<std::string>(uri), host, port))
    return std::nullopt;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue request, response;
  request[0] = subscriber;
  if (!client.execute("getBusInfo", request, response) || response.getType() != XmlRpc::XmlRpcValue::TypeArray ||
      response.size() < 3 || response[2].getType() != XmlRpc::XmlRpcValue::TypeArray)
    return std::nullopt;
  std::set<std::string> topics;
  XmlRpc::XmlRpcValue& connections = response[2];
  for (int i = 0; i < connections.size(); ++i)
  {
    XmlRpc::XmlRpcValue& c = connections[i];  // [id, other end's caller id, "o" (out) or "i", transport, topic, ...]
    if (c.getType() == XmlRpc::XmlRpcValue::TypeArray && c.size() >= 5 &&
        c[1].getType() == XmlRpc::XmlRpcValue::TypeString && c[2].getType() == XmlRpc::XmlRpcValue::TypeString &&
        c[4].getType() == XmlRpc::XmlRpcValue::TypeString && static_cast<std::string>(c[2]) == "o" &&
        static_cast<std::string>(c[1]) == subscriber)
      topics.insert(static_cast<std::string>(c[4]));
  }
  return topics;
}

/// rosbag refuses a message at time 0, and simulated time is 0 until physics has taken its first step (a
/// workspace that starts paused, or a recording started the moment it is up): such a message is written at
/// ros::TIME_MIN (1 ns), which keeps the order of everything received.
ros::Time bagTime(const ros::Time& time)
{
  return std::max(time, ros::TIME_MIN);
}
}  // namespace

BagRecorder::BagRecorder(ros::NodeHandle nh) : nh_(nh) {}

BagRecorder::~BagRecorder()
{
  if (!recording_)
    return;
  try
  {
    stop();
  }
  catch (const DemoError& e)
  {
    ROS_ERROR_STREAM("recorder: " << e.what());
  }
}

bool BagRecorder::wanted(const std::string& topic) const
{
  for (const std::regex& pattern : patterns_)
    if (std::regex_match(topic, pattern))
      return true;
  return false;
}

void BagRecorder::openActiveFile()
{
  // Created exclusively: no other writer's file (a second recorder's, an import's) is ever truncated.
  const std::string& active = status_.active_file;
  const int fd = ::open(active.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0 && errno == EEXIST)
    throw DemoError(active + ": exists (an earlier recording that did not end? ./vrrw demos recover " + active + ")");
  if (fd < 0)
    throw DemoError(status_.file + ": cannot create: " + std::strerror(errno));
  ::close(fd);
  try
  {
    bag_ = std::make_unique<rosbag::Bag>();
    bag_->open(active, rosbag::bagmode::Write);
  }
  catch (const rosbag::BagException& e)
  {
    ::unlink(active.c_str());
    throw DemoError(status_.file + ": cannot create: " + e.what());
  }
}

void BagRecorder::start(const std::string& file, std::vector<std::string> robots, const std::string& metadata_yaml)
{
  if (recording_)
    throw DemoError("already recording to " + status_.file + " (call /demos/stop first)");
  refuseTaken(file);
  status_ = Status();
  status_.file = file;
  status_.active_file = file + kActiveSuffix;
  status_.robots = std::move(robots);
  openActiveFile();
  // What a demonstration is: the robots' own topics (states, goals, operator commands), the operator's hands,
  // the annotations, tf (object poses), the scene's objects and what physics says of contacts and the hand.
  patterns_.clear();
  for (const std::string& robot : status_.robots)
    patterns_.emplace_back("/" + robot + "/.*");
  for (const char* topic : { "/operator/.*", "/demos/events", "/tf", "/tf_static", "/scene/objects",
                             "/physics/(contacts|errors|hand|spring_target)" })
    patterns_.emplace_back(topic);
  written_ = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    failure_.clear();
    failure_taken_ = false;
    stopping_ = false;
  }
  try
  {
    std_msgs::String metadata;
    metadata.data = metadata_yaml;
    bag_->write("/demos/metadata", bagTime(ros::Time::now()), metadata);
    ++written_;
  }
  catch (const rosbag::BagException& e)
  {
    static_cast<void>(bag_.release());
    throw DemoError(status_.active_file + ": cannot write (" + e.what() + ", disk full?)");
  }
  status_.started = ros::Time::now();
  recording_ = true;
  writer_ = std::thread(&BagRecorder::writeLoop, this);
  subscribeNewTopics();

  // Complete from now on: every publisher of the subscribed topics reaches this node.
  std::vector<std::string> unreached = unreachedTopics();
  for (const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(kConnectTimeout);
       !unreached.empty() && ros::WallTime::now() < give_up; unreached = unreachedTopics())
    ros::WallDuration(0.005).sleep();
  status_.complete_from = ros::Time::now();
  if (!unreached.empty())
  {
    std::string names;
    for (const std::string& topic : unreached)
      names += (names.empty() ? "" : ", ") + topic;
    status_.incomplete = "not complete from the start: " + names + " (a publisher did not connect within " +
                      std::to_string(static_cast<int>(kConnectTimeout)) + " s)";
  }
}

std::vector<std::string> BagRecorder::unreachedTopics() const
{
  const std::string me = ros::this_node::getName();
  const auto graph = vrrw_common::topicGraph();
  if (!graph)
    return {};
  std::map<std::string, std::optional<std::set<std::string>>> reaching;  // node -> topics it publishes to us
  std::vector<std::string> unreached;
  for (const auto& [topic, nodes] : graph->publishers)
  {
    if (!subscribers_.count(topic))
      continue;
    for (const std::string& node : nodes)
    {
      if (node == me)
        continue;  // our own messages go intraprocess, at once
      if (!reaching.count(node))
        reaching[node] = topicsPublishedTo(node, me);
      if (reaching[node] && !reaching[node]->count(topic))
      {
        unreached.push_back(topic);
        break;
      }
    }
  }
  return unreached;
}

void BagRecorder::subscribeNewTopics()
{
  if (!recording_)
    return;
  // published topics and those only subscribed so far (an action's goal topic before any client sends): a
  // recorder subscribed beforehand gets the first message of a publisher that waits for its subscribers
  const auto graph = vrrw_common::topicGraph();
  if (!graph)
    return;
  std::set<std::string> known;
  for (const auto* side : { &graph->publishers, &graph->subscribers })
    for (const auto& entry : *side)
      known.insert(entry.first);
  for (const std::string& topic : known)
  {
    if (subscribers_.count(topic) || !wanted(topic))
      continue;
    ros::SubscribeOptions options;
    options.init<topic_tools::ShapeShifter>(
        topic, kQueueSize, [this, topic](const ros::MessageEvent<topic_tools::ShapeShifter const>& event) {
          onMessage(topic, event);
        });
    options.transport_hints = ros::TransportHints().tcpNoDelay();
    subscribers_[topic] = nh_.subscribe(options);
    status_.topics.push_back(topic);
  }
}

void BagRecorder::onMessage(const std::string& topic, const ros::MessageEvent<topic_tools::ShapeShifter const>& event)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!recording_ || stopping_)
    return;
  queue_.push_back(
      { topic, bagTime(event.getReceiptTime()), event.getConstMessage(), event.getConnectionHeaderPtr() });
  last_message_ = std::chrono::steady_clock::now();
  wake_.notify_one();
}

void BagRecorder::fail(const std::string& reason)
{
  std::lock_guard<std::mutex> lock(mutex_);
  failure_ = reason;
  queue_.clear();
  stopping_ = true;
}

void BagRecorder::writeLoop()
{
  ros::WallTime last_flush = ros::WallTime::now();
  const uint32_t threshold = 768 * 1024;  // bytes: rosbag's own default chunk size
  while (true)
  {
    std::deque<Queued> batch;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      // woken by each message; the 100 ms bound only re-checks the predicate should a notification be missed
      wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return !queue_.empty() || stopping_; });
      batch.swap(queue_);
      if (batch.empty() && stopping_)
        return;
    }
    try
    {
      for (std::size_t k = 0; k < batch.size(); ++k)
      {
        // A chunk ends (and is written out) when it passes the threshold: force that now and then.
        const bool flush = k + 1 == batch.size() && (ros::WallTime::now() - last_flush).toSec() >= kFlushPeriod;
        bag_->setChunkThreshold(flush ? 0 : threshold);
        bag_->write(batch[k].topic, batch[k].time, *batch[k].message, batch[k].header);
        ++written_;
        if (flush)
          last_flush = ros::WallTime::now();
      }
      bag_->setChunkThreshold(threshold);
    }
    catch (const rosbag::BagException& e)
    {
      fail(std::string("writing ") + status_.active_file + " failed (" + e.what() + ", disk full?): recording stopped, " +
           std::to_string(written_) + " messages kept in " + status_.active_file + "; ./vrrw demos recover " +
           status_.active_file);
      return;
    }
  }
}

std::string BagRecorder::takeFailure()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (failure_taken_ || failure_.empty())
    return "";
  failure_taken_ = true;
  return failure_;
}

BagRecorder::Status BagRecorder::status()
{
  Status status = status_;
  status.recording = recording_;
  status.messages = written_;
  std::lock_guard<std::mutex> lock(mutex_);
  status.failure = failure_;
  return status;
}

uint64_t BagRecorder::stop()
{
  if (!recording_)
    throw DemoError("not recording");
  using Clock = std::chrono::steady_clock;
  const auto quiet = std::chrono::duration<double>(kQuietPeriod);
  for (const Clock::time_point give_up = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(kDrainTimeout));
       Clock::now() < give_up; std::this_thread::sleep_for(std::chrono::milliseconds(5)))
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (Clock::now() - last_message_ >= quiet)
      break;
  }
  subscribers_.clear();  // no callback runs after this returns
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    wake_.notify_one();
  }
  writer_.join();
  recording_ = false;
  status_.messages = written_;
  std::string failure;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    failure = failure_;
  }
  if (!failure.empty())
  {
    static_cast<void>(bag_.release());
    throw DemoError(failure);
  }
  try
  {
    bag_->close();
    bag_.reset();
  }
  catch (const rosbag::BagException& e)
  {
    static_cast<void>(bag_.release());
    throw DemoError("closing " + status_.active_file + " failed (" + e.what() + "): ./vrrw demos recover " +
                    status_.active_file);
  }
  // link + unlink: never replaces a file that appeared meanwhile.
  if (::link(status_.active_file.c_str(), status_.file.c_str()) != 0)
    throw DemoError(status_.file + ": exists or cannot be created; the recording stays in " + status_.active_file);
  ::unlink(status_.active_file.c_str());
  return written_;
}
}  // namespace vrrw_demos
