# Install script for directory: /work/wt/tools/catkin_ws/src/control_msgs

# Set the install prefix
if(NOT DEFINED CMAKE_INSTALL_PREFIX)
  set(CMAKE_INSTALL_PREFIX "/usr/local")
endif()
string(REGEX REPLACE "/$" "" CMAKE_INSTALL_PREFIX "${CMAKE_INSTALL_PREFIX}")

# Set the install configuration name.
if(NOT DEFINED CMAKE_INSTALL_CONFIG_NAME)
  if(BUILD_TYPE)
    string(REGEX REPLACE "^[^A-Za-z0-9_]+" ""
           CMAKE_INSTALL_CONFIG_NAME "${BUILD_TYPE}")
  else()
    set(CMAKE_INSTALL_CONFIG_NAME "Release")
  endif()
  message(STATUS "Install configuration: \"${CMAKE_INSTALL_CONFIG_NAME}\"")
endif()

# Set the component getting installed.
if(NOT CMAKE_INSTALL_COMPONENT)
  if(COMPONENT)
    message(STATUS "Install component: \"${COMPONENT}\"")
    set(CMAKE_INSTALL_COMPONENT "${COMPONENT}")
  else()
    set(CMAKE_INSTALL_COMPONENT)
  endif()
endif()

# Install shared libraries without execute permission?
if(NOT DEFINED CMAKE_INSTALL_SO_NO_EXE)
  set(CMAKE_INSTALL_SO_NO_EXE "1")
endif()

# Is this installation the result of a crosscompile?
if(NOT DEFINED CMAKE_CROSSCOMPILING)
  set(CMAKE_CROSSCOMPILING "FALSE")
endif()

# Set default install directory permissions.
if(NOT DEFINED CMAKE_OBJDUMP)
  set(CMAKE_OBJDUMP "/usr/bin/objdump")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs/msg" TYPE FILE FILES
    "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg"
    "/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg"
    )
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs/action" TYPE FILE FILES
    "/work/wt/tools/catkin_ws/src/control_msgs/action/FollowJointTrajectory.action"
    "/work/wt/tools/catkin_ws/src/control_msgs/action/GripperCommand.action"
    )
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs/msg" TYPE FILE FILES
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg"
    )
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs/msg" TYPE FILE FILES
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg"
    "/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg"
    )
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs/cmake" TYPE FILE FILES "/work/wt/tools/build_ninja/catkin_ws/src/control_msgs/catkin_generated/installspace/control_msgs-msg-paths.cmake")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/include" TYPE DIRECTORY FILES "/work/wt/tools/build_ninja/devel/include/control_msgs")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  execute_process(COMMAND "/usr/bin/python3" -m compileall "/work/wt/tools/build_ninja/devel/lib/python3/dist-packages/control_msgs")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/python3/dist-packages" TYPE DIRECTORY FILES "/work/wt/tools/build_ninja/devel/lib/python3/dist-packages/control_msgs")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/pkgconfig" TYPE FILE FILES "/work/wt/tools/build_ninja/catkin_ws/src/control_msgs/catkin_generated/installspace/control_msgs.pc")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs/cmake" TYPE FILE FILES "/work/wt/tools/build_ninja/catkin_ws/src/control_msgs/catkin_generated/installspace/control_msgs-msg-extras.cmake")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs/cmake" TYPE FILE FILES
    "/work/wt/tools/build_ninja/catkin_ws/src/control_msgs/catkin_generated/installspace/control_msgsConfig.cmake"
    "/work/wt/tools/build_ninja/catkin_ws/src/control_msgs/catkin_generated/installspace/control_msgsConfig-version.cmake"
    )
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/control_msgs" TYPE FILE FILES "/work/wt/tools/catkin_ws/src/control_msgs/package.xml")
endif()

