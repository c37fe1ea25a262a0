#pragma once
#include <array>

namespace vrrw_control
{
/// \brief One joint between two trajectory points: quintic when both ends carry accelerations,
/// cubic Hermite when both carry velocities, linear otherwise (as joint_trajectory_controller).
class SplineSegment
{
public:
  enum class Order { Linear, Cubic, Quintic };

  /// \brief Segment over [0, duration] from (q0, v0, a0) to (q1, v1, a1).
  SplineSegment(Order order, double duration, double q0, double v0, double a0, double q1, double v1, double a1);

  /// \brief Position, velocity and acceleration at tau in [0, duration] (clamped).
  void sample(double tau, double& q, double& v, double& a) const;

  Order order() const { return order_; }

private:
  Order order_;
  double duration_;
  std::array<double, 6> c_{};
};
}  // namespace vrrw_control
