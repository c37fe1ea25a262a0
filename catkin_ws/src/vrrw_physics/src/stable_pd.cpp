#include <vrrw_physics/articulated_robot.h>
#include <vrrw_physics/stable_pd.h>

#include <Eigen/Cholesky>

#include <algorithm>

namespace vrrw_physics
{

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
  reduction_ = JointMatrix::Zero(Eigen::Index(joints.size()), Eigen::Index(driven_.size()));
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

std::vector<double> StablePd::torques(double h, const JointMatrix& full, const std::vector<double>& external) const
{
  const auto& joints = robot_.joints();
  const Eigen::Index n = Eigen::Index(driven_.size());
  std::vector<double> tau(joints.size(), 0.0);
  if (n == 0)
    return tau;
  const std::vector<double> q = robot_.positions();
  const std::vector<double> qd = robot_.velocities();
  const JointVector velocity = Eigen::Map<const Eigen::VectorXd>(qd.data(), Eigen::Index(qd.size()));
  JointMatrix a = reduction_.transpose() * full * reduction_;
  const JointVector forces = Eigen::Map<const Eigen::VectorXd>(external.data(), Eigen::Index(external.size()));
  JointVector rhs = reduction_.transpose() * (full * velocity + h * forces);
  JointVector bias(n), gain(n);
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
  const JointVector x = a.ldlt().solve(rhs);
  for (Eigen::Index r = 0; r < n; ++r)
  {
    const int j = driven_[std::size_t(r)];
    const double limit = robot_.drives()[std::size_t(joints[std::size_t(j)].drive)]->forceLimit();
    tau[std::size_t(j)] = std::clamp(bias(r) - gain(r) * x(r), -limit, limit);
  }
  return tau;
}
}  // namespace vrrw_physics
