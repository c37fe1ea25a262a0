# CMake generated Testfile for 
# Source directory: /work/wt/tools/catkin_ws/src/vrrw_msgs
# Build directory: /work/wt/tools/build_ninja/catkin_ws/src/vrrw_msgs
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
