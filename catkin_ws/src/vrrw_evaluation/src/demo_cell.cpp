#include <vrrw_evaluation/demo_cell.h>

#include <algorithm>
#include <vrrw_scene/scene_loader.h>

namespace vrrw_evaluation
{
bool findCell(const std::string& scene_name, Cell& cell, std::string& error)
{
  vrrw_scene::Scene scene;
  try
  {
    scene = vrrw_scene::loadScene(scene_name);
  }
  catch (const std::exception& e)
  {
    return error = e.what(), false;
  }
  const auto robot = std::find_if(scene.robots.begin(), scene.robots.end(),
                                  [](const vrrw_scene::Robot& r) { return !r.gripper.empty(); });
  if (robot == scene.robots.end())
    return error = scene_name + ": robots: no robot with a gripper to pick with", false;
  std::string names;
  for (const vrrw_scene::Object& object : scene.objects)
  {
    names += (names.empty() ? "" : ", ") + object.name + " (" + object.kind + (object.fixed ? ", fixed)" : ")");
    cell.obstacles.insert(object.name);
    if (cell.object.empty() && !object.fixed && object.kind == "drill")
      cell.object = object.name;
    if (cell.table.empty() && object.fixed && object.kind == "table")
      cell.table = object.name;
  }
  if (cell.object.empty())
    return error = scene_name + ": objects: no graspable object (the demo picks a movable object of kind 'drill'; " +
                   "the scene has: " + (names.empty() ? "none" : names) + ")",
           false;
  if (cell.table.empty())
    return error = scene_name + ": objects: no fixed object of kind 'table' to set the " + cell.object + " down on", false;
  cell.robot = *robot;
  cell.urdf = scene.urdf;
  return true;
}
}  // namespace vrrw_evaluation
