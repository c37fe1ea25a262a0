#pragma once
// The cell ./vrrw demo works in: the robot that picks, what it picks, where it sets it down.
#include <set>
#include <string>
#include <vrrw_scene/scene.h>

namespace vrrw_evaluation
{
struct Cell
{
  vrrw_scene::Robot robot;
  std::string object;
  std::string table;  ///< the fixed object the drill is set down on
  std::set<std::string> obstacles;
  std::string urdf;   ///< the scene's combined URDF (joint limits)
};

/// \brief The first robot with a gripper, the movable object of kind drill and the fixed one of kind table of
/// `scene_name`; false with one line naming the field and what the scene has.
bool findCell(const std::string& scene_name, Cell& cell, std::string& error);
}  // namespace vrrw_evaluation
