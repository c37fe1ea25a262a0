#include "hand_operator.h"
#include "workspace_client.h"

#include <algorithm>
#include <std_msgs/Header.h>
#include <std_srvs/SetBool.h>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_evaluation/pick_place_task.h>

namespace vrrw_evaluation
{
namespace
{
constexpr double kRate = 100.0;  // Hz, a tracker's rate (of simulated time)
/// Poses per step slice (50 ms): fewer than the queues of 10 between the hand and physics hold.
constexpr std::size_t kSlice = 5;
}  // namespace

HandOperator::HandOperator(ros::NodeHandle& node, const std::string& robot, vrrw_physics::LockstepClient& sim,
                           const std::string& hand)
  : robot_(robot)
  , hand_(hand)
  , pose_topic_("/operator/" + hand + "/pose")
  , grip_topic_("/operator/" + hand + "/grip")
  , sim_(sim)
{
  pose_ = node.advertise<geometry_msgs::PoseStamped>(pose_topic_, 10);
  grip_ = node.advertise<std_msgs::Float64>(grip_topic_, 10);
  events_ = node.subscribe<vrrw_msgs::Event>("/operator/events", 50, [this](const vrrw_msgs::Event::ConstPtr& e) {
    if (e->detail.rfind("hand " + hand_ + " ", 0) != 0)
      return;  // another hand's, or not a hand's
    std::lock_guard<std::mutex> lock(mutex_);
    events_seen_.push_back(e->kind);
  });
  // what the interaction node makes of the hand, once physics has it queued (the relayed message seen here may
  // still be on its way to physics): the open hand on /physics/hand, the held one on its spring's target
  inputs_queued_ = node.subscribe<std_msgs::Header>("/physics/input_queued", 100, [this](const std_msgs::Header::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (m->frame_id == "hand " + hand_)
      hand_at_ = std::max(hand_at_, m->stamp);
    else if (m->frame_id.rfind("spring_target ", 0) == 0)
      spring_target_ = std::max(spring_target_, m->stamp);
  });
}

bool HandOperator::waitUntilReady(double seconds, std::string& error)
{
  if (!vrrw_common::PersistentServices::waitFor("/" + robot_ + "/free_drive", seconds))
    return error = "no interaction node (/" + robot_ + "/free_drive)", false;
  // the interaction node looks for new hands once a second
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;
       ros::WallDuration(0.05).sleep())
    if (pose_.getNumSubscribers() > 0 && grip_.getNumSubscribers() > 0 && events_.getNumPublishers() > 0 &&
        inputs_queued_.getNumPublishers() > 0)
      return true;
  return error = "the interaction node did not take the hand " + pose_topic_, false;
}

bool HandOperator::setFreeDrive(bool on, std::string& error)
{
  std_srvs::SetBool call;
  call.request.data = on;
  const std::string service = "/" + robot_ + "/free_drive";
  if (!links_.tryCall(service, call))
    return error = service + ": call failed", false;
  if (!call.response.success)
    return error = service + ": " + call.response.message, false;
  return true;
}

void HandOperator::publish(const Eigen::Isometry3d& pose, const ros::Time& stamp)
{
  geometry_msgs::PoseStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = "world";
  msg.pose = tf2::toMsg(pose);
  pose_.publish(msg);
}

void HandOperator::publish(double grip)
{
  std_msgs::Float64 closed;
  closed.data = grip;
  grip_.publish(closed);
}

bool HandOperator::await(const std::function<bool()>& done, double seconds)
{
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);; ros::WallDuration(0.0005).sleep())
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (done())
      return true;
    if (ros::WallTime::now() >= end)
      return false;
  }
}

bool HandOperator::gripUntil(double grip, const std::string& kind)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    events_seen_.clear();
  }
  publish(grip);
  return await([&] { return std::find(events_seen_.begin(), events_seen_.end(), kind) != events_seen_.end(); }, 1.0);
}

bool HandOperator::closeOn(const Eigen::Isometry3d& pose)
{
  for (int attempt = 0; attempt < 3; ++attempt)
  {
    const ros::Time at = sim_.time();
    publish(pose, at);  // the hand is there, open
    publish(0.0);
    if (await([&] { return hand_at_ >= at; }, kAnswerSeconds) && gripUntil(1.0, "grab"))
      return true;
  }
  return false;
}

bool HandOperator::pull(const std::vector<Eigen::Isometry3d>& poses, std::string& error)
{
  const ros::Time start = sim_.time();
  for (std::size_t k = 0; k < poses.size();)
  {
    const std::size_t end = std::min(poses.size(), k + kSlice);
    for (; k < end; ++k)
      publish(poses[k], start + ros::Duration(double(k + 1) / kRate));
    const ros::Time last = start + ros::Duration(double(end) / kRate);
    if (!await([&] { return spring_target_ >= last; }, kAnswerSeconds))
      return error = pose_topic_ + ": physics got no spring target for the hand (from the interaction node)", false;
    sim_.step((last - sim_.time()).toSec());
  }
  return true;
}

bool HandOperator::freeDrive(const Eigen::Isometry3d& tcp_from, const Eigen::Isometry3d& tcp_to,
                             const Eigen::Vector3d& grab, double seconds, double dwell, std::string& error)
{
  for (const std::string& used : { "/" + robot_ + "/free_drive", pose_topic_, grip_topic_ })
    used_.push_back(used);
  Eigen::Isometry3d grab_in_tcp = tcp_from.inverse();
  grab_in_tcp.translation() = tcp_from.inverse() * grab;
  grab_in_tcp.linear() = Eigen::Matrix3d::Identity();  // the hand turns with the TCP
  if (!setFreeDrive(true, error))
    return false;
  if (!closeOn(tcp_from * grab_in_tcp))
    return setFreeDrive(false, error), error = pose_topic_ + ": the hand closed at the wrist but grabbed nothing", false;
  // the pull along a minimum-jerk line, then the hand holds still for the dwell
  std::vector<Eigen::Isometry3d> poses;
  const int steps = std::max(1, int(std::lround(seconds * kRate)));
  for (int k = 1; k <= steps; ++k)
    poses.push_back(interpolatePose(tcp_from, tcp_to, minimumJerk(double(k) / steps)) * grab_in_tcp);
  poses.insert(poses.end(), std::size_t(std::lround(dwell * kRate)), tcp_to * grab_in_tcp);
  if (!pull(poses, error))
    return setFreeDrive(false, error), false;
  if (!setFreeDrive(false, error))  // the arm holds where the hand left it
    return false;
  if (!gripUntil(0.0, "release"))  // the hand opens
    return error = pose_topic_ + ": the hand opened but did not let go", false;
  return true;
}
}  // namespace vrrw_evaluation
