# generated from genmsg/cmake/pkg-genmsg.cmake.em

message(STATUS "vrrw_msgs: 1 messages, 14 services")

set(MSG_I_FLAGS "-Ivrrw_msgs:/work/wt/tools/catkin_ws/src/vrrw_msgs/msg;-Istd_msgs:/usr/share/std_msgs/cmake/../msg;-Igeometry_msgs:/usr/share/geometry_msgs/msg;-Isensor_msgs:/usr/share/sensor_msgs/msg;-Itrajectory_msgs:/usr/share/trajectory_msgs/msg")

# Find all generators
find_package(gencpp REQUIRED)
find_package(genpy REQUIRED)

add_custom_target(vrrw_msgs_generate_messages ALL)

# verify that message/service dependencies have not changed since configure



get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg" "std_msgs/Header"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv" "geometry_msgs/Point:std_msgs/Header:geometry_msgs/PoseStamped:geometry_msgs/Pose:sensor_msgs/JointState:geometry_msgs/Quaternion"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv" "geometry_msgs/Point:geometry_msgs/PoseStamped:std_msgs/Header:geometry_msgs/Pose:sensor_msgs/JointState:geometry_msgs/Quaternion"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv" "std_msgs/Header:sensor_msgs/JointState"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv" "geometry_msgs/Point:std_msgs/Header:geometry_msgs/PoseStamped:trajectory_msgs/JointTrajectory:trajectory_msgs/JointTrajectoryPoint:geometry_msgs/Pose:sensor_msgs/JointState:geometry_msgs/Quaternion"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv" "geometry_msgs/Point:geometry_msgs/PoseStamped:std_msgs/Header:geometry_msgs/Pose:geometry_msgs/Quaternion"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv" "std_msgs/Header:trajectory_msgs/JointTrajectory:trajectory_msgs/JointTrajectoryPoint"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv" NAME_WE)
add_custom_target(_vrrw_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_msgs" "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv" ""
)

#
#  langs = gencpp;genpy
#

### Section generating for lang: gencpp
### Generating Messages
_generate_msg_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)

### Generating Services
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/sensor_msgs/msg/JointState.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/sensor_msgs/msg/JointState.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/sensor_msgs/msg/JointState.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/sensor_msgs/msg/JointState.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_cpp(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
)

### Generating Module File
_generate_module_cpp(vrrw_msgs
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
  "${ALL_GEN_OUTPUT_FILES_cpp}"
)

add_custom_target(vrrw_msgs_generate_messages_cpp
  DEPENDS ${ALL_GEN_OUTPUT_FILES_cpp}
)
add_dependencies(vrrw_msgs_generate_messages vrrw_msgs_generate_messages_cpp)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_cpp _vrrw_msgs_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(vrrw_msgs_gencpp)
add_dependencies(vrrw_msgs_gencpp vrrw_msgs_generate_messages_cpp)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS vrrw_msgs_generate_messages_cpp)

### Section generating for lang: genpy
### Generating Messages
_generate_msg_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)

### Generating Services
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/sensor_msgs/msg/JointState.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/sensor_msgs/msg/JointState.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/sensor_msgs/msg/JointState.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/sensor_msgs/msg/JointState.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/PoseStamped.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/geometry_msgs/msg/Quaternion.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)
_generate_srv_py(vrrw_msgs
  "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
)

### Generating Module File
_generate_module_py(vrrw_msgs
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
  "${ALL_GEN_OUTPUT_FILES_py}"
)

add_custom_target(vrrw_msgs_generate_messages_py
  DEPENDS ${ALL_GEN_OUTPUT_FILES_py}
)
add_dependencies(vrrw_msgs_generate_messages vrrw_msgs_generate_messages_py)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv" NAME_WE)
add_dependencies(vrrw_msgs_generate_messages_py _vrrw_msgs_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(vrrw_msgs_genpy)
add_dependencies(vrrw_msgs_genpy vrrw_msgs_generate_messages_py)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS vrrw_msgs_generate_messages_py)



if(gencpp_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs)
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_msgs
    DESTINATION ${gencpp_INSTALL_DIR}
  )
endif()
if(TARGET std_msgs_generate_messages_cpp)
  add_dependencies(vrrw_msgs_generate_messages_cpp std_msgs_generate_messages_cpp)
endif()
if(TARGET geometry_msgs_generate_messages_cpp)
  add_dependencies(vrrw_msgs_generate_messages_cpp geometry_msgs_generate_messages_cpp)
endif()
if(TARGET sensor_msgs_generate_messages_cpp)
  add_dependencies(vrrw_msgs_generate_messages_cpp sensor_msgs_generate_messages_cpp)
endif()
if(TARGET trajectory_msgs_generate_messages_cpp)
  add_dependencies(vrrw_msgs_generate_messages_cpp trajectory_msgs_generate_messages_cpp)
endif()

if(genpy_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs)
  install(CODE "execute_process(COMMAND \"/usr/bin/python3\" -m compileall \"${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs\")")
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_msgs
    DESTINATION ${genpy_INSTALL_DIR}
  )
endif()
if(TARGET std_msgs_generate_messages_py)
  add_dependencies(vrrw_msgs_generate_messages_py std_msgs_generate_messages_py)
endif()
if(TARGET geometry_msgs_generate_messages_py)
  add_dependencies(vrrw_msgs_generate_messages_py geometry_msgs_generate_messages_py)
endif()
if(TARGET sensor_msgs_generate_messages_py)
  add_dependencies(vrrw_msgs_generate_messages_py sensor_msgs_generate_messages_py)
endif()
if(TARGET trajectory_msgs_generate_messages_py)
  add_dependencies(vrrw_msgs_generate_messages_py trajectory_msgs_generate_messages_py)
endif()
