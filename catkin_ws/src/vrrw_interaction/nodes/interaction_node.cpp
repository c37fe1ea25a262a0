// interaction_node: the operator's handles on every arm of a scene (ghost-drive, markers, free-drive).
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <vrrw_scene/scene_loader.h>

#include "free_drive.h"
#include "ghost_frames.h"
#include "ghost_marker.h"
#include "mouse_drag.h"

using namespace vrrw_interaction;

int main(int argc, char** argv)
{
  ros::init(argc, argv, "interaction");
  ros::NodeHandle pnh("~");
  const std::string mode = pnh.param<std::string>("mode", "fake");
  const std::string presets = pnh.param<std::string>("presets", vrrw_scene::vrrwRoot() + "/urdf/config/presets.yaml");
  if (mode != "fake" && mode != "physics" && mode != "none")
    ROS_ERROR_STREAM("~mode: '" << mode << "' is not fake, physics or none; free-drive acts as in fake mode");
  vrrw_scene::Scene scene;
  try
  {
    scene = vrrw_scene::loadScene(pnh.param<std::string>("scene", ""));
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
  // ghost/execute waits for a whole motion: it is served here, off the spinner threads, one thread per arm
  // and one more (a newer execute of an arm preempts its older one, which then returns)
  ros::CallbackQueue execution_queue;
  std::vector<std::unique_ptr<GhostInterface>> ghosts;
  std::vector<GhostInterface*> arms;
  for (const std::string& name : robots)
    try
    {
      if (!scene.robot(name))
      {
        ROS_ERROR_STREAM("~robots: unknown robot '" << name << "' in scene " << scene.name << " (skipped)");
        continue;
      }
      ghosts.push_back(std::make_unique<GhostInterface>(view, *scene.robot(name), presets, execution_queue));
      arms.push_back(ghosts.back().get());
    }
    catch (const std::exception& e)
    {
      ROS_ERROR_STREAM("robot " << name << ": " << e.what() << " (no ghost for it)");
    }
  SpringGains gains;
  gains.angular_stiffness = pnh.param("grip_angular_stiffness", gains.angular_stiffness);
  gains.angular_damping = pnh.param("grip_angular_damping", gains.angular_damping);
  FreeDrive free_drive(view, arms, pnh.param("grab_distance", 0.05), pnh.param("hand_radius", 0.04), gains);
  std::unique_ptr<MouseDrag> mouse = mode == "physics" ? std::make_unique<MouseDrag>(view, arms, gains) : nullptr;
  GhostMarkers markers(view, arms, pnh.param("marker_rate", 200.0), pnh.param("max_jump", 0.5),
                       [&free_drive](const std::string& robot, bool on) {
                         if (const Outcome o = free_drive.set(robot, on); !o.success)
                           ROS_WARN_STREAM(robot << " free-drive: " << o.message);
                       });
  GhostFrames frames(view, arms);
  ROS_INFO_STREAM("interaction: " << arms.size() << " arms of " << scene.name << " (" << mode << " mode)");
  ros::AsyncSpinner spinner(4);
  ros::AsyncSpinner executions(arms.size() + 1, &execution_queue);
  spinner.start();
  executions.start();
  ros::waitForShutdown();
  return 0;
}
