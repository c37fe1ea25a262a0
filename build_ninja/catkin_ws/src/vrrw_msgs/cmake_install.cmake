# Install script for directory: /work/wt/tools/catkin_ws/src/vrrw_msgs

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
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/vrrw_msgs/msg" TYPE FILE FILES "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/vrrw_msgs/srv" TYPE FILE FILES
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv"
    "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv"
    )
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/vrrw_msgs/cmake" TYPE FILE FILES "/work/wt/tools/build_ninja/catkin_ws/src/vrrw_msgs/catkin_generated/installspace/vrrw_msgs-msg-paths.cmake")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/include" TYPE DIRECTORY FILES "/work/wt/tools/build_ninja/devel/include/vrrw_msgs")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  execute_process(COMMAND "/usr/bin/python3" -m compileall "/work/wt/tools/build_ninja/devel/lib/python3/dist-packages/vrrw_msgs")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/python3/dist-packages" TYPE DIRECTORY FILES "/work/wt/tools/build_ninja/devel/lib/python3/dist-packages/vrrw_msgs")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/pkgconfig" TYPE FILE FILES "/work/wt/tools/build_ninja/catkin_ws/src/vrrw_msgs/catkin_generated/installspace/vrrw_msgs.pc")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/vrrw_msgs/cmake" TYPE FILE FILES "/work/wt/tools/build_ninja/catkin_ws/src/vrrw_msgs/catkin_generated/installspace/vrrw_msgs-msg-extras.cmake")
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/vrrw_msgs/cmake" TYPE FILE FILES
    "/work/wt/tools/build_ninja/catkin_ws/src/vrrw_msgs/catkin_generated/installspace/vrrw_msgsConfig.cmake"
    "/work/wt/tools/build_ninja/catkin_ws/src/vrrw_msgs/catkin_generated/installspace/vrrw_msgsConfig-version.cmake"
    )
endif()

if(CMAKE_INSTALL_COMPONENT STREQUAL "Unspecified" OR NOT CMAKE_INSTALL_COMPONENT)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/share/vrrw_msgs" TYPE FILE FILES "/work/wt/tools/catkin_ws/src/vrrw_msgs/package.xml")
endif()

