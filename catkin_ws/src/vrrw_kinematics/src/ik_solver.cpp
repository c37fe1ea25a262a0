#include <vrrw_kinematics/ik_solver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

namespace vrrw_kinematics
{
namespace
{
double largestJump(const Eigen::VectorXd& q, const Eigen::VectorXd& seed)
{
  return (q - seed).cwiseAbs().maxCoeff();
}

std::string number(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", value);
  return text;
}

/// Keeps why the solutions seen were refused, so that a failure names the reason of the nearest one.
class SolutionFilter
{
public:
  SolutionFilter(const Eigen::VectorXd& seed, double max_jump, const CollisionTest& collides)
    : seed_(seed), max_jump_(max_jump), collides_(collides)
  {
  }

  /// True when `q` lies within the jump bound of the seed and touches nothing.
  bool accepts(const Eigen::VectorXd& q)
  {
    const double jump = largestJump(q, seed_);
    nearest_jump_ = std::min(nearest_jump_, jump);
    if (jump > max_jump_)
      return false;
    const Contact contact = collides_(q);
    if (!contact.collision)
      return true;
    const double distance = (q - seed_).squaredNorm();
    if (distance < collided_distance_)
    {
      collided_distance_ = distance;
      contact_ = contact;
    }
    return false;
  }

  /// Fills code, message, contact and jump for the solutions seen; NoSolution when there were none.
  void explainFailure(const std::string& tip, IkResult& result) const
  {
    if (contact_.collision)
    {
      result.code = ErrorCode::InCollision;
      result.contact = contact_;
      result.message = "IK for " + tip + ": the nearest solution" +
                       (std::isfinite(max_jump_) ? " within " + number(max_jump_) + " of the seed" : std::string()) +
                       " is in collision (" + contact_.body_a + " - " + contact_.body_b + ")";
    }
    else if (std::isfinite(nearest_jump_))
    {
      result.code = ErrorCode::JointJump;
      result.jump = nearest_jump_;
      result.message = "IK for " + tip + ": the nearest solution moves a joint " + number(nearest_jump_) +
                       " from the seed, more than the " + number(max_jump_) + " allowed (a branch flip)";
    }
    else
    {
      result.code = ErrorCode::NoSolution;
      result.message = "IK for " + tip + ": unreachable within the joint limits (residual " +
                       number(result.position_error) + " m, " + number(result.orientation_error) + " rad)";
    }
  }

private:
  Eigen::VectorXd seed_;
  double max_jump_;
  const CollisionTest& collides_;
  double nearest_jump_ = std::numeric_limits<double>::infinity();
  double collided_distance_ = std::numeric_limits<double>::infinity();
  Contact contact_;
};

/// One Newton descent from the start point, no restarts.
IkOptions singleDescent(const IkOptions& options)
{
  IkOptions once = options;
  once.timeout = 0.0;
  once.nearest = false;
  return once;
}
}  // namespace

IkSolver::IkSolver(const KinematicChain& chain)
  : chain_(chain), analytic_(URAnalyticIK::detect(chain)), numeric_(chain)
{
}

std::string invalidPoseReason(const Eigen::Isometry3d& pose)
{
  if (!pose.matrix().allFinite())
    return "pose contains NaN or infinity";
  const Eigen::Matrix3d r = pose.linear();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 || r.determinant() < 0.0)
    return "pose orientation is not a rotation";
  return "";
}

Eigen::Isometry3d poseFromQuaternion(const Eigen::Vector3d& position, const Eigen::Vector4d& xyzw, double tolerance)
{
  if (!position.allFinite() || !xyzw.allFinite())
    throw KinematicsError(ErrorCode::InvalidPose, "pose: NaN or infinite value");
  if (std::abs(xyzw.norm() - 1.0) > tolerance)
    throw KinematicsError(ErrorCode::InvalidPose,
                          "pose: quaternion norm " + std::to_string(xyzw.norm()) + " is not 1");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = position;
  pose.linear() = Eigen::Quaterniond(xyzw[3], xyzw[0], xyzw[1], xyzw[2]).normalized().toRotationMatrix();
  return pose;
}

std::optional<IkResult> IkSolver::badInput(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed) const
{
  IkResult result;
  const std::string reason = invalidPoseReason(target);
  if (!reason.empty())
  {
    result.code = ErrorCode::InvalidPose;
    result.message = "IK target for " + chain_.tipLink() + ": " + reason;
    return result;
  }
  if (static_cast<std::size_t>(seed.size()) != chain_.size() || !seed.allFinite())
  {
    result.code = ErrorCode::InvalidArgument;
    result.message = "IK seed: expected " + std::to_string(chain_.size()) + " finite joint values, got " +
                     std::to_string(seed.size());
    return result;
  }
  return std::nullopt;
}

bool IkSolver::closedFormApplies(const IkOptions& options) const
{
  return analytic_ && options.allow_analytic && options.mode == IkOptions::Mode::Full;
}

IkResult IkSolver::solve(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed, const IkOptions& options) const
{
  if (auto bad = badInput(target, seed))
    return *bad;
  if (!closedFormApplies(options))
    return numeric_.solve(target, seed, options);
  IkResult result;
  result.attempts = 1;
  if (!analytic_->solveNearest(target, seed, result.q))
  {
    result.code = ErrorCode::NoSolution;
    result.message = "no IK solution for tip " + chain_.tipLink() + ": pose unreachable within joint limits";
    return result;
  }
  const Eigen::Isometry3d reached = chain_.fk(result.q);
  result.position_error = (reached.translation() - target.translation()).norm();
  result.orientation_error = rotationError(target.linear(), reached.linear()).norm();
  if (result.position_error > options.tolerance || result.orientation_error > options.tolerance)
    return numeric_.solve(target, result.q, options);  // near a wrist singularity the closed form loses digits
  result.success = true;
  result.code = ErrorCode::Ok;
  return result;
}

std::vector<Eigen::VectorXd> IkSolver::solveAll(const Eigen::Isometry3d& target, const Eigen::VectorXd& reference) const
{
  if (!analytic_ || !invalidPoseReason(target).empty())
    return {};
  return analytic_->solveAll(target, reference);
}

std::vector<Eigen::VectorXd> IkSolver::closedFormCandidates(const Eigen::Isometry3d& target,
                                                            const Eigen::VectorXd& seed, const IkOptions& options,
                                                            IkResult& residual) const
{
  const IkOptions once = singleDescent(options);
  std::vector<Eigen::VectorXd> candidates;
  for (const Eigen::VectorXd& q : analytic_->solveAll(target, seed))
  {
    const Eigen::Isometry3d reached = chain_.fk(q);
    if ((reached.translation() - target.translation()).norm() <= options.tolerance &&
        rotationError(target.linear(), reached.linear()).norm() <= options.tolerance)
      candidates.push_back(q);
    else if (const IkResult polished = numeric_.solve(target, q, once); polished.success)
      candidates.push_back(polished.q);
  }
  if (candidates.empty())
  {
    // Nothing within the limits: a descent from the seed measures how far the target is out of reach.
    const IkResult descent = numeric_.solve(target, seed, once);
    if (descent.success)
      candidates.push_back(descent.q);
    residual.position_error = descent.position_error;
    residual.orientation_error = descent.orientation_error;
  }
  std::sort(candidates.begin(), candidates.end(), [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return (a - seed).squaredNorm() < (b - seed).squaredNorm();
  });
  return candidates;
}

Eigen::VectorXd IkSolver::restartSeed(const Eigen::VectorXd& seed, double max_jump, std::mt19937_64& rng) const
{
  Eigen::VectorXd q = chain_.randomState(rng);
  if (!std::isfinite(max_jump))
    return q;
  for (std::size_t i = 0; i < chain_.size(); ++i)
  {
    const ChainJoint& joint = chain_.joints()[i];
    const Eigen::Index j = static_cast<Eigen::Index>(i);
    const double low = joint.continuous ? seed[j] - max_jump : std::max(joint.lower, seed[j] - max_jump);
    const double high = joint.continuous ? seed[j] + max_jump : std::min(joint.upper, seed[j] + max_jump);
    q[j] = std::uniform_real_distribution<double>(low, std::max(low, high))(rng);
  }
  return q;
}

IkResult IkSolver::solveCollisionFree(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed,
                                      const IkOptions& options, const CollisionTest& collides) const
{
  if (auto bad = badInput(target, seed))
    return *bad;
  SolutionFilter filter(seed, options.max_jump, collides);
  IkResult result;
  const auto solved = [&](const Eigen::VectorXd& q) {
    const Eigen::Isometry3d reached = chain_.fk(q);
    result.success = true;
    result.code = ErrorCode::Ok;
    result.message.clear();
    result.q = q;
    result.position_error = (reached.translation() - target.translation()).norm();
    result.orientation_error = rotationError(target.linear(), reached.linear()).norm();
    result.jump = largestJump(q, seed);
    return result;
  };
  if (closedFormApplies(options))
  {
    result.attempts = 1;
    for (const Eigen::VectorXd& q : closedFormCandidates(target, seed, options, result))
      if (filter.accepts(q))
        return solved(q);
  }
  else
  {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout));
    const IkOptions once = singleDescent(options);
    std::mt19937_64 rng(options.seed);
    double best_residual = std::numeric_limits<double>::infinity();
    Eigen::VectorXd start = seed;
    do
    {
      ++result.attempts;
      const IkResult attempt = numeric_.solve(target, start, once);
      if (attempt.success && filter.accepts(attempt.q))
        return solved(attempt.q);
      if (!attempt.success && attempt.position_error + attempt.orientation_error < best_residual)
      {
        best_residual = attempt.position_error + attempt.orientation_error;
        result.position_error = attempt.position_error;
        result.orientation_error = attempt.orientation_error;
      }
      start = restartSeed(seed, options.max_jump, rng);
    } while (Clock::now() < deadline);
  }
  filter.explainFailure(chain_.tipLink(), result);
  return result;
}
}  // namespace vrrw_kinematics
