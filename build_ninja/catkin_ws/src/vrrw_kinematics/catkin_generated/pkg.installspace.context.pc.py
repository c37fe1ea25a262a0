# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "\${prefix}/include;/usr/lib/x86_64-linux-gnu/urdfdom/cmake/../../../../include".split(';') if "\${prefix}/include;/usr/lib/x86_64-linux-gnu/urdfdom/cmake/../../../../include" != "" else []
PROJECT_CATKIN_DEPENDS = "geometry_msgs;roscpp;sensor_msgs;tf2_ros;trajectory_msgs;vrrw_msgs;vrrw_scene;vrrw_trajectory".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "-lvrrw_kinematics;-lurdfdom_sensor;-lurdfdom_model_state;-lurdfdom_model;-lurdfdom_world;-lconsole_bridge".split(';') if "-lvrrw_kinematics;-lurdfdom_sensor;-lurdfdom_model_state;-lurdfdom_model;-lurdfdom_world;-lconsole_bridge" != "" else []
PROJECT_NAME = "vrrw_kinematics"
PROJECT_SPACE_DIR = "/usr/local"
PROJECT_VERSION = "0.1.0"
PROJECT_LIB_DIR = "lib"
