#pragma once
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

#include <vector>

namespace vrrw_physics
{
/// \brief Bullet's multibody sequential-impulse solver with sparse sweeps over the joint rows.
///
/// A joint row (drive, coupling, limit) acts on one or two joint coordinates, yet Bullet's
/// resolveSingleConstraintRowGeneric takes the dot product of its Jacobian with the delta velocities
/// over all dofs + 6 of the robot, and adds the unit-impulse response over all of them, in every sweep.
/// This solver does the same Gauss-Seidel sweeps in the same order with the same single-precision
/// operations, but skips the terms whose Jacobian or response entry is exactly zero (adding them
/// changes no finite sum): the results are bit-identical to btMultiBodyConstraintSolver's (Bullet
/// 3.24) as long as the velocities are finite. Contacts and friction rows go through Bullet's own code.
///
/// Order (joint_rows_last, the default): Bullet solves a sweep's joint rows before its contacts, so a step
/// ends with the velocities the last contact and friction rows left, not the ones the drives last saw. Under a
/// squeeze (fingers pressing a held object) 30 sweeps stop short of converging and the rows after a drive's
/// last visit move its joint by the same dv every step; the drive takes that for motion and its damping answers
/// it: the joint settles where K e = D dv, an offset of (D / K) dv = 0.8 s x dv with the rigid gains, while
/// its effort stays near zero. So the joint rows come after the contacts: the drives see the velocities the
/// step ends with, and what stays unconverged is a contact's, a penetration that its position correction takes
/// up. The UR5e holding the drill stretched out, default sweeps (test_grasping): worst arm joint 3.6 mrad off
/// with a 70 N grip before, 0.66 mrad after; 4.2 mrad with the rated 235 N after. The direction of each sweep
/// stays Bullet's (alternating, the last one ascending: the gripper's couplings last): reversed, the 2F-85's
/// linkage diverged in free motion (a finger at 70 rad/s) and the drill slipped out of a lifting grasp.
/// Without contacts the order changes nothing. false: Bullet's order, the bit-identical reference of
/// test_joint_row_solver.
ATTRIBUTE_ALIGNED16(class) JointRowSolver : public btMultiBodyConstraintSolver
{
public:
  BT_DECLARE_ALIGNED_ALLOCATOR();

  explicit JointRowSolver(bool joint_rows_last = true) : joint_rows_last_(joint_rows_last) {}

protected:
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int numBodies,
                                btPersistentManifold** manifoldPtr, int numManifolds,
                                btTypedConstraint** constraints, int numConstraints,
                                const btContactSolverInfo& infoGlobal, btIDebugDraw* debugDrawer) override;

private:
  /// Where a non-contact row is nonzero: at most kMaxTerms Jacobian entries, and the response (unit-impulse
  /// delta velocity) between response_begin and response_end. terms < 0: Bullet's generic path.
  static constexpr int kMaxTerms = 4;
  struct SparseRow
  {
    int terms = -1;
    int jacobian[kMaxTerms] = {};
    int response_begin = 0;
    int response_end = 0;
  };
  void indexRows();
  /// The joint rows' inner sweeps (alternating direction by `iteration`); their squared residual.
  btScalar solveJointRows(int iteration, const btContactSolverInfo& infoGlobal);
  /// The multibody contact and friction rows, as Bullet's sweep; their squared residual.
  btScalar solveContactRows(int iteration, const btContactSolverInfo& infoGlobal);
  btScalar resolveSparse(const btMultiBodySolverConstraint& c, const SparseRow& row);

  bool joint_rows_last_;
  std::vector<SparseRow> rows_;
};
}  // namespace vrrw_physics
