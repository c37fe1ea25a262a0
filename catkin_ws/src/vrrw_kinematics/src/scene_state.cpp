#include "vrrw_kinematics/scene_state.h"

namespace vrrw_kinematics
{
Eigen::VectorXd initialState(const RobotModel& model, const vrrw_scene::Scene& scene)
{
  Eigen::VectorXd q = model.neutralState();
  for (const vrrw_scene::Robot& robot : scene.robots)
    for (const auto& entry : robot.initial_positions)
    {
      int v = model.variableIndex(entry.first);
      if (v < 0)
        v = model.variableIndex(robot.name + "_" + entry.first);
      if (v >= 0)
        q[v] = entry.second;
    }
  return q;
}
}  // namespace vrrw_kinematics
