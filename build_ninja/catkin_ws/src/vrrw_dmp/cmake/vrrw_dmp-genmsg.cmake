# generated from genmsg/cmake/pkg-genmsg.cmake.em

message(STATUS "vrrw_dmp: 0 messages, 2 services")

set(MSG_I_FLAGS "-Istd_msgs:/usr/share/std_msgs/cmake/../msg;-Itrajectory_msgs:/usr/share/trajectory_msgs/msg;-Igeometry_msgs:/usr/share/geometry_msgs/msg")

# Find all generators
find_package(gencpp REQUIRED)
find_package(genpy REQUIRED)

add_custom_target(vrrw_dmp_generate_messages ALL)

# verify that message/service dependencies have not changed since configure



get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv" NAME_WE)
add_custom_target(_vrrw_dmp_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_dmp" "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv" "trajectory_msgs/JointTrajectoryPoint:trajectory_msgs/JointTrajectory:std_msgs/Header"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv" NAME_WE)
add_custom_target(_vrrw_dmp_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_dmp" "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv" "trajectory_msgs/JointTrajectoryPoint:trajectory_msgs/JointTrajectory:std_msgs/Header"
)

#
#  langs = gencpp;genpy
#

### Section generating for lang: gencpp
### Generating Messages

### Generating Services
_generate_srv_cpp(vrrw_dmp
  "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_dmp
)
_generate_srv_cpp(vrrw_dmp
  "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_dmp
)

### Generating Module File
_generate_module_cpp(vrrw_dmp
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_dmp
  "${ALL_GEN_OUTPUT_FILES_cpp}"
)

add_custom_target(vrrw_dmp_generate_messages_cpp
  DEPENDS ${ALL_GEN_OUTPUT_FILES_cpp}
)
add_dependencies(vrrw_dmp_generate_messages vrrw_dmp_generate_messages_cpp)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv" NAME_WE)
add_dependencies(vrrw_dmp_generate_messages_cpp _vrrw_dmp_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv" NAME_WE)
add_dependencies(vrrw_dmp_generate_messages_cpp _vrrw_dmp_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(vrrw_dmp_gencpp)
add_dependencies(vrrw_dmp_gencpp vrrw_dmp_generate_messages_cpp)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS vrrw_dmp_generate_messages_cpp)

### Section generating for lang: genpy
### Generating Messages

### Generating Services
_generate_srv_py(vrrw_dmp
  "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_dmp
)
_generate_srv_py(vrrw_dmp
  "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/trajectory_msgs/msg/JointTrajectoryPoint.msg;/usr/share/trajectory_msgs/msg/JointTrajectory.msg;/usr/share/std_msgs/cmake/../msg/Header.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_dmp
)

### Generating Module File
_generate_module_py(vrrw_dmp
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_dmp
  "${ALL_GEN_OUTPUT_FILES_py}"
)

add_custom_target(vrrw_dmp_generate_messages_py
  DEPENDS ${ALL_GEN_OUTPUT_FILES_py}
)
add_dependencies(vrrw_dmp_generate_messages vrrw_dmp_generate_messages_py)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv" NAME_WE)
add_dependencies(vrrw_dmp_generate_messages_py _vrrw_dmp_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv" NAME_WE)
add_dependencies(vrrw_dmp_generate_messages_py _vrrw_dmp_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(vrrw_dmp_genpy)
add_dependencies(vrrw_dmp_genpy vrrw_dmp_generate_messages_py)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS vrrw_dmp_generate_messages_py)



if(gencpp_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_dmp)
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_dmp
    DESTINATION ${gencpp_INSTALL_DIR}
  )
endif()
if(TARGET std_msgs_generate_messages_cpp)
  add_dependencies(vrrw_dmp_generate_messages_cpp std_msgs_generate_messages_cpp)
endif()
if(TARGET trajectory_msgs_generate_messages_cpp)
  add_dependencies(vrrw_dmp_generate_messages_cpp trajectory_msgs_generate_messages_cpp)
endif()

if(genpy_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_dmp)
  install(CODE "execute_process(COMMAND \"/usr/bin/python3\" -m compileall \"${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_dmp\")")
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_dmp
    DESTINATION ${genpy_INSTALL_DIR}
  )
endif()
if(TARGET std_msgs_generate_messages_py)
  add_dependencies(vrrw_dmp_generate_messages_py std_msgs_generate_messages_py)
endif()
if(TARGET trajectory_msgs_generate_messages_py)
  add_dependencies(vrrw_dmp_generate_messages_py trajectory_msgs_generate_messages_py)
endif()
