// controller_node: FollowJointTrajectory, GripperCommand and the command topic of one robot, in its
// namespace, in fake or real mode (physics mode runs the same controllers inside physics_node: the
// vrrw_control/PhysicsController plugin). Reads parameters and runs the control loop (controller_loop.h).
#include <ros/ros.h>
#include <vrrw_control/ros/controller_loop.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "controller_node");
  ros::NodeHandle nh, pnh("~");
  const std::string ns = nh.getNamespace();
  const std::string name = pnh.param<std::string>("robot", ns.substr(ns.find_last_of('/') + 1));
  const std::string mode = pnh.param<std::string>("mode", "fake");
  const double rate_hz = pnh.param("rate", 100.0);
  if (mode == "physics")
  {
    ROS_FATAL_STREAM("~mode: physics runs the controllers inside physics_node (its ~controller parameter: "
                     "vrrw_control/PhysicsController); controller_node runs fake and real");
    return 2;
  }
  if (mode != "fake" && mode != "real")
  {
    ROS_FATAL_STREAM("~mode: '" << mode << "' is not one of fake, real");
    return 2;
  }
  if (!(rate_hz > 0.0 && rate_hz <= 1000.0))
  {
    ROS_FATAL_STREAM("~rate: " << rate_hz << " Hz outside (0, 1000]");
    return 2;
  }
  try
  {
    vrrw_control::ControllerLoop loop(nh, pnh, name, mode, rate_hz);
    loop.spin();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM(e.what());
    return 2;
  }
  return 0;
}
