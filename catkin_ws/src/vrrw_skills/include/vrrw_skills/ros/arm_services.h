#pragma once
// The planning node's services for one arm, as the planner's ArmKinematics: compute_ik, check_path,
// compute_fk and attach_object, each over a persistent connection.
#include <string>
#include <vector>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_skills/skill_plan.h>

namespace vrrw_skills
{
class ArmServices : public ArmKinematics
{
public:
  ArmServices(vrrw_common::PersistentServices& services, std::string robot, std::vector<std::string> arm_joints);

  IkAnswer ik(const CartesianPose& tcp, const std::vector<double>& seed, bool avoid_collisions) override;
  std::vector<ContactPair> checkPath(const std::vector<std::vector<double>>& path) override;
  CartesianPose tcp(const std::vector<double>& joints) override;
  /// \brief Fixes \a object to the TCP in the planning scene (it moves with the arm and may touch the gripper),
  /// or frees it where it is. Throws SkillRefusal with the node's message.
  void attach(const std::string& object, bool attach);

private:
  vrrw_common::PersistentServices& services_;
  std::string robot_;
  std::vector<std::string> arm_joints_;
};
}  // namespace vrrw_skills
