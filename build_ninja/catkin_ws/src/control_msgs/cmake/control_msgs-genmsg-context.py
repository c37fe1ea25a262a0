# generated from genmsg/cmake/pkg-genmsg.context.in

messages_str = "/work/wt/tools/catkin_ws/src/control_msgs/msg/GripperCommand.msg;/work/wt/tools/catkin_ws/src/control_msgs/msg/JointTolerance.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryAction.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionGoal.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryActionFeedback.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryGoal.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/FollowJointTrajectoryFeedback.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandAction.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionGoal.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandActionFeedback.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandGoal.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandResult.msg;/work/wt/tools/build_ninja/devel/share/control_msgs/msg/GripperCommandFeedback.msg"
services_str = ""
pkg_name = "control_msgs"
dependencies_str = "actionlib_msgs;std_msgs;trajectory_msgs"
langs = "gencpp;genpy"
dep_include_paths_str = "control_msgs;/work/wt/tools/catkin_ws/src/control_msgs/msg;control_msgs;/work/wt/tools/build_ninja/devel/share/control_msgs/msg;actionlib_msgs;/usr/share/actionlib_msgs/msg;std_msgs;/usr/share/std_msgs/cmake/../msg;trajectory_msgs;/usr/share/trajectory_msgs/msg;geometry_msgs;/usr/share/geometry_msgs/msg"
PYTHON_EXECUTABLE = "/usr/bin/python3"
package_has_static_sources = '' == 'TRUE'
genmsg_check_deps_script = "/usr/lib/genmsg/genmsg_check_deps.py"
