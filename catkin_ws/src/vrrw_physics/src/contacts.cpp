// PhysicsWorld::contacts: the touching pairs of the last step, named the way the scene names bodies.
#include <vrrw_physics/physics_world.h>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <map>

#include "bullet_conversions.h"
#include "touching.h"

namespace vrrw_physics
{
namespace
{
struct PairSum
{
  double force = 0.0;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();  ///< sum of force * position
  Eigen::Vector3d positions = Eigen::Vector3d::Zero();
  int points = 0;
};
}  // namespace

std::vector<ContactPair> PhysicsWorld::contacts() const
{
  const auto name = [this](const btCollisionObject* object, int shape) -> std::string {
    if (const btMultiBodyLinkCollider* link = btMultiBodyLinkCollider::upcast(object))
    {
      for (const RobotEntry& e : robots_)
        if (e.robot->body() == link->m_multiBody)
          return e.robot->shapeLink(link->m_link, shape);
    }
    if (object == floor_.get())
      return "floor";
    for (const auto& o : objects_)
      if (o->body() == object)
        return o->name();
    return operator_->handName(object);
  };
  std::map<std::pair<std::string, std::string>, PairSum> pairs;
  btDispatcher* dispatcher = world_->getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m)
  {
    const btPersistentManifold* manifold = dispatcher->getInternalManifoldPointer()[m];
    for (int p = 0; p < manifold->getNumContacts(); ++p)
    {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (!isTouching(point))
        continue;
      std::pair<std::string, std::string> key{ name(manifold->getBody0(), point.m_index0),
                                               name(manifold->getBody1(), point.m_index1) };
      if (key.second < key.first)
        std::swap(key.first, key.second);
      PairSum& sum = pairs[key];
      const double force = std::max(0.0, double(point.m_appliedImpulse)) / options_.dt;
      const Eigen::Vector3d at = 0.5 * (toEigen(point.getPositionWorldOnA()) + toEigen(point.getPositionWorldOnB()));
      sum.force += force;
      sum.weighted += force * at;
      sum.positions += at;
      ++sum.points;
    }
  }
  std::vector<ContactPair> out;
  for (const auto& [key, sum] : pairs)
  {
    const Eigen::Vector3d at = sum.force > 0.0 ? Eigen::Vector3d(sum.weighted / sum.force) :
                                                 Eigen::Vector3d(sum.positions / sum.points);
    out.push_back({ key.first, key.second, sum.force, at });
  }
  return out;
}
}  // namespace vrrw_physics
