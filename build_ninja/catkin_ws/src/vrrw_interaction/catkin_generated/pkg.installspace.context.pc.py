# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "\${prefix}/include".split(';') if "\${prefix}/include" != "" else []
PROJECT_CATKIN_DEPENDS = "vrrw_scene;vrrw_kinematics".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "-lvrrw_interaction".split(';') if "-lvrrw_interaction" != "" else []
PROJECT_NAME = "vrrw_interaction"
PROJECT_SPACE_DIR = "/usr/local"
PROJECT_VERSION = "0.1.0"
PROJECT_LIB_DIR = "lib"
