// physics_node: steps a vrrw_physics::PhysicsWorld of the scene in ~scene with every robot's controller
// loaded into it (lockstep), at a real-time factor; wires it to ROS (src/ros/physics_node.h).
//   publishes  /<robot>/joint_states, /joint_states (all robots), one tf message (the robots' moving joints'
//              frames unless ~robot_tf is false, world -> <object>), ~contacts at ~publish_rate; /clock at ~clock_rate; ~errors (std_msgs/String, latched)
//   subscribes ~hand (vrrw_physics/Hand), ~spring_target (vrrw_physics/SpringTarget): applied at header.stamp;
//              each acknowledged on ~input_queued (std_msgs/Header, "hand <id>" / "spring_target <id>", its stamp)
//   services   ~pause ~unpause (std_srvs/Empty), ~step (vrrw_physics/Step), ~reset (std_srvs/Trigger),
//              ~set_mode, ~set_gains, ~set_spring, ~set_object_pose (vrrw_physics/*)
#include <vrrw_scene/scene_loader.h>

#include "physics_node.h"

namespace
{
vrrw_physics::WorldOptions readWorldOptions(ros::NodeHandle& pnh)
{
  vrrw_physics::WorldOptions options;
  pnh.param("dt", options.dt, options.dt);
  pnh.param("solver_iterations", options.solver_iterations, options.solver_iterations);
  pnh.param("solver_inner_iterations", options.solver_inner_iterations, options.solver_inner_iterations);
  pnh.param("gravity_compensation", options.gravity_compensation, options.gravity_compensation);
  pnh.param("target_timeout", options.target_timeout, options.target_timeout);
  pnh.param("hand_timeout", options.hand_timeout, options.hand_timeout);
  options.mode = vrrw_physics::parseDriveMode(pnh.param<std::string>("mode", "rigid"));
  options.drive_scheme = vrrw_physics::parseDriveScheme(pnh.param<std::string>("drives", "constraint"));
  return options;
}

/// ~rtf: "max" or a positive number (a launch file gives either text or a number).
double readRealTimeFactor(ros::NodeHandle& pnh)
{
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam("rtf", value))
    return 1.0;
  std::string text;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeString)
    text = static_cast<std::string>(value);
  else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt)
    text = std::to_string(static_cast<int>(value));
  else if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble)
    text = std::to_string(static_cast<double>(value));
  return vrrw_physics::parseRealTimeFactor(text, "~rtf");
}

vrrw_physics::NodeOptions readNodeOptions(ros::NodeHandle& pnh)
{
  vrrw_physics::NodeOptions options;
  options.rtf = readRealTimeFactor(pnh);
  pnh.param("publish_rate", options.publish_rate, options.publish_rate);
  pnh.param("clock_rate", options.clock_rate, options.clock_rate);
  pnh.param("paused", options.paused, options.paused);
  pnh.param("robot_tf", options.robot_tf, options.robot_tf);
  pnh.param("controller", options.controller, options.controller);
  if (!(options.publish_rate > 0.0))
    throw std::invalid_argument("~publish_rate: must be > 0 Hz");
  if (!(options.clock_rate >= 0.0))
    throw std::invalid_argument("~clock_rate: must be >= 0 Hz (0: every step)");
  return options;
}
}  // namespace

int main(int argc, char** argv)
{
  // The node is the clock: its own ROS internals (actionlib's status timers, waits) run on the wall clock, or a
  // paused simulation would stop them; its controllers get the simulated time explicitly. So /use_sim_time,
  // which the nodes beside it read, is looked up here under a name nobody sets.
  std::vector<char*> args(argv, argv + argc);
  char wall_clock[] = "/use_sim_time:=/physics_node/runs_on_the_wall_clock";
  args.push_back(wall_clock);
  int count = int(args.size());
  ros::init(count, args.data(), "physics_node");
  ros::NodeHandle nh, pnh("~");
  std::string scene_name;
  if (!pnh.getParam("scene", scene_name))
  {
    ROS_FATAL("physics_node: ~scene: missing (a shipped scene name or a scene YAML path)");
    return 2;
  }
  try
  {
    const vrrw_physics::WorldOptions world_options = readWorldOptions(pnh);
    const vrrw_physics::NodeOptions options = readNodeOptions(pnh);
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(scene_name);
    vrrw_physics::PhysicsNode node(nh, pnh, scene, world_options, options);
    ROS_INFO_STREAM("physics_node: scene " << scene.name << ", " << scene.robots.size() << " robots, "
                                           << scene.objects.size() << " objects, dt " << world_options.dt
                                           << " s, rtf " << options.rtf << (options.paused ? ", paused" : ""));
    node.run();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM("physics_node: " << e.what());
    return 1;
  }
  return 0;
}
