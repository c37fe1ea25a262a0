#include <vrrw_skills/poses.h>

#include <vrrw_dmp/quaternion_maps.h>

namespace vrrw_skills
{
Eigen::Isometry3d toIsometry(const CartesianPose& pose)
{
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.translation() = pose.position;
  transform.linear() = pose.orientation.normalized().toRotationMatrix();
  return transform;
}

CartesianPose toPose(const Eigen::Isometry3d& transform)
{
  CartesianPose pose;
  pose.position = transform.translation();
  pose.orientation = Eigen::Quaterniond(transform.rotation()).normalized();
  if (pose.orientation.w() < 0.0)
    pose.orientation.coeffs() = -pose.orientation.coeffs();
  return pose;
}

CartesianPose relativeTo(const CartesianPose& frame, const CartesianPose& pose)
{
  return toPose(toIsometry(frame).inverse() * toIsometry(pose));
}

CartesianPose inWorld(const CartesianPose& frame, const CartesianPose& relative)
{
  return toPose(toIsometry(frame) * toIsometry(relative));
}

CartesianPose averagePose(const std::vector<CartesianPose>& poses)
{
  CartesianPose mean;
  mean.position.setZero();
  Eigen::Vector4d sum = Eigen::Vector4d::Zero();
  for (const CartesianPose& pose : poses)
  {
    mean.position += pose.position;
    const Eigen::Vector4d q = pose.orientation.coeffs();
    sum += q.dot(poses.front().orientation.coeffs()) < 0.0 ? Eigen::Vector4d(-q) : q;
  }
  mean.position /= static_cast<double>(poses.size());
  mean.orientation = Eigen::Quaterniond(sum[3], sum[0], sum[1], sum[2]).normalized();
  return mean;
}

double positionDistance(const CartesianPose& a, const CartesianPose& b)
{
  return (a.position - b.position).norm();
}

double angleDistance(const CartesianPose& a, const CartesianPose& b)
{
  return vrrw_dmp::angleBetween(a.orientation, b.orientation);
}
}  // namespace vrrw_skills
