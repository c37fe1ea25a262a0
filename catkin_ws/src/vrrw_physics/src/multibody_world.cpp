#include <vrrw_physics/multibody_world.h>

namespace vrrw_physics
{
void MultiBodyWorld::predictUnconstraintMotion(btScalar timeStep)
{
  btDiscreteDynamicsWorld::predictUnconstraintMotion(timeStep);
}
}  // namespace vrrw_physics
