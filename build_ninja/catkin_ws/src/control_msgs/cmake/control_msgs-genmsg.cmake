# generated from genmsg/cmake/pkg-genmsg.cmake.em

message(STATUS "control_msgs: 16 messages, 0 services")

set(MSG_I_FLAGS "-Icontrol_msgs:/work/wt/tools/catkin_ws/src/control_msgs/msg;-Icontrol_msgs:/work/wt/tools/build_ninja/devel/share/control_msgs/msg;-Iactionlib_msgs:/usr/share/actionlib_msgs/msg;-Istd_msgs:/usr/share/std_msgs/cmake/../msg;-Itrajectory_msgs:/usr/share/trajectory_msgs/msg;-Igeometry_msgs:/usr/share/geometry_msgs/msg")

# Find all generators
find_package(gencpp REQUIRED)
find_package(genpy REQUIRED)

add_custom_target(control_msgs_generate_messages ALL)

# verify that message/service dependencies have not changed since configure



get_filename_component(_filename "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg" ""
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg" "control_msgs/FollowJointTrajectoryResult:control_msgs/FollowJointTrajectoryGoal:std_msgs/Header:actionlib_msgs/GoalID:control_msgs/FollowJointTrajectoryActionGoal:control_msgs/JointTolerance:control_msgs/FollowJointTrajectoryActionResult:trajectory_msgs/JointTrajectory:control_msgs/FollowJointTrajectoryActionFeedback:control_msgs/FollowJointTrajectoryFeedback:trajectory_msgs/JointTrajectoryPoint:actionlib_msgs/GoalStatus"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg" "control_msgs/FollowJointTrajectoryGoal:std_msgs/Header:actionlib_msgs/GoalID:control_msgs/JointTolerance:trajectory_msgs/JointTrajectory:trajectory_msgs/JointTrajectoryPoint"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg" "control_msgs/FollowJointTrajectoryResult:actionlib_msgs/GoalID:std_msgs/Header:actionlib_msgs/GoalStatus"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg" "std_msgs/Header:actionlib_msgs/GoalID:control_msgs/FollowJointTrajectoryFeedback:trajectory_msgs/JointTrajectoryPoint:actionlib_msgs/GoalStatus"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg" "control_msgs/JointTolerance:trajectory_msgs/JointTrajectoryPoint:std_msgs/Header:trajectory_msgs/JointTrajectory"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg" ""
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg" "trajectory_msgs/JointTrajectoryPoint:std_msgs/Header"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg" "control_msgs/GripperCommandActionResult:control_msgs/GripperCommand:std_msgs/Header:control_msgs/GripperCommandFeedback:actionlib_msgs/GoalID:actionlib_msgs/GoalStatus:control_msgs/GripperCommandActionFeedback:control_msgs/GripperCommandResult:control_msgs/GripperCommandActionGoal:control_msgs/GripperCommandGoal"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg" "actionlib_msgs/GoalID:control_msgs/GripperCommand:std_msgs/Header:control_msgs/GripperCommandGoal"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg" "actionlib_msgs/GoalID:std_msgs/Header:control_msgs/GripperCommandResult:actionlib_msgs/GoalStatus"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg" "actionlib_msgs/GoalID:std_msgs/Header:control_msgs/GripperCommandFeedback:actionlib_msgs/GoalStatus"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg" "control_msgs/GripperCommand"
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg" ""
)

get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg" NAME_WE)
add_custom_target(_control_msgs_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "control_msgs" "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg" ""
)

#
#  langs = gencpp;genpy
#

### Section generating for lang: gencpp
### Generating Messages
_generate_msg_cpp(control_msgs
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)
_generate_msg_cpp(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
)

### Generating Services

### Generating Module File
_generate_module_cpp(control_msgs
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
  "${ALL_GEN_OUTPUT_FILES_cpp}"
)

add_custom_target(control_msgs_generate_messages_cpp
  DEPENDS ${ALL_GEN_OUTPUT_FILES_cpp}
)
add_dependencies(control_msgs_generate_messages control_msgs_generate_messages_cpp)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_cpp _control_msgs_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(control_msgs_gencpp)
add_dependencies(control_msgs_gencpp control_msgs_generate_messages_cpp)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS control_msgs_generate_messages_cpp)

### Section generating for lang: genpy
### Generating Messages
_generate_msg_py(control_msgs
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg;/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg;/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/actionlib_msgs/msg/GoalID.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/actionlib_msgs/msg/GoalID.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg;/usr/share/actionlib_msgs/msg/GoalStatus.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)
_generate_msg_py(control_msgs
  "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
)

### Generating Services

### Generating Module File
_generate_module_py(control_msgs
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
  "${ALL_GEN_OUTPUT_FILES_py}"
)

add_custom_target(control_msgs_generate_messages_py
  DEPENDS ${ALL_GEN_OUTPUT_FILES_py}
)
add_dependencies(control_msgs_generate_messages control_msgs_generate_messages_py)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg" NAME_WE)
add_dependencies(control_msgs_generate_messages_py _control_msgs_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(control_msgs_genpy)
add_dependencies(control_msgs_genpy control_msgs_generate_messages_py)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS control_msgs_generate_messages_py)



if(gencpp_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs)
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/control_msgs
    DESTINATION ${gencpp_INSTALL_DIR}
  )
endif()
if(TARGET actionlib_msgs_generate_messages_cpp)
  add_dependencies(control_msgs_generate_messages_cpp actionlib_msgs_generate_messages_cpp)
endif()
if(TARGET std_msgs_generate_messages_cpp)
  add_dependencies(control_msgs_generate_messages_cpp std_msgs_generate_messages_cpp)
endif()
if(TARGET trajectory_msgs_generate_messages_cpp)
  add_dependencies(control_msgs_generate_messages_cpp trajectory_msgs_generate_messages_cpp)
endif()

if(genpy_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs)
  install(CODE "execute_process(COMMAND \"/usr/bin/python3\" -m compileall \"${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs\")")
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/control_msgs
    DESTINATION ${genpy_INSTALL_DIR}
  )
endif()
if(TARGET actionlib_msgs_generate_messages_py)
  add_dependencies(control_msgs_generate_messages_py actionlib_msgs_generate_messages_py)
endif()
if(TARGET std_msgs_generate_messages_py)
  add_dependencies(control_msgs_generate_messages_py std_msgs_generate_messages_py)
endif()
if(TARGET trajectory_msgs_generate_messages_py)
  add_dependencies(control_msgs_generate_messages_py trajectory_msgs_generate_messages_py)
endif()
