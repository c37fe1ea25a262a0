# CMake generated Testfile for 
# Source directory: /work/wt/tools/catkin_ws/src
# Build directory: /work/wt/tools/build_ninja/catkin_ws/src
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
subdirs("control_msgs")
subdirs("vrrw_common")
subdirs("vrrw_msgs")
subdirs("vrrw_bringup")
subdirs("vrrw_scene")
subdirs("vrrw_physics")
subdirs("vrrw_trajectory")
subdirs("vrrw_dmp")
subdirs("vrrw_kinematics")
subdirs("vrrw_control")
subdirs("vrrw_demos")
subdirs("vrrw_evaluation")
subdirs("vrrw_interaction")
subdirs("vrrw_viz")
