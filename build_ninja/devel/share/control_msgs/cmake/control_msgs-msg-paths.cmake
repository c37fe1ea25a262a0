# generated from genmsg/cmake/pkg-msg-paths.cmake.develspace.in

set(control_msgs_MSG_INCLUDE_DIRS "/work/wt/tools/catkin_ws/src/control_msgs/msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg")
set(control_msgs_MSG_DEPENDENCIES actionlib_msgs;std_msgs;trajectory_msgs)
