#include <vrrw_control/tolerances.h>

namespace vrrw_control
{
Tolerances Tolerances::uniform(size_t joints, double path_position, double goal_position, double goal_velocity,
                               double goal_time)
{
  Tolerances t;
  t.path_position.assign(joints, path_position);
  t.path_velocity.assign(joints, 0.0);
  t.goal_position.assign(joints, goal_position);
  t.goal_velocity.assign(joints, goal_velocity);
  t.goal_time = goal_time;
  return t;
}
}  // namespace vrrw_control
