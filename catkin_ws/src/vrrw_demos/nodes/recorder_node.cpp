// recorder_node: records demonstrations to rosbag (vrrw_demos::DemoRecorder, src/ros/demo_recorder.h).
//   services /demos/start (vrrw_msgs/DemoStart), /demos/stop (DemoStop), /demos/annotate (DemoAnnotate)
//   publishes /demos/events (vrrw_msgs/Event: annotations), /demos/status (vrrw_msgs/DemoStatus, latched)
//   params ~file (record to it at once; empty: idle until /demos/start), ~robots (list; default all of the scene's)
#include <ros/ros.h>

#include "../src/ros/demo_recorder.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "demo_recorder");
  ros::NodeHandle nh, pnh("~");
  vrrw_demos::DemoRecorder recorder(nh, pnh.param<std::string>("file", ""),
                                    pnh.param("robots", std::vector<std::string>{}));
  ros::spin();
  recorder.shutdown();
  return 0;
}
