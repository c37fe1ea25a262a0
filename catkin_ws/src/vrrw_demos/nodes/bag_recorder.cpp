#include "bag_recorder.h"

#include <cstdio>
#include <sys/stat.h>
#include <unistd.h>

#include <ros/master.h>
#include <std_msgs/String.h>

namespace vrrw_demos
{
namespace
{
bool exists(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}
}  // namespace

BagRecorder::BagRecorder(ros::NodeHandle nh) : nh_(nh) {}

BagRecorder::~BagRecorder()
{
  std::string file;
  uint64_t messages = 0;
  if (recording_)
    stop(file, messages);
}

bool BagRecorder::wanted(const std::string& topic) const
{
  for (const std::regex& pattern : patterns_)
    if (std::regex_match(topic, pattern))
      return true;
  return false;
}

std::string BagRecorder::start(const std::string& file, std::vector<std::string> robots,
                               const std::string& metadata_yaml)
{
  if (recording_)
    return "already recording to " + file_ + " (call /demos/stop first)";
  if (file.empty())
    return "file: empty; give the bag's path";
  if (exists(file))
    return file + ": exists; not overwritten (choose another name)";
  const std::string active = file + ".active";
  if (exists(active))
    return active + ": exists (an earlier recording that did not end? ./vrrw demos recover " + active + ")";
  try
  {
    bag_ = std::make_unique<rosbag::Bag>();
    bag_->open(active, rosbag::bagmode::Write);
  }
  catch (const rosbag::BagException& e)
  {
    return file + ": cannot create: " + e.what();
  }
  file_ = file;
  active_file_ = active;
  robots_ = std::move(robots);
  patterns_.clear();
  for (const std::string& robot : robots_)
    patterns_.emplace_back("/" + robot + "/.*");
  for (const char* topic : { "/operator/.*", "/demos/events", "/tf", "/tf_static", "/scene/objects",
                             "/physics/(contacts|errors|hand|spring_target)" })
    patterns_.emplace_back(topic);
  written_ = 0;
  failure_.clear();
  failure_taken_ = false;
  stopping_ = false;
  try
  {
    std_msgs::String metadata;
    metadata.data = metadata_yaml;
    bag_->write("/demos/metadata", ros::Time::now(), metadata);
    ++written_;
  }
  catch (const rosbag::BagException& e)
  {
    static_cast<void>(bag_.release());
    return active + ": cannot write (" + e.what() + ", disk full?)";
  }
  recording_ = true;
  writer_ = std::thread(&BagRecorder::writeLoop, this);
  subscribeNewTopics();
  return "";
}

void BagRecorder::subscribeNewTopics()
{
  if (!recording_)
    return;
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics))
    return;
  for (const ros::master::TopicInfo& info : topics)
  {
    if (subscribers_.count(info.name) || !wanted(info.name))
      continue;
    const std::string topic = info.name;
    ros::SubscribeOptions options;
    options.init<topic_tools::ShapeShifter>(
        topic, kQueueSize, [this, topic](const ros::MessageEvent<topic_tools::ShapeShifter const>& event) {
          onMessage(topic, event);
        });
    options.transport_hints = ros::TransportHints().tcpNoDelay();
    subscribers_[topic] = nh_.subscribe(options);
  }
}

void BagRecorder::onMessage(const std::string& topic, const ros::MessageEvent<topic_tools::ShapeShifter const>& event)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!recording_ || stopping_)
    return;
  queue_.push_back({ topic, event.getReceiptTime(), event.getConstMessage(), event.getConnectionHeaderPtr() });
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
  const uint32_t threshold = 768 * 1024;
  while (true)
  {
    std::deque<Queued> batch;
    {
      std::unique_lock<std::mutex> lock(mutex_);
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
      fail(std::string("writing ") + active_file_ + " failed (" + e.what() + ", disk full?): recording stopped, " +
           std::to_string(written_) + " messages kept in " + active_file_ + "; ./vrrw demos recover " + active_file_);
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

std::string BagRecorder::stop(std::string& file, uint64_t& messages)
{
  if (!recording_)
    return "not recording";
  subscribers_.clear();  // no callback runs after this returns
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    wake_.notify_one();
  }
  writer_.join();
  recording_ = false;
  file = file_;
  messages = written_;
  std::string failure;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    failure = failure_;
  }
  if (!failure.empty())
  {
    file = active_file_;
    static_cast<void>(bag_.release());
    return failure;
  }
  try
  {
    bag_->close();
    bag_.reset();
  }
  catch (const rosbag::BagException& e)
  {
    file = active_file_;
    static_cast<void>(bag_.release());
    return "closing " + active_file_ + " failed (" + e.what() + "): ./vrrw demos recover " + active_file_;
  }
  // link + unlink: never replaces a file that appeared meanwhile.
  if (::link(active_file_.c_str(), file_.c_str()) != 0)
  {
    file = active_file_;
    return file_ + ": exists or cannot be created; the recording stays in " + active_file_;
  }
  ::unlink(active_file_.c_str());
  return "";
}
}  // namespace vrrw_demos
