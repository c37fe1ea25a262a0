#include <vrrw_physics/joint_row_solver.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include <cstdint>
#include <cstring>

namespace vrrw_physics
{
namespace
{
/// x == 0 (+0 or -0) by its bits: an integer test, no floating-point compare.
bool isZero(btScalar x)
{
  static_assert(sizeof(btScalar) == 4 || sizeof(btScalar) == 8, "btScalar is float or double");
  if constexpr (sizeof(btScalar) == 4)
  {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof(bits));
    return (bits & 0x7fffffffu) == 0;
  }
  else
  {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof(bits));
    return (bits & 0x7fffffffffffffffull) == 0;
  }
}
}  // namespace

void JointRowSolver::indexRows()
{
  const int n = m_multiBodyNonContactConstraints.size();
  rows_.resize(std::size_t(n));
  for (int r = 0; r < n; ++r)
  {
    const btMultiBodySolverConstraint& c = m_multiBodyNonContactConstraints[r];
    SparseRow& row = rows_[std::size_t(r)];
    row.terms = -1;
    // Only rows on one multibody and nothing else; the rest keep Bullet's generic path.
    if (!c.m_multiBodyA || c.m_multiBodyB || c.m_solverBodyIdB >= 0)
      continue;
    const int size = c.m_multiBodyA->getNumDofs() + 6;
    const btScalar* jacobian = &m_data.m_jacobians[c.m_jacAindex];
    const btScalar* response = &m_data.m_deltaVelocitiesUnitImpulse[c.m_jacAindex];
    // Branch-free scan (the nonzero positions differ from row to row): a bit per nonzero entry, then
    // the set bits in ascending order.
    std::uint64_t nonzero = 0;
    for (int i = 0; i < size && i < 64; ++i)
      nonzero |= std::uint64_t(!isZero(jacobian[i])) << i;
    int terms = 0;
    for (int i = 64; i < size; ++i)
      terms += isZero(jacobian[i]) ? 0 : kMaxTerms + 1;  // beyond 64 dofs: generic path
    for (; nonzero != 0 && terms <= kMaxTerms; nonzero &= nonzero - 1)
    {
      if (terms < kMaxTerms)
        row.jacobian[terms] = __builtin_ctzll(nonzero);
      ++terms;
    }
    if (terms > kMaxTerms)
      continue;
    row.terms = terms;
    int begin = 0, end = size;
    while (begin < end && isZero(response[begin]))
      ++begin;
    while (end > begin && isZero(response[end - 1]))
      --end;
    row.response_begin = begin;
    row.response_end = end;
  }
}

btScalar JointRowSolver::resolveSparse(const btMultiBodySolverConstraint& c, const SparseRow& row)
{
  // Same operations, in the same order and precision, as resolveSingleConstraintRowGeneric for a row on
  // one multibody; only exact-zero terms are left out.
  const btScalar* jacobian = &m_data.m_jacobians[c.m_jacAindex];
  const btScalar* response = &m_data.m_deltaVelocitiesUnitImpulse[c.m_jacAindex];
  btScalar* delta_v = &m_data.m_deltaVelocities[c.m_deltaVelAindex];

  btScalar delta_impulse = c.m_rhs - btScalar(c.m_appliedImpulse) * c.m_cfm;
  btScalar rate = 0;
  for (int k = 0; k < row.terms; ++k)
    rate += jacobian[row.jacobian[k]] * delta_v[row.jacobian[k]];
  const btScalar rate_b = 0;
  delta_impulse -= rate * c.m_jacDiagABInv;
  delta_impulse -= rate_b * c.m_jacDiagABInv;
  const btScalar sum = btScalar(c.m_appliedImpulse) + delta_impulse;
  if (sum < c.m_lowerLimit)
  {
    delta_impulse = c.m_lowerLimit - c.m_appliedImpulse;
    c.m_appliedImpulse = c.m_lowerLimit;
  }
  else if (sum > c.m_upperLimit)
  {
    delta_impulse = c.m_upperLimit - c.m_appliedImpulse;
    c.m_appliedImpulse = c.m_upperLimit;
  }
  else
    c.m_appliedImpulse = sum;
  // Bullet's solver also moves the body's own delta velocity in step (DIRECTLY_UPDATE_VELOCITY_DURING_
  // SOLVER_ITERATIONS, applyDeltaVeeMultiDof2); that array has only a const accessor, the body is not const.
  btScalar* body_delta_v = const_cast<btScalar*>(c.m_multiBodyA->getDeltaVelocityVector());
  for (int i = row.response_begin; i < row.response_end; ++i)
  {
    const btScalar change = response[i] * delta_impulse;  // the same product Bullet forms twice
    delta_v[i] += change;
    body_delta_v[i] += change;
  }
  return delta_impulse / c.m_jacDiagABInv;
}

btScalar JointRowSolver::solveSingleIteration(int iteration, btCollisionObject** bodies, int numBodies,
                                              btPersistentManifold** manifoldPtr, int numManifolds,
                                              btTypedConstraint** constraints, int numConstraints,
                                              const btContactSolverInfo& infoGlobal, btIDebugDraw* debugDrawer)
{
  // Bullet 3.24's btMultiBodyConstraintSolver::solveSingleIteration sweeps rigid-body rows, then the multibody
  // joint rows (inner sweeps, alternating direction), then multibody contacts and friction. With
  // joint_rows_last_ the joint rows come after the contacts (see the class comment); the squared residual is
  // the largest of all either way.
  btScalar residual = btSequentialImpulseConstraintSolver::solveSingleIteration(
      iteration, bodies, numBodies, manifoldPtr, numManifolds, constraints, numConstraints, infoGlobal, debugDrawer);
  if (iteration == 0 || rows_.size() != std::size_t(m_multiBodyNonContactConstraints.size()))
    indexRows();
  if (joint_rows_last_)
  {
    residual = btMax(residual, solveContactRows(iteration, infoGlobal));
    return btMax(residual, solveJointRows(iteration, infoGlobal));
  }
  residual = btMax(residual, solveJointRows(iteration, infoGlobal));
  return btMax(residual, solveContactRows(iteration, infoGlobal));
}

btScalar JointRowSolver::solveJointRows(int iteration, const btContactSolverInfo& infoGlobal)
{
  const int n = m_multiBodyNonContactConstraints.size();
  // Bullet alternates the direction every sweep (symmetric Gauss-Seidel converges faster).
  const bool ascending = iteration & 1;
  btScalar joint_residual = 0;
  for (int inner = 0; inner < infoGlobal.m_numNonContactInnerIterations; ++inner)
  {
    joint_residual = 0;
    for (int j = 0; j < n; ++j)
    {
      const int r = ascending ? j : n - 1 - j;
      btMultiBodySolverConstraint& c = m_multiBodyNonContactConstraints[r];
      const SparseRow& row = rows_[std::size_t(r)];
      const btScalar change = row.terms >= 0 ? resolveSparse(c, row) : resolveSingleConstraintRowGeneric(c);
      joint_residual = btMax(joint_residual, change * change);
      if (c.m_multiBodyA)
        c.m_multiBodyA->setPosUpdated(false);
      if (c.m_multiBodyB)
        c.m_multiBodyB->setPosUpdated(false);
    }
  }
  return joint_residual;
}

btScalar JointRowSolver::solveContactRows(int iteration, const btContactSolverInfo& infoGlobal)
{
  btScalar residual = 0;
  const auto touched = [](btMultiBodySolverConstraint& c) {
    if (c.m_multiBodyA)
      c.m_multiBodyA->setPosUpdated(false);
    if (c.m_multiBodyB)
      c.m_multiBodyB->setPosUpdated(false);
  };
  for (int j = 0; j < m_multiBodyNormalContactConstraints.size(); ++j)
  {
    btMultiBodySolverConstraint& c = m_multiBodyNormalContactConstraints[j];
    btScalar change = 0;
    if (iteration < infoGlobal.m_numIterations)
      change = resolveSingleConstraintRowGeneric(c);
    residual = btMax(residual, change * change);
    touched(c);
  }
  if (iteration >= infoGlobal.m_numIterations)
    return residual;
  const auto normalImpulse = [this](const btMultiBodySolverConstraint& c) {
    return btScalar(m_multiBodyNormalContactConstraints[c.m_frictionIndex].m_appliedImpulse);
  };
  const auto bound = [](btMultiBodySolverConstraint& c, btScalar total) {
    c.m_lowerLimit = -(c.m_friction * total);
    c.m_upperLimit = c.m_friction * total;
  };
  const auto solveFrictionRow = [&](btMultiBodySolverConstraint& c) {
    const btScalar total = normalImpulse(c);
    if (total > btScalar(0))
    {
      bound(c, total);
      const btScalar change = resolveSingleConstraintRowGeneric(c);
      residual = btMax(residual, change * change);
      touched(c);
    }
  };
  if ((infoGlobal.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) &&
      (infoGlobal.m_solverMode & SOLVER_DISABLE_IMPLICIT_CONE_FRICTION) == 0)
  {
    for (int j = 0; j < m_multiBodySpinningFrictionContactConstraints.size(); ++j)
      solveFrictionRow(m_multiBodySpinningFrictionContactConstraints[j]);
    for (int j = 0; j < m_multiBodyTorsionalFrictionContactConstraints.size(); ++j)
    {
      btMultiBodySolverConstraint& a = m_multiBodyTorsionalFrictionContactConstraints[j];
      const btScalar total = normalImpulse(a);
      ++j;
      btMultiBodySolverConstraint& b = m_multiBodyTorsionalFrictionContactConstraints[j];
      if (total > btScalar(0) && a.m_frictionIndex == b.m_frictionIndex)
      {
        bound(a, total);
        bound(b, total);
        const btScalar change = resolveConeFrictionConstraintRows(a, b);
        residual = btMax(residual, change * change);
        touched(a);
        touched(b);
      }
    }
    for (int j = 0; j < m_multiBodyFrictionContactConstraints.size(); ++j)
    {
      btMultiBodySolverConstraint& a = m_multiBodyFrictionContactConstraints[j];
      const btScalar total = normalImpulse(a);
      ++j;
      btMultiBodySolverConstraint& b = m_multiBodyFrictionContactConstraints[j];
      if (a.m_frictionIndex == b.m_frictionIndex)
      {
        bound(a, total);
        bound(b, total);
        const btScalar change = resolveConeFrictionConstraintRows(a, b);
        residual = btMax(residual, change * change);
        touched(b);
        touched(a);
      }
    }
  }
  else
  {
    for (int j = 0; j < m_multiBodyFrictionContactConstraints.size(); ++j)
      solveFrictionRow(m_multiBodyFrictionContactConstraints[j]);
  }
  return residual;
}
}  // namespace vrrw_physics
