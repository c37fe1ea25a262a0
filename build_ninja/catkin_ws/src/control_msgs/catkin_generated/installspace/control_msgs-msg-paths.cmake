# generated from genmsg/cmake/pkg-msg-paths.cmake.installspace.in

_prepend_path("${control_msgs_DIR}/.." "msg;msg;msg" control_msgs_MSG_INCLUDE_DIRS UNIQUE)
set(control_msgs_MSG_DEPENDENCIES actionlib_msgs;std_msgs;trajectory_msgs)
