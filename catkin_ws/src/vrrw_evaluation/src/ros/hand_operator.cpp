#include "hand_operator.h"

#include <algorithm>
#include <std_srvs/SetBool.h>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_evaluation/pick_place_task.h>

namespace vrrw_evaluation
{
namespace
{
constexpr double kRate = 100.0;  // Hz, a tracker's rate
}

HandOperator::HandOperator(ros::NodeHandle& node, const std::string& robot, const std::string& hand)
  : robot_(robot)
  , hand_(hand)
  , pose_topic_("/operator/" + hand + "/pose")
  , grip_topic_("/operator/" + hand + "/grip")
{
  pose_ = node.advertise<geometry_msgs::PoseStamped>(pose_topic_, 10);
  grip_ = node.advertise<std_msgs::Float64>(grip_topic_, 10);
  events_ = node.subscribe<vrrw_msgs::Event>("/operator/events", 50, [this](const vrrw_msgs::Event::ConstPtr& e) {
    if (e->detail.rfind("hand " + hand_ + " ", 0) != 0)
      return;  // another hand's, or not a hand's
    std::lock_guard<std::mutex> lock(mutex_);
    events_seen_.push_back(e->kind);
  });
}

bool HandOperator::waitUntilReady(double seconds, std::string& error)
{
  if (!ros::service::waitForService("/" + robot_ + "/free_drive", ros::Duration(seconds)))
    return error = "no interaction node (/" + robot_ + "/free_drive)", false;
  // the interaction node looks for new hands once a second
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;
       ros::WallDuration(0.05).sleep())
    if (pose_.getNumSubscribers() > 0 && grip_.getNumSubscribers() > 0 && events_.getNumPublishers() > 0)
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

void HandOperator::publish(const Eigen::Isometry3d& pose, double grip)
{
  geometry_msgs::PoseStamped msg;
  msg.header.stamp = ros::Time::now();
  msg.header.frame_id = "world";
  msg.pose = tf2::toMsg(pose);
  pose_.publish(msg);
  std_msgs::Float64 closed;
  closed.data = grip;
  grip_.publish(closed);
}

bool HandOperator::holdUntil(const Eigen::Isometry3d& pose, double grip, const std::string& kind, double seconds)
{
  ros::WallRate rate(kRate);
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;)
  {
    publish(pose, grip);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (std::find(events_seen_.begin(), events_seen_.end(), kind) != events_seen_.end())
        return true;
    }
    rate.sleep();
  }
  return kind.empty();
}

bool HandOperator::freeDrive(const Eigen::Isometry3d& tcp_from, const Eigen::Isometry3d& tcp_to,
                             const Eigen::Vector3d& grab, double seconds, double dwell, std::string& error)
{
  for (const std::string& used : { "/" + robot_ + "/free_drive", pose_topic_, grip_topic_ })
    used_.push_back(used);
  Eigen::Isometry3d grab_in_tcp = tcp_from.inverse();
  grab_in_tcp.translation() = tcp_from.inverse() * grab;
  grab_in_tcp.linear() = Eigen::Matrix3d::Identity();  // the hand turns with the TCP
  {
    std::lock_guard<std::mutex> lock(mutex_);
    events_seen_.clear();
  }
  if (!setFreeDrive(true, error))
    return false;
  holdUntil(tcp_from * grab_in_tcp, 0.0, "", 0.1);  // the hand is there, open
  if (!holdUntil(tcp_from * grab_in_tcp, 1.0, "grab", 2.0))
    return setFreeDrive(false, error), error = pose_topic_ + ": the hand closed at the wrist but grabbed nothing", false;
  ros::WallRate rate(kRate);
  const int steps = std::max(1, int(std::lround(seconds * kRate)));
  for (int k = 1; k <= steps; ++k, rate.sleep())
    publish(interpolatePose(tcp_from, tcp_to, minimumJerk(double(k) / steps)) * grab_in_tcp, 1.0);
  holdUntil(tcp_to * grab_in_tcp, 1.0, "", dwell);
  const bool rigid = setFreeDrive(false, error);  // the arm holds where the hand left it
  if (!holdUntil(tcp_to * grab_in_tcp, 0.0, "release", 1.0) && rigid)
    return error = pose_topic_ + ": the hand opened but did not let go", false;
  return rigid;
}
}  // namespace vrrw_evaluation
