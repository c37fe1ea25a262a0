#include <vrrw_physics/joint_space_inertia.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>
#include <algorithm>
#include <cmath>
#include <Eigen/Geometry>

#include "bullet_conversions.h"

namespace vrrw_physics
{
namespace
{
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

/// Inverse of a symmetric positive-definite matrix by Cholesky, M = L L', M^-1 = L^-T L^-1.
/// Every entry is the same sequence of double operations as the textbook triple loops (each sum taken
/// in ascending k, the same products and divisions), but the loops are ordered so that independent
/// sums advance together over contiguous storage: the divisions of a row of L^-1 pipeline instead of
/// waiting on each other, and the inner loops vectorize.
JointMatrix invertSpd(const JointMatrix& m)
{
  const int n = int(m.rows());
  constexpr int S = kMaxJoints;
  double l[S * S];    // column-major: l[i + k * S] = L(i, k), i >= k
  double inv[S * S];  // row-major: inv[i * S + j] = L^-1(i, j), j <= i (partial sums until row i is done)
  double acc[S];
  for (int j = 0; j < n; ++j)
  {
    double* column = l + j * S;
    for (int i = j; i < n; ++i)
      column[i] = m(i, j);
    for (int k = 0; k < j; ++k)
    {
      const double* lk = l + k * S;
      const double ljk = lk[j];
      for (int i = j; i < n; ++i)
        column[i] -= lk[i] * ljk;
    }
    column[j] = std::sqrt(column[j]);
    for (int i = j + 1; i < n; ++i)
      column[i] = column[i] / column[j];
  }
  // Forward substitution row by row: L^-1(i, j) = (0 - sum_{k=j}^{i-1} L(i, k) L^-1(k, j)) / L(i, i).
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      inv[i * S + j] = 0.0;
  for (int k = 0; k < n; ++k)
  {
    double* row = inv + k * S;
    const double diagonal = l[k + k * S];
    for (int j = 0; j < k; ++j)
      row[j] = row[j] / diagonal;
    row[k] = 1.0 / diagonal;
    for (int i = k + 1; i < n; ++i)
    {
      double* target = inv + i * S;
      const double lik = l[i + k * S];
      for (int j = 0; j <= k; ++j)
        target[j] -= lik * row[j];
    }
  }
  JointMatrix inverse(n, n);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j <= i; ++j)
      acc[j] = 0.0;
    for (int k = i; k < n; ++k)
    {
      const double* row = inv + k * S;
      const double a = row[i];
      for (int j = 0; j <= i; ++j)
        acc[j] += a * row[j];
    }
    for (int j = 0; j <= i; ++j)
      inverse(i, j) = inverse(j, i) = acc[j];
  }
  return inverse;
}
}  // namespace

JointMatrix jointSpaceInertia(const btMultiBody& body, const std::vector<Eigen::Isometry3d>& frames)
{
  // Spatial inertias about the world origin, kept as mass m, first moment h = m c and rotational
  // inertia about the origin I_O = I_c - m [c]x^2; a motion (w, v_O) meets the momentum
  // (I_O w + h x v_O, m v_O - h x w).
  // Every field is assigned in the first loop: no initializers, and fixed storage (one link per
  // movable joint, at most kMaxJoints), so a step allocates nothing here.
  struct Composite
  {
    double mass;
    Eigen::Vector3d moment;
    Eigen::Matrix3d rotational;
  };
  const std::size_t n_links = static_cast<std::size_t>(body.getNumLinks());
  Composite composite[kMaxJoints];
  Eigen::Vector3d angular[kMaxJoints], linear[kMaxJoints];
  for (std::size_t k = 0; k < n_links; ++k)
  {
    const int link = int(k);
    const Eigen::Isometry3d& pose = frames[k + 1];
    const Eigen::Matrix3d r = pose.rotation();
    const Eigen::Vector3d c = pose.translation();
    const double m = body.getLinkMass(link);
    const Eigen::Matrix3d cx = skew(c);
    composite[k].mass = m;
    composite[k].moment = m * c;
    composite[k].rotational = r * toEigen(body.getLinkInertia(link)).asDiagonal() * r.transpose() - m * cx * cx;
    const btMultibodyLink& joint = body.getLink(link);
    if (joint.m_jointType == btMultibodyLink::ePrismatic)
    {
      angular[k].setZero();
      linear[k] = r * toEigen(joint.getAxisBottom(0));
    }
    else
    {
      angular[k] = r * toEigen(joint.getAxisTop(0));
      linear[k] = (c - r * toEigen(joint.m_dVector)).cross(angular[k]);
    }
  }
  for (std::size_t k = n_links; k-- > 0;)
  {
    const int parent = body.getParent(int(k));
    if (parent < 0)
      continue;
    Composite& p = composite[std::size_t(parent)];
    p.mass += composite[k].mass;
    p.moment += composite[k].moment;
    p.rotational += composite[k].rotational;
  }
  const Eigen::Index n = Eigen::Index(n_links);
  JointMatrix m = JointMatrix::Zero(n, n);
  for (std::size_t k = 0; k < n_links; ++k)
  {
    const Composite& ic = composite[k];
    const Eigen::Vector3d torque = ic.rotational * angular[k] + ic.moment.cross(linear[k]);
    const Eigen::Vector3d force = ic.mass * linear[k] - ic.moment.cross(angular[k]);
    for (int a = int(k); a >= 0; a = body.getParent(a))
    {
      const double value = angular[std::size_t(a)].dot(torque) + linear[std::size_t(a)].dot(force);
      m(a, Eigen::Index(k)) = value;
      m(Eigen::Index(k), a) = value;
    }
  }
  return m;
}

void JointSpaceResponse::setInertia(const JointMatrix& inertia)
{
  inertia_ = &inertia;
  inverted_ = false;
  valid_ = inertia.allFinite();
}

const JointMatrix& JointSpaceResponse::inverse() const
{
  if (!inverted_)
  {
    inverse_ = invertSpd(*inertia_);
    inverted_ = true;
  }
  return inverse_;
}

bool supportsJointSpaceAccelerations(const btMultiBody& body, const JointSpaceResponse& response)
{
  const int n_links = body.getNumLinks();
  if (!response.valid() || !body.hasFixedBase() || body.isUsingGlobalVelocities() || body.isUsingRK4Integration() ||
      n_links > kMaxJoints || body.getNumDofs() != n_links || int(response.joint_of_dof.size()) != n_links)
    return false;
  for (int i = 0; i < n_links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int joint = response.joint_of_dof[std::size_t(i)];
    if (link.m_dofCount != 1 || link.m_jointFeedback != nullptr || joint < 0 || joint >= n_links ||
        (link.m_jointType != btMultibodyLink::eRevolute && link.m_jointType != btMultibodyLink::ePrismatic))
      return false;
  }
  return true;
}

void jointSpaceAccelerations(const btMultiBody& body, const JointSpaceResponse& response, double* qdd)
{
  // The terms are Bullet's, in Bullet's link frames (origin at the centre of mass, principal axes):
  // velocities v_i, the velocity-product acceleration c_i = v_i x (S_i qd_i) and the zero-acceleration force
  // z_i (minus the applied force and torque, damping, gyroscopic term). With qdd = 0 the accelerations are
  // a_i = X_i a_parent + c_i and the link forces f_i = I_i a_i + z_i, summed to the root: tau - S_i . f_i is
  // what is left for M qdd.
  const int n = body.getNumLinks();
  const btScalar k_linear = body.getLinearDamping();
  const btScalar k_angular = body.getAngularDamping();
  const bool gyro = body.getUseGyroTerm();
  const btScalar* velocity = body.getVelocityVector();
  btMatrix3x3 rot_from_world[kMaxJoints + 1];
  btSpatialMotionVector spat_vel[kMaxJoints + 1], spat_acc[kMaxJoints + 1];
  btSpatialForceVector force[kMaxJoints + 1];
  double bias[kMaxJoints];
  rot_from_world[0] = btMatrix3x3(body.getWorldToBaseRot());
  spat_vel[0].setVector(rot_from_world[0] * body.getBaseOmega(), rot_from_world[0] * body.getBaseVel());
  spat_acc[0].setZero();
  force[0].setZero();
  btSpatialTransformationMatrix from_parent;
  for (int i = 0; i < n; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int parent = link.m_parent;
    const btMatrix3x3 rot_from_parent(link.m_cachedRotParentToThis);
    rot_from_world[i + 1] = rot_from_parent * rot_from_world[parent + 1];
    from_parent.m_rotMat = rot_from_parent;
    from_parent.m_trnVec = link.m_cachedRVector;
    btSpatialMotionVector& v = spat_vel[i + 1];
    from_parent.transform(spat_vel[parent + 1], v);
    const btSpatialMotionVector joint_vel = link.m_axes[0] * velocity[6 + link.m_dofOffset];
    v += joint_vel;
    btSpatialMotionVector coriolis;
    v.cross(joint_vel, coriolis);
    btSpatialForceVector& f = force[i + 1];
    f.setVector(-(rot_from_world[i + 1] * body.getLinkTorque(i)), -(rot_from_world[i + 1] * body.getLinkForce(i)));
    f.addVector(link.m_inertiaLocal * v.getAngular() * (k_angular + k_angular * v.getAngular().safeNorm()),
                link.m_mass * v.getLinear() * (k_linear + k_linear * v.getLinear().safeNorm()));
    if (gyro)
      f.addAngular(v.getAngular().cross(link.m_inertiaLocal * v.getAngular()));
    f.addLinear(link.m_mass * v.getAngular().cross(v.getLinear()));
    btSpatialMotionVector& a = spat_acc[i + 1];
    from_parent.transform(spat_acc[parent + 1], a);
    a += coriolis;
    // I_i a_i with I_i = diag(inertia) about the centre of mass, m on the linear part.
    f.addVector(link.m_inertiaLocal * a.getAngular(), link.m_mass * a.getLinear());
  }
  for (int i = n; i-- > 0;)
  {
    const btMultibodyLink& link = body.getLink(i);
    bias[link.m_dofOffset] = link.m_axes[0].dot(force[i + 1]);
    if (link.m_parent < 0)
      continue;
    from_parent.m_rotMat = btMatrix3x3(link.m_cachedRotParentToThis);
    from_parent.m_trnVec = link.m_cachedRVector;
    from_parent.transformInverse(force[i + 1], force[link.m_parent + 1], btSpatialTransformationMatrix::Add);
  }
  double rhs[kMaxJoints];
  for (int i = 0; i < n; ++i)
  {
    const int d = body.getLink(i).m_dofOffset;
    rhs[response.joint_of_dof[std::size_t(d)]] = double(body.getJointTorque(i)) - bias[d];
  }
  const JointMatrix& inverse = response.inverse();
  for (int k = 0; k < 6; ++k)
    qdd[k] = 0.0;
  for (int d = 0; d < n; ++d)
  {
    const int j = response.joint_of_dof[std::size_t(d)];
    double sum = 0.0;
    for (int e = 0; e < n; ++e)
      sum += inverse(j, e) * rhs[e];
    qdd[6 + d] = sum;
  }
}

double fillJointRow(btMultiBodySolverConstraint& row, btMultiBodyJacobianData& data, btMultiBody* body,
                    const JointSpaceResponse& response, int link_a, double coeff_a, int link_b, double coeff_b,
                    double goal_velocity, double cfm, double lower, double upper)
{
  const int size = body->getNumDofs() + 6;
  row.m_multiBodyA = body;
  row.m_multiBodyB = nullptr;
  row.m_linkA = link_a;
  row.m_linkB = -1;
  row.m_solverBodyIdA = -1;
  row.m_solverBodyIdB = -1;
  row.m_deltaVelAindex = body->getCompanionId();
  if (row.m_deltaVelAindex < 0)
  {
    row.m_deltaVelAindex = data.m_deltaVelocities.size();
    body->setCompanionId(row.m_deltaVelAindex);
    data.m_deltaVelocities.resize(data.m_deltaVelocities.size() + size);
  }
  row.m_jacAindex = data.m_jacobians.size();
  data.m_jacobians.resize(data.m_jacobians.size() + size);
  data.m_deltaVelocitiesUnitImpulse.resize(data.m_deltaVelocitiesUnitImpulse.size() + size);
  // resize() fills the new entries with zeros: only the joint coordinates are written below.
  btScalar* jacobian = &data.m_jacobians[row.m_jacAindex];
  btScalar* delta = &data.m_deltaVelocitiesUnitImpulse[row.m_jacAindex];
  const int dof_a = body->getLink(link_a).m_dofOffset;
  const int dof_b = link_b >= 0 ? body->getLink(link_b).m_dofOffset : -1;
  jacobian[6 + dof_a] = btScalar(coeff_a);
  if (dof_b >= 0)
    jacobian[6 + dof_b] += btScalar(coeff_b);
  const int ja = response.joint_of_dof[std::size_t(dof_a)];
  const int jb = dof_b >= 0 ? response.joint_of_dof[std::size_t(dof_b)] : -1;
  const JointMatrix& inverse = response.inverse();
  // denominator = J M^-1 J' summed over the dofs in ascending order; the Jacobian is zero but at
  // dof_a and dof_b, and adding the zero terms changes no finite sum, so only those two are added.
  double denominator = 0.0;
  const int first = dof_b >= 0 && dof_b < dof_a ? dof_b : dof_a;
  const int second = dof_b >= 0 ? (dof_b < dof_a ? dof_a : dof_b) : -1;
  for (int d = 0; d < size - 6; ++d)
  {
    const int j = response.joint_of_dof[std::size_t(d)];
    double value = coeff_a * inverse(j, ja);
    if (jb >= 0)
      value += coeff_b * inverse(j, jb);
    delta[6 + d] = btScalar(value);
    if (d == first || d == second)
      denominator += double(jacobian[6 + d]) * value;
  }
  const btScalar* velocity = body->getVelocityVector();
  double rate = coeff_a * velocity[6 + dof_a];
  if (dof_b >= 0)
    rate += coeff_b * velocity[6 + dof_b];
  const double w = denominator > 1e-12 ? 1.0 / (denominator + cfm) : 0.0;
  const btVector3 zero(0, 0, 0);
  row.m_contactNormal1 = row.m_contactNormal2 = zero;
  row.m_relpos1CrossNormal = row.m_relpos2CrossNormal = zero;
  row.m_angularComponentA = row.m_angularComponentB = zero;
  row.m_friction = 0;
  row.m_appliedImpulse = 0;
  row.m_appliedPushImpulse = 0;
  row.m_jacDiagABInv = btScalar(w);
  row.m_rhs = btScalar((goal_velocity - rate) * w);
  row.m_rhsPenetration = 0;
  row.m_cfm = btScalar(cfm * w);
  row.m_lowerLimit = btScalar(lower);
  row.m_upperLimit = btScalar(upper);
  return rate;
}
}  // namespace vrrw_physics
