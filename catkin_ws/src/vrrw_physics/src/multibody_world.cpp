#include <vrrw_physics/joint_row_group.h>
#include <vrrw_physics/joint_limits.h>
#include <vrrw_physics/joint_space_inertia.h>
#include <vrrw_physics/multibody_world.h>
#include <vrrw_physics/soft_joint_constraint.h>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <algorithm>

namespace vrrw_physics
{
namespace
{
bool sleeping(const btMultiBody& body)
{
  if (body.getBaseCollider() && body.getBaseCollider()->getActivationState() == ISLAND_SLEEPING)
    return true;
  for (int b = 0; b < body.getNumLinks(); ++b)
    if (body.getLink(b).m_collider && body.getLink(b).m_collider->getActivationState() == ISLAND_SLEEPING)
      return true;
  return false;
}

const btMultiBody* multiBodyOf(const btCollisionObject* object)
{
  const btMultiBodyLinkCollider* collider = btMultiBodyLinkCollider::upcast(object);
  return collider ? collider->m_multiBody : nullptr;
}
}  // namespace

void MultiBodyWorld::setJointSpaceDynamics(btMultiBody* body, const JointSpaceResponse* response)
{
  joint_space_.push_back({ body, response });
}

void MultiBodyWorld::predictUnconstraintMotion(btScalar timeStep)
{
  btDiscreteDynamicsWorld::predictUnconstraintMotion(timeStep);
}

void MultiBodyWorld::solveExternalForces(btContactSolverInfo& solverInfo)
{
  ours_.clear();
  if (joint_space_.empty())
  {
    btMultiBodyDynamicsWorld::solveExternalForces(solverInfo);
    return;
  }
  // Bodies whose rows Bullet fills itself this step (contacts of this step's collision pass, foreign
  // constraints) need the articulated inertias of Bullet's pass.
  bullet_needed_.clear();
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m)
  {
    const btPersistentManifold* manifold = dispatcher->getInternalManifoldPointer()[m];
    if (manifold->getNumContacts() == 0)
      continue;
    for (const btMultiBody* body : { multiBodyOf(manifold->getBody0()), multiBodyOf(manifold->getBody1()) })
      if (body)
        bullet_needed_.push_back(body);
  }
  for (int c = 0; c < m_multiBodyConstraints.size(); ++c)
  {
    btMultiBodyConstraint* constraint = m_multiBodyConstraints[c];
    if (dynamic_cast<JointRowGroup*>(constraint) || dynamic_cast<SoftJointConstraint*>(constraint) ||
        dynamic_cast<JointLimits*>(constraint))
      continue;
    if (constraint->getMultiBodyA())
      bullet_needed_.push_back(constraint->getMultiBodyA());
    if (constraint->getMultiBodyB())
      bullet_needed_.push_back(constraint->getMultiBodyB());
  }
  for (const Entry& e : joint_space_)
    if (std::find(bullet_needed_.begin(), bullet_needed_.end(), e.body) == bullet_needed_.end() &&
        supportsJointSpaceAccelerations(*e.body, *e.response) && !sleeping(*e.body) &&
        e.body->getNumDofs() <= 64 && m_multiBodies.findLinearSearch(e.body) < m_multiBodies.size())
      ours_.push_back(e);
  if (ours_.empty())
  {
    btMultiBodyDynamicsWorld::solveExternalForces(solverInfo);
    return;
  }
  // Bullet's own pass (kinematics, sorting, solver preparation, articulated-body pass) for the others.
  all_bodies_ = m_multiBodies;
  bullet_bodies_.resize(0);
  for (int i = 0; i < all_bodies_.size(); ++i)
  {
    btMultiBody* body = all_bodies_[i];
    if (std::none_of(ours_.begin(), ours_.end(), [body](const Entry& e) { return e.body == body; }))
      bullet_bodies_.push_back(body);
  }
  m_multiBodies = bullet_bodies_;
  btMultiBodyDynamicsWorld::solveExternalForces(solverInfo);
  m_multiBodies = all_bodies_;
  for (const Entry& e : ours_)
  {
    e.body->forwardKinematics(m_scratch_world_to_local, m_scratch_local_origin);
    e.body->clearConstraintForces();
    jointSpaceAccelerations(*e.body, *e.response, qdd_);
    btScalar delta[6 + 64];
    for (int d = 0; d < 6 + e.body->getNumDofs(); ++d)
      delta[d] = btScalar(qdd_[d]);
    e.body->applyDeltaVeeMultiDof(delta, solverInfo.m_timeStep);
  }
}
}  // namespace vrrw_physics
