// interaction_node: the operator's handles on every arm of a scene (ghost-drive, markers, free-drive).
#include <ros/ros.h>
#include <vrrw_scene/scene_loader.h>

#include "free_drive.h"
#include "ghost_marker.h"

using namespace vrrw_interaction;

int main(int argc, char** argv)
{
  ros::init(argc, argv, "interaction");
  ros::NodeHandle pnh("~");
  const std::string scene_name = pnh.param<std::string>("scene", "");
  const std::string mode = pnh.param<std::string>("mode", "fake");
  const std::string presets =
      pnh.param<std::string>("presets", vrrw_scene::vrrwRoot() + "/urdf/config/presets.yaml");
  const double marker_rate = pnh.param("marker_rate", 200.0);
  const double max_jump = pnh.param("max_jump", 0.5);
  if (mode != "fake" && mode != "physics" && mode != "none")
    ROS_ERROR_STREAM("~mode: '" << mode << "' is not fake, physics or none; free-drive acts as in fake mode");
  vrrw_scene::Scene scene;
  try
  {
    scene = vrrw_scene::loadScene(scene_name);
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM("~scene: " << e.what());
    return 1;
  }
  ros::NodeHandle nh;
  WorldView view(nh, scene, mode);
  std::vector<std::string> robots = pnh.param("robots", std::vector<std::string>());
  if (robots.empty())
    for (const vrrw_scene::Robot& robot : scene.robots)
      robots.push_back(robot.name);
  std::vector<std::unique_ptr<GhostInterface>> ghosts;
  std::vector<GhostInterface*> arms;
  for (const std::string& name : robots)
  {
    const vrrw_scene::Robot* robot = scene.robot(name);
    if (!robot)
    {
      ROS_ERROR_STREAM("~robots: unknown robot '" << name << "' in scene " << scene.name << " (skipped)");
      continue;
    }
    try
    {
      ghosts.push_back(std::make_unique<GhostInterface>(view, *robot, presets));
      arms.push_back(ghosts.back().get());
    }
    catch (const std::exception& e)
    {
      ROS_ERROR_STREAM("robot " << name << ": " << e.what() << " (no ghost for it)");
    }
  }
  // a grip on a link carries its orientation too (README: the wrist within 2 deg over the drag benchmark)
  FreeDrive free_drive(view, arms, pnh.param("grab_distance", 0.05), pnh.param("hand_radius", 0.04),
                       pnh.param("grip_angular_stiffness", 500.0), pnh.param("grip_angular_damping", 5.0));
  GhostMarkers markers(view, arms, marker_rate, max_jump,
                       [&free_drive](const std::string& robot, bool on) {
                         if (const std::string error = free_drive.set(robot, on); !error.empty())
                           ROS_WARN_STREAM(robot << " free-drive: " << error);
                       });
  // the ghosts on tf (ghost/<link>), where rviz's "Ghosts" RobotModel and the render draw them
  // at 30 Hz when a ghost (or a gripper) moved, else once a second
  Eigen::VectorXd published;
  ros::WallTime last_published;
  ros::Timer frames = nh.createTimer(ros::Duration(1.0 / 30.0), [&](const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(view.mutex());
    Eigen::VectorXd state = view.liveState();
    for (GhostInterface* ghost : arms)
      ghost->ghostInto(state);
    if (published.size() == state.size() && (published - state).cwiseAbs().maxCoeff() < 1e-9 &&
        ros::WallTime::now() - last_published < ros::WallDuration(1.0))
      return;
    view.publishGhostFrames(state);
    published = state;
    last_published = ros::WallTime::now();
  });
  ROS_INFO_STREAM("interaction: " << arms.size() << " arms of " << scene.name << " (" << mode << " mode)");
  ros::AsyncSpinner spinner(4);
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
