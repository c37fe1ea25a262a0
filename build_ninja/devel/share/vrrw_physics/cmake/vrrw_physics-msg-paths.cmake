# generated from genmsg/cmake/pkg-msg-paths.cmake.develspace.in

set(vrrw_physics_MSG_INCLUDE_DIRS "/work/wt/tools/catkin_ws/src/vrrw_physics/msg")
set(vrrw_physics_MSG_DEPENDENCIES geometry_msgs;std_msgs)
