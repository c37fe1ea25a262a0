#include <vrrw_kinematics/top_grasp.h>

namespace vrrw_kinematics
{
Eigen::Isometry3d topGrasp(const Eigen::Isometry3d& object, const Eigen::Vector3d& point)
{
  Eigen::Matrix3d tool;
  tool.col(2) = -Eigen::Vector3d::UnitZ();
  Eigen::Vector3d across = object.rotation().col(1);
  across.z() = 0.0;
  tool.col(1) = across.normalized();
  tool.col(0) = tool.col(1).cross(tool.col(2));
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  tcp.linear() = tool;
  tcp.translation() = object * point;
  return tcp;
}
}  // namespace vrrw_kinematics
