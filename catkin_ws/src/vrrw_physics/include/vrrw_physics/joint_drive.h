#pragma once
#include <vrrw_physics/soft_joint_constraint.h>

namespace vrrw_physics
{
/// \brief A joint drive with PhysX articulation semantics, solved implicitly:
/// effort = K*(q_target - q) - D*(qd - qd_target), |effort| <= max_force.
class JointDrive : public SoftJointConstraint
{
public:
  /// \brief Drive of the 1-dof joint whose child is Bullet link `link` of `body`.
  JointDrive(btMultiBody* body, int link, const JointSpaceResponse* response = nullptr);
};

/// \brief Mimic joint of a URDF: keeps q_mimic = multiplier * q_master + offset (stiff, implicit).
class JointCoupling : public SoftJointConstraint
{
public:
  JointCoupling(btMultiBody* body, int mimic_link, int master_link, double multiplier, double offset,
                const JointSpaceResponse* response = nullptr);
};
}  // namespace vrrw_physics
