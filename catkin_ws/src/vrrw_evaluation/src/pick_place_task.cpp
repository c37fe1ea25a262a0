#include <vrrw_evaluation/pick_place_task.h>
#include <vrrw_kinematics/top_grasp.h>

namespace vrrw_evaluation
{
bool isGripperInstruction(const std::string& name)
{
  return name == "close_gripper" || name == "open_gripper";
}

Eigen::Isometry3d tcpAtGrasp(const Eigen::Isometry3d& drill, const GraspGeometry& grasp)
{
  return vrrw_kinematics::topGrasp(drill, grasp.grasp_point);
}

Eigen::Isometry3d tcpAtNearPick(const Eigen::Isometry3d& drill, const GraspGeometry& grasp)
{
  Eigen::Isometry3d tcp = tcpAtGrasp(drill, grasp);
  tcp.translation().z() += grasp.approach;
  return tcp;
}

Eigen::Isometry3d drillInHand(const Eigen::Isometry3d& tcp, const Eigen::Isometry3d& drill_at_grasp,
                              const Eigen::Isometry3d& tcp_at_grasp)
{
  return tcp * (tcp_at_grasp.inverse() * drill_at_grasp);
}

Eigen::Isometry3d interpolatePose(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to, double s)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = from.translation() + s * (to.translation() - from.translation());
  pose.linear() = Eigen::Quaterniond(from.rotation()).slerp(s, Eigen::Quaterniond(to.rotation())).toRotationMatrix();
  return pose;
}
}  // namespace vrrw_evaluation
