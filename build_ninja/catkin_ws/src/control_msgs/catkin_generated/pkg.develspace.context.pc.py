# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "/work/wt/tools/build_ninja/devel/include".split(';') if "/work/wt/tools/build_ninja/devel/include" != "" else []
PROJECT_CATKIN_DEPENDS = "actionlib_msgs;message_runtime;std_msgs;trajectory_msgs".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "".split(';') if "" != "" else []
PROJECT_NAME = "control_msgs"
PROJECT_SPACE_DIR = "/work/wt/tools/build_ninja/devel"
PROJECT_VERSION = "1.5.2"
PROJECT_LIB_DIR = "lib"
