# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "/work/wt/tools/build_ninja/devel/include;/work/wt/tools/catkin_ws/src/vrrw_dmp/include".split(';') if "/work/wt/tools/build_ninja/devel/include;/work/wt/tools/catkin_ws/src/vrrw_dmp/include" != "" else []
PROJECT_CATKIN_DEPENDS = "vrrw_trajectory;message_runtime;std_msgs;trajectory_msgs".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "-lvrrw_dmp".split(';') if "-lvrrw_dmp" != "" else []
PROJECT_NAME = "vrrw_dmp"
PROJECT_SPACE_DIR = "/work/wt/tools/build_ninja/devel"
PROJECT_VERSION = "0.1.0"
PROJECT_LIB_DIR = "lib"
