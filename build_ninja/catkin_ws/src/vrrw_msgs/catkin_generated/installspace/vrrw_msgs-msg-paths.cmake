# generated from genmsg/cmake/pkg-msg-paths.cmake.installspace.in

_prepend_path("${vrrw_msgs_DIR}/.." "msg" vrrw_msgs_MSG_INCLUDE_DIRS UNIQUE)
set(vrrw_msgs_MSG_DEPENDENCIES std_msgs;geometry_msgs;sensor_msgs;trajectory_msgs)
