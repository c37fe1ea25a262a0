# generated from genmsg/cmake/pkg-msg-paths.cmake.installspace.in

_prepend_path("${vrrw_physics_DIR}/.." "msg" vrrw_physics_MSG_INCLUDE_DIRS UNIQUE)
set(vrrw_physics_MSG_DEPENDENCIES geometry_msgs;std_msgs)
