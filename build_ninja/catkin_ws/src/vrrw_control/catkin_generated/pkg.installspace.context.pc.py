# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "\${prefix}/include".split(';') if "\${prefix}/include" != "" else []
PROJECT_CATKIN_DEPENDS = "vrrw_trajectory;vrrw_scene;vrrw_msgs;roscpp;actionlib;control_msgs;sensor_msgs;std_msgs;std_srvs;trajectory_msgs".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "-lvrrw_control;-lvrrw_control_ros".split(';') if "-lvrrw_control;-lvrrw_control_ros" != "" else []
PROJECT_NAME = "vrrw_control"
PROJECT_SPACE_DIR = "/usr/local"
PROJECT_VERSION = "0.1.0"
PROJECT_LIB_DIR = "lib"
