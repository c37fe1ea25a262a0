# generated from genmsg/cmake/pkg-genmsg.context.in

messages_str = ""
services_str = "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv;/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv"
pkg_name = "vrrw_dmp"
dependencies_str = "std_msgs;trajectory_msgs"
langs = "gencpp;genpy"
dep_include_paths_str = "std_msgs;/usr/share/std_msgs/cmake/../msg;trajectory_msgs;/usr/share/trajectory_msgs/msg;geometry_msgs;/usr/share/geometry_msgs/msg"
PYTHON_EXECUTABLE = "/usr/bin/python3"
package_has_static_sources = '' == 'TRUE'
genmsg_check_deps_script = "/usr/lib/genmsg/genmsg_check_deps.py"
