#include <vrrw_physics/joint_drive.h>

#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

namespace vrrw_physics
{
JointDrive::JointDrive(btMultiBody* body, int link, const JointSpaceResponse* response)
  : SoftJointConstraint(body, link, 1.0, -1, 0.0, MULTIBODY_CONSTRAINT_1DOF_JOINT_MOTOR, response)
{
  finalizeMultiDof();
}

JointCoupling::JointCoupling(btMultiBody* body, int mimic_link, int master_link, double multiplier, double offset,
                             const JointSpaceResponse* response)
  : SoftJointConstraint(body, mimic_link, 1.0, master_link, -multiplier, MULTIBODY_CONSTRAINT_GEAR, response)
{
  finalizeMultiDof();
  setTarget(offset, 0.0);
}
}  // namespace vrrw_physics
