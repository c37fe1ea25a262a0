#include <vrrw_physics/joint_limits.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

#include <cmath>

namespace vrrw_physics
{
int constraintIsland(const btMultiBody* body, int link)
{
  const btMultiBodyLinkCollider* collider = body->getLink(link).m_collider;
  for (int i = 0; !collider && i < body->getNumLinks(); ++i)
    collider = body->getLink(i).m_collider;
  return collider ? collider->getIslandTag() : -1;
}

JointLimits::JointLimits(btMultiBody* body, const std::vector<JointRange>& ranges, const JointSpaceResponse* response)
  : btMultiBodyConstraint(body, body, ranges.front().link, ranges.front().link, int(2 * ranges.size()), true,
                          MULTIBODY_CONSTRAINT_LIMIT)
  , ranges_(ranges)
  , response_(response)
{
  finalizeMultiDof();
}

void JointLimits::finalizeMultiDof()
{
  allocateJacobiansMultiDof();
  for (int row = 0; row < m_numRows; ++row)
  {
    for (int i = 0; i < m_jacSizeBoth; ++i)
      jacobianA(row)[i] = 0;
    const JointRange& range = ranges_[std::size_t(row / 2)];
    jacobianA(row)[6 + m_bodyA->getLink(range.link).m_dofOffset] = row % 2 == 0 ? 1 : -1;
  }
  m_numDofsFinalized = m_jacSizeBoth;
}

int JointLimits::getIslandIdA() const
{
  return constraintIsland(m_bodyA, m_linkA);
}

int JointLimits::getIslandIdB() const
{
  return constraintIsland(m_bodyA, m_linkA);
}

void JointLimits::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                       const btContactSolverInfo& info)
{
  if (m_numDofsFinalized != m_jacSizeBoth)
    finalizeMultiDof();
  const double h = info.m_timeStep;
  const btVector3 zero(0, 0, 0);
  for (std::size_t i = 0; i < ranges_.size(); ++i)
  {
    const JointRange& range = ranges_[i];
    const double q = m_bodyA->getJointPos(range.link);
    const double qd = m_bodyA->getJointVel(range.link);
    const double reach = 2.0 * std::abs(qd) * h + 1e-3;
    const double gaps[2] = { q - range.lower, range.upper - q };
    for (int side = 0; side < 2; ++side)
    {
      if (gaps[side] > reach)
        continue;
      const int row = int(2 * i) + side;
      const double goal = gaps[side] >= 0.0 ? -gaps[side] / h : -gaps[side] * info.m_erp / h;
      btMultiBodySolverConstraint& c = rows.expandNonInitializing();
      if (response_ && response_->valid())
        fillJointRow(c, data, m_bodyA, *response_, range.link, side == 0 ? 1.0 : -1.0, -1, 0.0, goal, 0.0, 0.0,
                     m_maxAppliedImpulse);
      else
        fillMultiBodyConstraint(c, data, jacobianA(row), jacobianB(row), zero, zero, zero, zero, 0, info, 0,
                                m_maxAppliedImpulse, false, 1, false, btScalar(goal));
      c.m_orgConstraint = this;
      c.m_orgDofIndex = row;
    }
  }
}
}  // namespace vrrw_physics
