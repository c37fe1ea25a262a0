#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/stable_pd.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>

namespace vrrw_physics
{
namespace
{
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

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
}  // namespace

StablePd::StablePd(const ArticulatedRobot& robot) : robot_(robot)
{
  const auto& joints = robot.joints();
  std::vector<int> reduced(joints.size(), -1);
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].drive >= 0)
    {
      reduced[j] = int(driven_.size());
      driven_.push_back(int(j));
    }
  reduction_ = Eigen::MatrixXd::Zero(Eigen::Index(joints.size()), Eigen::Index(driven_.size()));
  for (std::size_t j = 0; j < joints.size(); ++j)
  {
    int master = int(j);
    double factor = 1.0;
    while (master >= 0 && joints[std::size_t(master)].mimic >= 0)
    {
      factor *= joints[std::size_t(master)].multiplier;
      master = joints[std::size_t(master)].mimic;
    }
    if (master >= 0 && reduced[std::size_t(master)] >= 0)
      reduction_(Eigen::Index(j), reduced[std::size_t(master)]) = factor;
  }
}

Eigen::MatrixXd StablePd::inertia() const
{
  const btMultiBody& body = *robot_.body();
  const int n_links = body.getNumLinks();
  std::vector<Matrix6d> composite(static_cast<std::size_t>(n_links));
  std::vector<Vector6d> motion(static_cast<std::size_t>(n_links));
  for (int k = 0; k < n_links; ++k)
  {
    const Eigen::Isometry3d pose = robot_.bodyPose(k);
    const Eigen::Matrix3d r = pose.rotation();
    const Eigen::Vector3d c = pose.translation();
    const double m = body.getLinkMass(k);
    const Eigen::Matrix3d cx = skew(c);
    Matrix6d& inertia = composite[std::size_t(k)];
    inertia.topLeftCorner<3, 3>() = r * toEigen(body.getLinkInertia(k)).asDiagonal() * r.transpose() - m * cx * cx;
    inertia.topRightCorner<3, 3>() = m * cx;
    inertia.bottomLeftCorner<3, 3>() = -m * cx;
    inertia.bottomRightCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
    const btMultibodyLink& link = body.getLink(k);
    Vector6d& s = motion[std::size_t(k)];
    if (link.m_jointType == btMultibodyLink::ePrismatic)
      s << Eigen::Vector3d::Zero(), r * toEigen(link.getAxisBottom(0));
    else
    {
      const Eigen::Vector3d axis = r * toEigen(link.getAxisTop(0));
      const Eigen::Vector3d pivot = c - r * toEigen(link.m_dVector);
      s << axis, pivot.cross(axis);
    }
  }
  for (int k = n_links - 1; k >= 0; --k)
  {
    const int parent = body.getParent(k);
    if (parent >= 0)
      composite[std::size_t(parent)] += composite[std::size_t(k)];
  }
  // Joint j of ArticulatedRobot sits on Bullet link joints()[j].link; map link -> joint index.
  const auto& joints = robot_.joints();
  std::vector<int> joint_of_link(std::size_t(n_links), -1);
  for (std::size_t j = 0; j < joints.size(); ++j)
    joint_of_link[std::size_t(joints[j].link)] = int(j);
  const Eigen::Index n = Eigen::Index(joints.size());
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n_links; ++k)
  {
    const int j = joint_of_link[std::size_t(k)];
    if (j < 0)
      continue;
    const Vector6d force = composite[std::size_t(k)] * motion[std::size_t(k)];
    for (int a = k; a >= 0; a = body.getParent(a))
    {
      const int i = joint_of_link[std::size_t(a)];
      if (i < 0)
        continue;
      const double value = motion[std::size_t(a)].dot(force);
      m(i, j) = value;
      m(j, i) = value;
    }
  }
  return m;
}

std::vector<double> StablePd::torques(double h) const
{
  const auto& joints = robot_.joints();
  const Eigen::Index n = Eigen::Index(driven_.size());
  std::vector<double> tau(joints.size(), 0.0);
  if (n == 0)
    return tau;
  const std::vector<double> q = robot_.positions();
  const std::vector<double> qd = robot_.velocities();
  const Eigen::MatrixXd full = inertia();
  const Eigen::VectorXd velocity = Eigen::Map<const Eigen::VectorXd>(qd.data(), Eigen::Index(qd.size()));
  Eigen::MatrixXd a = reduction_.transpose() * full * reduction_;
  Eigen::VectorXd rhs = reduction_.transpose() * (full * velocity);
  Eigen::VectorXd bias(n), gain(n);
  for (Eigen::Index r = 0; r < n; ++r)
  {
    const int j = driven_[std::size_t(r)];
    const JointDrive& drive = *robot_.drives()[std::size_t(joints[std::size_t(j)].drive)];
    const double k = drive.stiffness(), d = drive.damping();
    bias(r) = k * (drive.targetPosition() - q[std::size_t(j)]) + d * drive.targetVelocity();
    gain(r) = h * k + d;
    a(r, r) += h * gain(r);
    rhs(r) += h * bias(r);
  }
  const Eigen::VectorXd x = a.ldlt().solve(rhs);
  for (Eigen::Index r = 0; r < n; ++r)
  {
    const int j = driven_[std::size_t(r)];
    const double limit = robot_.drives()[std::size_t(joints[std::size_t(j)].drive)]->forceLimit();
    tau[std::size_t(j)] = std::clamp(bias(r) - gain(r) * x(r), -limit, limit);
  }
  return tau;
}
}  // namespace vrrw_physics
