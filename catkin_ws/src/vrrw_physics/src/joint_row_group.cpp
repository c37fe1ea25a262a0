#include <vrrw_physics/joint_row_group.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace vrrw_physics
{
JointRowGroup::JointRowGroup(btMultiBody* body) : btMultiBodyConstraint(body, body, 0, 0, 0, false, MULTIBODY_CONSTRAINT_LIMIT)
{
  for (int i = 0; !island_object_ && i < body->getNumLinks(); ++i)
    island_object_ = body->getLink(i).m_collider;
}

void JointRowGroup::add(btMultiBodyConstraint* member)
{
  members_.push_back(member);
}

int JointRowGroup::getIslandIdA() const
{
  return island_object_ ? island_object_->getIslandTag() : -1;
}

int JointRowGroup::getIslandIdB() const
{
  return getIslandIdA();
}

void JointRowGroup::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                         const btContactSolverInfo& info)
{
  for (btMultiBodyConstraint* member : members_)
    member->createConstraintRows(rows, data, info);
}
}  // namespace vrrw_physics
