# generated from genmsg/cmake/pkg-msg-paths.cmake.develspace.in

set(vrrw_dmp_MSG_INCLUDE_DIRS "")
set(vrrw_dmp_MSG_DEPENDENCIES std_msgs;trajectory_msgs)
