#pragma once
#include <Eigen/Dense>
#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace vrrw_kinematics
{
inline Eigen::VectorXd toEigen(const ompl::base::State* state, std::size_t n)
{
  const double* values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
  return Eigen::Map<const Eigen::VectorXd>(values, static_cast<Eigen::Index>(n));
}

inline void fromEigen(const Eigen::VectorXd& q, ompl::base::State* state)
{
  double* values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
  for (Eigen::Index i = 0; i < q.size(); ++i)
    values[i] = q[i];
}
}  // namespace vrrw_kinematics
