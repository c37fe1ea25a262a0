#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/joint_space_inertia.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>
#include <algorithm>
#include <cmath>
#include <Eigen/Geometry>

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

Eigen::Vector3d toEigen(const btVector3& v)
{
  return Eigen::Vector3d(v.x(), v.y(), v.z());
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

JointMatrix jointSpaceInertia(const ArticulatedRobot& robot)
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
  const btMultiBody& body = *robot.body();
  const std::size_t n_links = static_cast<std::size_t>(body.getNumLinks());
  Composite composite[kMaxJoints];
  Eigen::Vector3d angular[kMaxJoints], linear[kMaxJoints];
  for (std::size_t k = 0; k < n_links; ++k)
  {
    const int link = int(k);
    const Eigen::Isometry3d& pose = robot.bodyPose(link);
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
  const auto& joints = robot.joints();
  int joint_of_link[kMaxJoints];
  std::fill(joint_of_link, joint_of_link + n_links, -1);
  for (std::size_t j = 0; j < joints.size(); ++j)
    joint_of_link[std::size_t(joints[j].link)] = int(j);
  const Eigen::Index n = Eigen::Index(joints.size());
  JointMatrix m = JointMatrix::Zero(n, n);
  for (std::size_t k = 0; k < n_links; ++k)
  {
    const int j = joint_of_link[k];
    if (j < 0)
      continue;
    const Composite& ic = composite[k];
    const Eigen::Vector3d torque = ic.rotational * angular[k] + ic.moment.cross(linear[k]);
    const Eigen::Vector3d force = ic.mass * linear[k] - ic.moment.cross(angular[k]);
    for (int a = int(k); a >= 0; a = body.getParent(a))
    {
      const int i = joint_of_link[std::size_t(a)];
      if (i < 0)
        continue;
      const double value = angular[std::size_t(a)].dot(torque) + linear[std::size_t(a)].dot(force);
      m(i, j) = value;
      m(j, i) = value;
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
