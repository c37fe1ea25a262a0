// planning_node: FK, IK, state checks and motion planning for every robot of a scene, as services
// under /<robot>/; live joint states from /joint_states. Parameters: ~scene (a shipped scene name or YAML
// path), ~seed (OMPL's process seed, default 1), ~stale_after (s, default 1: answers taken from a robot's
// live state older than this carry a warning in their message).
#include <memory>
#include <ompl/util/RandomNumbers.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_listener.h>
#include <vrrw_scene/scene_loader.h>

#include "../src/ros/robot_services.h"
#include "../src/ros/scene_context.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "planning_node");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  std::string scene_name;
  if (!private_nh.getParam("scene", scene_name))
  {
    ROS_FATAL("planning_node: parameter ~scene (scene name or YAML path) is required");
    return 2;
  }
  int seed = 1;
  private_nh.param("seed", seed, 1);
  double stale_after = 1.0;
  private_nh.param("stale_after", stale_after, 1.0);
  if (!(stale_after > 0.0))
  {
    ROS_FATAL_STREAM("planning_node: ~stale_after: " << stale_after << " s: must be positive");
    return 2;
  }
  ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));
  tf2_ros::Buffer tf;
  tf2_ros::TransformListener listener(tf);
  std::unique_ptr<vrrw_kinematics::SceneContext> context;
  std::vector<std::unique_ptr<vrrw_kinematics::RobotServices>> robots;
  try
  {
    context = std::make_unique<vrrw_kinematics::SceneContext>(vrrw_scene::loadScene(scene_name), tf);
    for (const vrrw_scene::Robot& robot : context->scene().robots)
      robots.push_back(std::make_unique<vrrw_kinematics::RobotServices>(nh, robot, *context, stale_after));
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM("planning_node: " << e.what());
    return 2;
  }
  const ros::Subscriber joint_states = nh.subscribe<sensor_msgs::JointState>(
      "/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr& msg) { context->updateLive(*msg); });
  ROS_INFO_STREAM("planning_node: scene " << context->scene().name << ", " << robots.size() << " robots, "
                                          << context->world().acm().size() << " allowed pairs");
  ros::spin();
  return 0;
}
