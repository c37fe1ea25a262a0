# generated from genmsg/cmake/pkg-genmsg.context.in

messages_str = "/work/wt/tools/catkin_ws/src/vrrw_msgs/msg/Event.msg"
services_str = "/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeFK.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/ComputeIK.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/CheckState.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/Plan.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/AttachObject.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetJoints.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSetPose.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPreset.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostPlan.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostExecute.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/GhostSupportSurface.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStart.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoStop.srv;/work/wt/tools/catkin_ws/src/vrrw_msgs/srv/DemoAnnotate.srv"
pkg_name = "vrrw_msgs"
dependencies_str = "std_msgs;geometry_msgs;sensor_msgs;trajectory_msgs"
langs = "gencpp;genpy"
dep_include_paths_str = "vrrw_msgs;/work/wt/tools/catkin_ws/src/vrrw_msgs/msg;std_msgs;/usr/share/std_msgs/cmake/../msg;geometry_msgs;/usr/share/geometry_msgs/msg;sensor_msgs;/usr/share/sensor_msgs/msg;trajectory_msgs;/usr/share/trajectory_msgs/msg"
PYTHON_EXECUTABLE = "/usr/bin/python3"
package_has_static_sources = '' == 'TRUE'
genmsg_check_deps_script = "/usr/lib/genmsg/genmsg_check_deps.py"
