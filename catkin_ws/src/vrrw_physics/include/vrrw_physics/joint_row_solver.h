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
ATTRIBUTE_ALIGNED16(class) JointRowSolver : public btMultiBodyConstraintSolver
{
public:
  BT_DECLARE_ALIGNED_ALLOCATOR();

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
  btScalar resolveSparse(const btMultiBodySolverConstraint& c, const SparseRow& row);

  std::vector<SparseRow> rows_;
};
}  // namespace vrrw_physics
