# generated from genmsg/cmake/pkg-msg-paths.cmake.installspace.in

_prepend_path("${vrrw_dmp_DIR}/.." "" vrrw_dmp_MSG_INCLUDE_DIRS UNIQUE)
set(vrrw_dmp_MSG_DEPENDENCIES std_msgs;trajectory_msgs)
