#include <vrrw_kinematics/numeric_ik.h>

#include <chrono>
#include <cmath>
#include <limits>

namespace vrrw_kinematics
{
namespace
{
constexpr int kIterationsPerAttempt = 60;
constexpr double kMaxStep = 0.6;
}  // namespace

NumericIK::NumericIK(const KinematicChain& chain)
  : chain_(chain), lower_(chain.lowerLimits()), upper_(chain.upperLimits())
{
  for (std::size_t i = 0; i < chain.size(); ++i)
    if (chain.joints()[i].continuous)
    {
      lower_[static_cast<Eigen::Index>(i)] = -std::numeric_limits<double>::infinity();
      upper_[static_cast<Eigen::Index>(i)] = std::numeric_limits<double>::infinity();
    }
}

void NumericIK::clamp(Eigen::VectorXd& q) const
{
  q = q.cwiseMax(lower_).cwiseMin(upper_);
}

NumericIK::Error NumericIK::error(const Eigen::Isometry3d& target, const Eigen::Isometry3d& current,
                                  const IkOptions& options) const
{
  Error e;
  e.residual.head<3>() = target.translation() - current.translation();
  e.position = e.residual.head<3>().stableNorm();  // (norm() squares: a target 1e300 m away would be inf)
  if (options.mode == IkOptions::Mode::PositionOnly)
  {
    e.residual.tail<3>().setZero();
    return e;
  }
  const Eigen::Vector3d rotation = rotationError(target.linear(), current.linear());
  e.orientation = rotation.norm();
  if (options.mode == IkOptions::Mode::OrientationTolerant && e.orientation > 0.0)
    e.residual.tail<3>() = rotation * std::max(0.0, 1.0 - options.orientation_tolerance / e.orientation);
  else
    e.residual.tail<3>() = rotation;
  return e;
}

bool NumericIK::converged(const Error& e, const IkOptions& options) const
{
  if (e.position > options.tolerance)
    return false;
  switch (options.mode)
  {
    case IkOptions::Mode::PositionOnly: return true;
    case IkOptions::Mode::OrientationTolerant: return e.orientation <= options.orientation_tolerance + options.tolerance;
    case IkOptions::Mode::Full: break;
  }
  return e.orientation <= options.tolerance;
}

bool NumericIK::descend(const Eigen::Isometry3d& target, const IkOptions& options, Eigen::VectorXd& q, Error& e,
                        int max_iterations) const
{
  Eigen::Matrix<double, 6, Eigen::Dynamic> jac;
  Eigen::Isometry3d tip;
  Eigen::VectorXd candidate(q.size());
  const int rows = options.mode == IkOptions::Mode::PositionOnly ? 3 : 6;
  chain_.jacobian(q, tip, jac);
  e = error(target, tip, options);
  int slow = 0;
  for (int iteration = 0; iteration < max_iterations; ++iteration)
  {
    if (converged(e, options))
      return true;
    const double norm = e.residual.norm();
    const double damping = 1e-6 + 1e-3 * norm * norm;
    const auto dampedStep = [&](const Eigen::Matrix<double, 6, Eigen::Dynamic>& j) {
      Eigen::Matrix<double, 6, 6> a = j * j.transpose();
      a.diagonal().array() += damping;
      return Eigen::VectorXd(j.topRows(rows).transpose() * a.topLeftCorner(rows, rows).ldlt().solve(e.residual.head(rows)));
    };
    Eigen::VectorXd step = dampedStep(jac);
    // Joints at a limit that the step pushes further out are taken out of this step (active set).
    bool blocked = false;
    for (Eigen::Index i = 0; i < step.size(); ++i)
      if ((q[i] <= lower_[i] && step[i] < 0.0) || (q[i] >= upper_[i] && step[i] > 0.0))
      {
        jac.col(i).setZero();
        blocked = true;
      }
    if (blocked)
      step = dampedStep(jac);
    const double largest = step.cwiseAbs().maxCoeff();
    if (largest > kMaxStep)
      step *= kMaxStep / largest;
    Error next;
    for (int halving = 0; halving < 4; ++halving)
    {
      candidate = q + step;
      clamp(candidate);
      next = error(target, chain_.fk(candidate), options);
      if (next.residual.norm() < norm)
        break;
      step *= 0.5;
    }
    if (!(next.residual.norm() < norm))  // (also a step that came out NaN: a target 1e300 m away)
      return false;
    slow = next.residual.norm() > 0.9 * norm ? slow + 1 : 0;
    if (slow > 4)
      return false;
    q = candidate;
    chain_.jacobian(q, tip, jac);
    e = next;
  }
  return converged(e, options);
}

IkResult NumericIK::solve(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed, const IkOptions& options) const
{
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout));
  std::mt19937_64 rng(options.seed);
  IkResult result;
  Eigen::VectorXd q = seed;
  clamp(q);
  Error e;
  double best = std::numeric_limits<double>::infinity();
  double closest = std::numeric_limits<double>::infinity();
  while (true)
  {
    ++result.attempts;
    const bool solved = descend(target, options, q, e, kIterationsPerAttempt);
    if (solved && (q - seed).squaredNorm() < best)
    {
      best = (q - seed).squaredNorm();
      result.success = true;
      result.code = ErrorCode::Ok;
      result.q = q;
      result.position_error = e.position;
      result.orientation_error = e.orientation;
      if (!options.nearest)
        return result;
    }
    else if (!solved && !result.success && e.residual.stableNorm() < closest)
    {
      // A failure reports the residual of the attempt that came closest to the target.
      closest = e.residual.stableNorm();
      result.position_error = e.position;
      result.orientation_error = e.orientation;
    }
    if (Clock::now() >= deadline)
      break;
    q = chain_.randomState(rng);
  }
  if (result.success)
    return result;
  result.message = "no IK solution for tip " + chain_.tipLink() + " within " + std::to_string(options.timeout) +
                   " s (" + std::to_string(result.attempts) + " attempts; best position error " +
                   std::to_string(result.position_error) + " m)";
  return result;
}
}  // namespace vrrw_kinematics
