#include <vrrw_physics/joint_limits.h>
#include <vrrw_physics/soft_joint_constraint.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

namespace vrrw_physics
{
Softness implicitSpringDamper(double h, double stiffness, double damping)
{
  const double denominator = h * stiffness + damping;
  return { h * stiffness / denominator, 1.0 / (h * denominator) };
}

SoftJointConstraint::SoftJointConstraint(btMultiBody* body, int link_a, double coeff_a, int link_b, double coeff_b,
                                         int type, const JointSpaceResponse* response)
  : btMultiBodyConstraint(body, body, link_a, link_b < 0 ? link_a : link_b, 1, false, type)
  , response_(response)
  , link_b_(link_b)
  , coeff_a_(coeff_a)
  , coeff_b_(coeff_b)
{
}

void SoftJointConstraint::finalizeMultiDof()
{
  allocateJacobiansMultiDof();
  for (int i = 0; i < m_jacSizeBoth; ++i)
    jacobianA(0)[i] = 0;
  jacobianA(0)[6 + m_bodyA->getLink(m_linkA).m_dofOffset] = btScalar(coeff_a_);
  if (link_b_ >= 0)
    jacobianA(0)[6 + m_bodyA->getLink(link_b_).m_dofOffset] += btScalar(coeff_b_);
  m_numDofsFinalized = m_jacSizeBoth;
}

int SoftJointConstraint::getIslandIdA() const
{
  return constraintIsland(m_bodyA, m_linkA);
}

int SoftJointConstraint::getIslandIdB() const
{
  return constraintIsland(m_bodyA, m_linkA);
}

void SoftJointConstraint::setGains(double stiffness, double damping)
{
  stiffness_ = stiffness;
  damping_ = damping;
}

void SoftJointConstraint::setForceLimit(double max_force)
{
  max_force_ = max_force;
}

void SoftJointConstraint::setTarget(double position, double velocity)
{
  target_position_ = position;
  target_velocity_ = velocity;
}

double SoftJointConstraint::position() const
{
  double c = coeff_a_ * m_bodyA->getJointPos(m_linkA);
  if (link_b_ >= 0)
    c += coeff_b_ * m_bodyA->getJointPos(link_b_);
  return c;
}

double SoftJointConstraint::velocity() const
{
  double v = coeff_a_ * m_bodyA->getJointVel(m_linkA);
  if (link_b_ >= 0)
    v += coeff_b_ * m_bodyA->getJointVel(link_b_);
  return v;
}

void SoftJointConstraint::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                               const btContactSolverInfo& info)
{
  if (m_numDofsFinalized != m_jacSizeBoth)
    finalizeMultiDof();
  if (stiffness_ + damping_ <= 0.0 || max_force_ <= 0.0)
    return;
  const double h = info.m_timeStep;
  const Softness soft = implicitSpringDamper(h, stiffness_, damping_);
  const double error = target_position_ - position();
  const double goal_velocity = soft.erp / h * error + (1.0 - soft.erp) * target_velocity_;
  const double max_impulse = max_force_ * h;

  btMultiBodySolverConstraint& row = rows.expandNonInitializing();
  row.m_orgConstraint = this;
  row.m_orgDofIndex = 0;
  if (response_ && response_->valid())
  {
    fillJointRow(row, data, m_bodyA, *response_, m_linkA, coeff_a_, link_b_, coeff_b_, goal_velocity, soft.cfm,
                 -max_impulse, max_impulse);
    return;
  }
  const btVector3 zero(0, 0, 0);
  fillMultiBodyConstraint(row, data, jacobianA(0), jacobianB(0), zero, zero, zero, zero, 0, info,
                          btScalar(-max_impulse), btScalar(max_impulse), false, 1, false, btScalar(goal_velocity));
  // fill sets m_jacDiagABInv = 1/A and m_rhs = (goal - J*v)/A; soften: w = 1/(A + cfm).
  const double a = 1.0 / row.m_jacDiagABInv;
  const double w = 1.0 / (a + soft.cfm);
  row.m_rhs = btScalar(row.m_rhs * a * w);
  row.m_jacDiagABInv = btScalar(w);
  row.m_cfm = btScalar(soft.cfm * w);
  row.m_orgConstraint = this;
  row.m_orgDofIndex = 0;
}
}  // namespace vrrw_physics
