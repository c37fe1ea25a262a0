# generated from genmsg/cmake/pkg-msg-paths.cmake.develspace.in

set(vrrw_msgs_MSG_INCLUDE_DIRS "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg")
set(vrrw_msgs_MSG_DEPENDENCIES std_msgs;geometry_msgs;sensor_msgs;trajectory_msgs)
