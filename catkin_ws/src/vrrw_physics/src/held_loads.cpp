// PhysicsWorld::findHeldObjects: what each robot holds between its fingers, judged from the contacts of a step.
#include <vrrw_physics/physics_world.h>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <map>
#include <set>

#include "bullet_conversions.h"
#include "touching.h"

namespace vrrw_physics
{
namespace
{
/// What a movable object touched in one step.
struct Touches
{
  std::map<std::size_t, std::set<int>> links;  ///< robot index -> its Bullet links touching the object
  bool other = false;                           ///< anything else: the table, another object, the floor, a hand
};

bool touching(const btPersistentManifold& manifold)
{
  for (int p = 0; p < manifold.getNumContacts(); ++p)
    if (isTouching(manifold.getContactPoint(p)))
      return true;
  return false;
}
}  // namespace

void PhysicsWorld::findHeldObjects()
{
  std::map<const RigidObject*, Touches> touches;
  const auto objectOf = [this](const btCollisionObject* body) -> const RigidObject* {
    for (const auto& o : objects_)
      if (!o->fixed() && o->body() == body)
        return o.get();
    return nullptr;
  };
  const auto robotOf = [this](const btCollisionObject* body, int& link) -> long {
    if (const btMultiBodyLinkCollider* collider = btMultiBodyLinkCollider::upcast(body))
      for (std::size_t r = 0; r < robots_.size(); ++r)
        if (robots_[r].robot->body() == collider->m_multiBody)
          return link = collider->m_link, long(r);
    return -1;
  };
  btDispatcher* dispatcher = world_->getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m)
  {
    const btPersistentManifold* manifold = dispatcher->getInternalManifoldPointer()[m];
    if (!touching(*manifold))
      continue;
    const btCollisionObject* bodies[2] = { manifold->getBody0(), manifold->getBody1() };
    for (int side = 0; side < 2; ++side)
      if (const RigidObject* object = objectOf(bodies[side]))
      {
        int link = -1;
        const long robot = robotOf(bodies[1 - side], link);
        if (robot >= 0)
          touches[object].links[std::size_t(robot)].insert(link);
        else
          touches[object].other = true;
      }
  }
  for (RobotEntry& e : robots_)
    e.held.clear(), e.held_objects.clear();
  for (const auto& [object, touched] : touches)
  {
    if (touched.other || touched.links.size() != 1 || touched.links.begin()->second.size() < 2)
      continue;
    RobotEntry& e = robots_[touched.links.begin()->first];
    const std::set<int>& links = touched.links.begin()->second;
    const btRigidBody* body = object->body();
    e.held.push_back({ e.robot->commonAncestor({ links.begin(), links.end() }), 1.0 / double(body->getInvMass()),
                       toEigen(body->getCenterOfMassPosition()) });
    e.held_objects.push_back(object->name());
  }
}
}  // namespace vrrw_physics
