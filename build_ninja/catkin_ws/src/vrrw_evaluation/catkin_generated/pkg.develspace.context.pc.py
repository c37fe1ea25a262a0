# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "/work/wt/tools/catkin_ws/src/vrrw_evaluation/include".split(';') if "/work/wt/tools/catkin_ws/src/vrrw_evaluation/include" != "" else []
PROJECT_CATKIN_DEPENDS = "vrrw_trajectory;vrrw_dmp".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "-lvrrw_evaluation".split(';') if "-lvrrw_evaluation" != "" else []
PROJECT_NAME = "vrrw_evaluation"
PROJECT_SPACE_DIR = "/work/wt/tools/build_ninja/devel"
PROJECT_VERSION = "0.1.0"
PROJECT_LIB_DIR = "lib"
