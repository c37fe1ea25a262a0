#pragma once
#include <cstdint>
#include <ompl/base/StateSampler.h>
#include <random>

namespace vrrw_kinematics
{
/// \brief Uniform sampling of a RealVectorStateSpace from its own seeded generator, so a seeded query repeats.
class SeededStateSampler : public ompl::base::StateSampler
{
public:
  SeededStateSampler(const ompl::base::StateSpace* space, std::uint64_t seed);

  void sampleUniform(ompl::base::State* state) override;
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double std_dev) override;

private:
  std::mt19937_64 engine_;
};
}  // namespace vrrw_kinematics
