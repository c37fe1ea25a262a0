#include "seeded_state_sampler.h"

#include <algorithm>
#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace vrrw_kinematics
{
namespace ob = ompl::base;

SeededStateSampler::SeededStateSampler(const ob::StateSpace* space, std::uint64_t seed)
  : ob::StateSampler(space), engine_(seed)
{
}

void SeededStateSampler::sampleUniform(ob::State* state)
{
  const auto& bounds = space_->as<ob::RealVectorStateSpace>()->getBounds();
  double* values = state->as<ob::RealVectorStateSpace::StateType>()->values;
  for (std::size_t i = 0; i < bounds.low.size(); ++i)
    values[i] = std::uniform_real_distribution<double>(bounds.low[i], bounds.high[i])(engine_);
}

void SeededStateSampler::sampleUniformNear(ob::State* state, const ob::State* near, double distance)
{
  const auto& bounds = space_->as<ob::RealVectorStateSpace>()->getBounds();
  double* values = state->as<ob::RealVectorStateSpace::StateType>()->values;
  const double* center = near->as<ob::RealVectorStateSpace::StateType>()->values;
  for (std::size_t i = 0; i < bounds.low.size(); ++i)
    values[i] = std::uniform_real_distribution<double>(std::max(bounds.low[i], center[i] - distance),
                                                       std::min(bounds.high[i], center[i] + distance))(engine_);
}

void SeededStateSampler::sampleGaussian(ob::State* state, const ob::State* mean, double std_dev)
{
  const auto& bounds = space_->as<ob::RealVectorStateSpace>()->getBounds();
  double* values = state->as<ob::RealVectorStateSpace::StateType>()->values;
  const double* center = mean->as<ob::RealVectorStateSpace::StateType>()->values;
  for (std::size_t i = 0; i < bounds.low.size(); ++i)
    values[i] = std::min(bounds.high[i],
                         std::max(bounds.low[i], std::normal_distribution<double>(center[i], std_dev)(engine_)));
}
}  // namespace vrrw_kinematics
