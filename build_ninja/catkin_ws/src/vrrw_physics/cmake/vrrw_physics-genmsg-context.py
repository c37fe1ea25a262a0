# generated from genmsg/cmake/pkg-genmsg.context.in

messages_str = "/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contact.msg;/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Contacts.msg;/work/wt/tools/catkin_ws/src/vrrw_physics/msg/Hand.msg;/work/wt/tools/catkin_ws/src/vrrw_physics/msg/SpringTarget.msg"
services_str = "/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetMode.srv;/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetGains.srv;/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetSpring.srv;/work/wt/tools/catkin_ws/src/vrrw_physics/srv/SetObjectPose.srv"
pkg_name = "vrrw_physics"
dependencies_str = "geometry_msgs;std_msgs"
langs = "gencpp;genpy"
dep_include_paths_str = "vrrw_physics;/work/wt/tools/catkin_ws/src/vrrw_physics/msg;geometry_msgs;/usr/share/geometry_msgs/msg;std_msgs;/usr/share/std_msgs/cmake/../msg"
PYTHON_EXECUTABLE = "/usr/bin/python3"
package_has_static_sources = '' == 'TRUE'
genmsg_check_deps_script = "/usr/lib/genmsg/genmsg_check_deps.py"
