# generated from genmsg/cmake/pkg-genmsg.cmake.em

message(STATUS "vrrw_physics: 4 messages, 4 services")

set(MSG_I_FLAGS "-Ivrrw_physics:/work/wt/tools/catkin_ws/src/vrrw_physics/msg;-Igeometry_msgs:/usr/share/geometry_msgs/msg;-Istd_msgs:/usr/share/std_msgs/cmake/../msg")

# Find all generators
find_package(gencpp REQUIRED)
find_package(genpy REQUIRED)

add_custom_target(vrrw_physics_generate_messages ALL)

# verify that message/service dependencies have not changed since configure



get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg" "geometry_msgs/Point"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contacts.msg" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contacts.msg" "vrrw_physics/Contact:std_msgs/Header:geometry_msgs/Point"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Hand.msg" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Hand.msg" "geometry_msgs/Point:geometry_msgs/Quaternion:geometry_msgs/Pose"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/SpringTarget.msg" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/SpringTarget.msg" "geometry_msgs/Point:geometry_msgs/Quaternion:geometry_msgs/Pose:geometry_msgs/Vector3"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetMode.srv" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetMode.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetGains.srv" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetGains.srv" ""
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetSpring.srv" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetSpring.srv" "geometry_msgs/Point:geometry_msgs/Quaternion:geometry_msgs/Pose"
)

get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetObjectPose.srv" NAME_WE)
add_custom_target(_vrrw_physics_generate_messages_check_deps_${_filename}
  COMMAND ${CATKIN_ENV} ${PYTHON_EXECUTABLE} ${GENMSG_CHECK_DEPS_SCRIPT} "vrrw_physics" "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetObjectPose.srv" "geometry_msgs/Point:geometry_msgs/Quaternion:geometry_msgs/Pose"
)

#
#  langs = gencpp;genpy
#

### Section generating for lang: gencpp
### Generating Messages
_generate_msg_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)
_generate_msg_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contacts.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/Point.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)
_generate_msg_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Hand.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)
_generate_msg_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/SpringTarget.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/geometry_msgs/msg/Vector3.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)

### Generating Services
_generate_srv_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetMode.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)
_generate_srv_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetGains.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)
_generate_srv_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetSpring.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)
_generate_srv_cpp(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetObjectPose.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg"
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
)

### Generating Module File
_generate_module_cpp(vrrw_physics
  ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
  "${ALL_GEN_OUTPUT_FILES_cpp}"
)

add_custom_target(vrrw_physics_generate_messages_cpp
  DEPENDS ${ALL_GEN_OUTPUT_FILES_cpp}
)
add_dependencies(vrrw_physics_generate_messages vrrw_physics_generate_messages_cpp)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contacts.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Hand.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/SpringTarget.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetMode.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetGains.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetSpring.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetObjectPose.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_cpp _vrrw_physics_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(vrrw_physics_gencpp)
add_dependencies(vrrw_physics_gencpp vrrw_physics_generate_messages_cpp)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS vrrw_physics_generate_messages_cpp)

### Section generating for lang: genpy
### Generating Messages
_generate_msg_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)
_generate_msg_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contacts.msg"
  "${MSG_I_FLAGS}"
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg;/usr/share/std_msgs/cmake/../msg/Header.msg;/usr/share/geometry_msgs/msg/Point.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)
_generate_msg_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Hand.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)
_generate_msg_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/SpringTarget.msg"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg;/usr/share/geometry_msgs/msg/Vector3.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)

### Generating Services
_generate_srv_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetMode.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)
_generate_srv_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetGains.srv"
  "${MSG_I_FLAGS}"
  ""
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)
_generate_srv_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetSpring.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)
_generate_srv_py(vrrw_physics
  "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetObjectPose.srv"
  "${MSG_I_FLAGS}"
  "/usr/share/geometry_msgs/msg/Point.msg;/usr/share/geometry_msgs/msg/Quaternion.msg;/usr/share/geometry_msgs/msg/Pose.msg"
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
)

### Generating Module File
_generate_module_py(vrrw_physics
  ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
  "${ALL_GEN_OUTPUT_FILES_py}"
)

add_custom_target(vrrw_physics_generate_messages_py
  DEPENDS ${ALL_GEN_OUTPUT_FILES_py}
)
add_dependencies(vrrw_physics_generate_messages vrrw_physics_generate_messages_py)

# add dependencies to all check dependencies targets
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contacts.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Hand.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/SpringTarget.msg" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetMode.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetGains.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetSpring.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})
get_filename_component(_filename "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetObjectPose.srv" NAME_WE)
add_dependencies(vrrw_physics_generate_messages_py _vrrw_physics_generate_messages_check_deps_${_filename})

# target for backward compatibility
add_custom_target(vrrw_physics_genpy)
add_dependencies(vrrw_physics_genpy vrrw_physics_generate_messages_py)

# register target for catkin_package(EXPORTED_TARGETS)
list(APPEND ${PROJECT_NAME}_EXPORTED_TARGETS vrrw_physics_generate_messages_py)



if(gencpp_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics)
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${gencpp_INSTALL_DIR}/vrrw_physics
    DESTINATION ${gencpp_INSTALL_DIR}
  )
endif()
if(TARGET geometry_msgs_generate_messages_cpp)
  add_dependencies(vrrw_physics_generate_messages_cpp geometry_msgs_generate_messages_cpp)
endif()
if(TARGET std_msgs_generate_messages_cpp)
  add_dependencies(vrrw_physics_generate_messages_cpp std_msgs_generate_messages_cpp)
endif()

if(genpy_INSTALL_DIR AND EXISTS ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics)
  install(CODE "execute_process(COMMAND \"/usr/bin/python3\" -m compileall \"${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics\")")
  # install generated code
  install(
    DIRECTORY ${CATKIN_DEVEL_PREFIX}/${genpy_INSTALL_DIR}/vrrw_physics
    DESTINATION ${genpy_INSTALL_DIR}
  )
endif()
if(TARGET geometry_msgs_generate_messages_py)
  add_dependencies(vrrw_physics_generate_messages_py geometry_msgs_generate_messages_py)
endif()
if(TARGET std_msgs_generate_messages_py)
  add_dependencies(vrrw_physics_generate_messages_py std_msgs_generate_messages_py)
endif()
