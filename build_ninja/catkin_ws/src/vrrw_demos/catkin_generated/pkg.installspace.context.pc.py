# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "\${prefix}/include".split(';') if "\${prefix}/include" != "" else []
PROJECT_CATKIN_DEPENDS = "vrrw_trajectory".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "-lvrrw_demos".split(';') if "-lvrrw_demos" != "" else []
PROJECT_NAME = "vrrw_demos"
PROJECT_SPACE_DIR = "/usr/local"
PROJECT_VERSION = "0.1.0"
PROJECT_LIB_DIR = "lib"
