# generated from catkin/cmake/template/pkg.context.pc.in
CATKIN_PACKAGE_PREFIX = ""
PROJECT_PKG_CONFIG_INCLUDE_DIRS = "/work/wt/tools/build_ninja/devel/include;/work/wt/tools/catkin_ws/src/vrrw_physics/include;/usr/include/bullet;/usr/lib/x86_64-linux-gnu/urdfdom/cmake/../../../../include".split(';') if "/work/wt/tools/build_ninja/devel/include;/work/wt/tools/catkin_ws/src/vrrw_physics/include;/usr/include/bullet;/usr/lib/x86_64-linux-gnu/urdfdom/cmake/../../../../include" != "" else []
PROJECT_CATKIN_DEPENDS = "roscpp;sensor_msgs;geometry_msgs;std_msgs;std_srvs;rosgraph_msgs;tf2_ros;message_runtime;vrrw_scene".replace(';', ' ')
PKG_CONFIG_LIBRARIES_WITH_PREFIX = "-lvrrw_physics;-lBulletDynamics;-lBulletCollision;-lLinearMath;-lBulletSoftBody;-lurdfdom_sensor;-lurdfdom_model_state;-lurdfdom_model;-lurdfdom_world;-lconsole_bridge".split(';') if "-lvrrw_physics;-lBulletDynamics;-lBulletCollision;-lLinearMath;-lBulletSoftBody;-lurdfdom_sensor;-lurdfdom_model_state;-lurdfdom_model;-lurdfdom_world;-lconsole_bridge" != "" else []
PROJECT_NAME = "vrrw_physics"
PROJECT_SPACE_DIR = "/work/wt/tools/build_ninja/devel"
PROJECT_VERSION = "0.1.0"
PROJECT_LIB_DIR = "lib"
