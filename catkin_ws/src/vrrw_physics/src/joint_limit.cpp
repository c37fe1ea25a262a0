#include <vrrw_physics/joint_limit.h>

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

JointLimit::JointLimit(btMultiBody* body, int link, double lower, double upper)
  : btMultiBodyConstraint(body, body, link, link, 2, true, MULTIBODY_CONSTRAINT_LIMIT), lower_(lower), upper_(upper)
{
  finalizeMultiDof();
}

void JointLimit::finalizeMultiDof()
{
  allocateJacobiansMultiDof();
  for (int row = 0; row < 2; ++row)
  {
    for (int i = 0; i < m_jacSizeBoth; ++i)
      jacobianA(row)[i] = 0;
    jacobianA(row)[6 + m_bodyA->getLink(m_linkA).m_dofOffset] = row == 0 ? 1 : -1;
  }
  m_numDofsFinalized = m_jacSizeBoth;
}

int JointLimit::getIslandIdA() const
{
  return constraintIsland(m_bodyA, m_linkA);
}

int JointLimit::getIslandIdB() const
{
  return constraintIsland(m_bodyA, m_linkA);
}

void JointLimit::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                      const btContactSolverInfo& info)
{
  if (m_numDofsFinalized != m_jacSizeBoth)
    finalizeMultiDof();
  const double h = info.m_timeStep;
  const double q = m_bodyA->getJointPos(m_linkA);
  const double qd = m_bodyA->getJointVel(m_linkA);
  const double reach = 2.0 * std::abs(qd) * h + 1e-3;
  const double gaps[2] = { q - lower_, upper_ - q };
  const btVector3 zero(0, 0, 0);
  for (int row = 0; row < 2; ++row)
  {
    if (gaps[row] > reach)
      continue;
    // Speculative when the gap is open; a violated limit is pushed back with the solver's erp.
    const double goal = gaps[row] >= 0.0 ? -gaps[row] / h : -gaps[row] * info.m_erp / h;
    btMultiBodySolverConstraint& c = rows.expandNonInitializing();
    fillMultiBodyConstraint(c, data, jacobianA(row), jacobianB(row), zero, zero, zero, zero, 0, info, 0,
                            m_maxAppliedImpulse, false, 1, false, btScalar(goal));
    c.m_orgConstraint = this;
    c.m_orgDofIndex = row;
  }
}
}  // namespace vrrw_physics
