#include <algorithm>
#include <vrrw_control/spline_segment.h>

namespace vrrw_control
{
SplineSegment::SplineSegment(Order order, double duration, double q0, double v0, double a0, double q1, double v1,
                             double a1)
  : order_(order), duration_(duration)
{
  const double T = duration, dq = q1 - q0;
  c_[0] = q0;
  if (T <= 0.0)
  {
    order_ = Order::Linear;
    return;
  }
  switch (order_)
  {
    case Order::Linear:
      c_[1] = dq / T;
      break;
    case Order::Cubic:
      c_[1] = v0;
      c_[2] = (3.0 * dq - (2.0 * v0 + v1) * T) / (T * T);
      c_[3] = (-2.0 * dq + (v0 + v1) * T) / (T * T * T);
      break;
    case Order::Quintic:
    {
      const double T2 = T * T, T3 = T2 * T;
      c_[1] = v0;
      c_[2] = 0.5 * a0;
      c_[3] = (20.0 * dq - (8.0 * v1 + 12.0 * v0) * T - (3.0 * a0 - a1) * T2) / (2.0 * T3);
      c_[4] = (-30.0 * dq + (14.0 * v1 + 16.0 * v0) * T + (3.0 * a0 - 2.0 * a1) * T2) / (2.0 * T3 * T);
      c_[5] = (12.0 * dq - 6.0 * (v1 + v0) * T - (a0 - a1) * T2) / (2.0 * T3 * T2);
      break;
    }
  }
}

void SplineSegment::sample(double tau, double& q, double& v, double& a) const
{
  const double t = std::clamp(tau, 0.0, std::max(duration_, 0.0));
  q = c_[0] + t * (c_[1] + t * (c_[2] + t * (c_[3] + t * (c_[4] + t * c_[5]))));
  v = c_[1] + t * (2.0 * c_[2] + t * (3.0 * c_[3] + t * (4.0 * c_[4] + t * 5.0 * c_[5])));
  a = 2.0 * c_[2] + t * (6.0 * c_[3] + t * (12.0 * c_[4] + t * 20.0 * c_[5]));
}
}  // namespace vrrw_control
