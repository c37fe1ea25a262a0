#pragma once
#include <string>
#include <vector>

#include <ros/ros.h>
#include <vrrw_msgs/DemoAnnotate.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStop.h>

#include "bag_recorder.h"

namespace vrrw_demos
{
/// \brief The recorder's ROS face: /demos/start, /demos/stop and /demos/annotate, /demos/events (the
/// annotations) and /demos/status (latched: once a second while recording, and at every start and stop).
/// Runs idle in every workspace (`./vrrw up`), like the paper's record button; its callbacks run on one
/// thread (ros::spin).
class DemoRecorder
{
public:
  static constexpr double kStatusPeriod = 1.0;  ///< wall s between status messages while recording
  static constexpr double kPollPeriod = 0.05;   ///< wall s between looks for new topics

  /// \brief \a file non-empty: records to it at once (\a robots empty: every robot of the scene).
  DemoRecorder(ros::NodeHandle nh, const std::string& file, const std::vector<std::string>& robots);
  /// \brief Closes a running recording (the node is shutting down).
  void shutdown();

private:
  /// Starts recording; throws DemoError (an unknown robot, a taken file, ...).
  void start(const std::string& file, std::vector<std::string> robots);
  void poll();
  void publishStatus();
  bool onStart(vrrw_msgs::DemoStart::Request& request, vrrw_msgs::DemoStart::Response& response);
  bool onStop(vrrw_msgs::DemoStop::Request& request, vrrw_msgs::DemoStop::Response& response);
  bool onAnnotate(vrrw_msgs::DemoAnnotate::Request& request, vrrw_msgs::DemoAnnotate::Response& response);

  ros::NodeHandle nh_;
  BagRecorder recorder_;
  ros::Publisher events_, status_;
  std::vector<ros::ServiceServer> services_;
  ros::WallTimer poll_timer_, status_timer_;
};
}  // namespace vrrw_demos
