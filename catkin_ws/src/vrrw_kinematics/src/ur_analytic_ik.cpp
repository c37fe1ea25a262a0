#include "vrrw_kinematics/ur_analytic_ik.h"

#include <cmath>
#include <random>

namespace vrrw_kinematics
{
namespace
{
constexpr double kAlpha[6] = { M_PI / 2, 0.0, 0.0, M_PI / 2, -M_PI / 2, 0.0 };
constexpr double kParallel = 1e-9;

/// cos and sin of the DH twists kAlpha, exact.
constexpr double kCosAlpha[6] = { 0.0, 1.0, 1.0, 0.0, 0.0, 1.0 };
constexpr double kSinAlpha[6] = { 1.0, 0.0, 0.0, 1.0, -1.0, 0.0 };

Eigen::Matrix4d dhMatrix(double theta, double d, double a, int joint)
{
  const double ct = std::cos(theta), st = std::sin(theta), ca = kCosAlpha[joint], sa = kSinAlpha[joint];
  Eigen::Matrix4d m;
  m << ct, -st * ca, st * sa, a * ct, st, ct * ca, -ct * sa, a * st, 0, sa, ca, d, 0, 0, 0, 1;
  return m;
}

Eigen::Matrix4d dhInverse(double theta, double d, double a, int joint)
{
  const double ct = std::cos(theta), st = std::sin(theta), ca = kCosAlpha[joint], sa = kSinAlpha[joint];
  Eigen::Matrix4d m;
  m << ct, st, 0, -a, -st * ca, ct * ca, sa, -d * sa, st * sa, -ct * sa, ca, -d * ca, 0, 0, 0, 1;
  return m;
}

Eigen::Vector3d perpendicular(const Eigen::Vector3d& z)
{
  const Eigen::Vector3d e = std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return (e - e.dot(z) * z).normalized();
}

double signedAngle(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3d& axis)
{
  return std::atan2(from.cross(to).dot(axis), from.dot(to));
}

double wrap(double angle)
{
  return angle - 2.0 * M_PI * std::nearbyint(angle / (2.0 * M_PI));
}
}  // namespace

URAnalyticIK::URAnalyticIK(const KinematicChain& chain, const URParameters& params)
  : params_(params), lower_(chain.lowerLimits()), upper_(chain.upperLimits())
{
}

std::optional<URAnalyticIK> URAnalyticIK::detect(const KinematicChain& chain)
{
  if (chain.size() != 6)
    return std::nullopt;
  std::array<Eigen::Vector3d, 6> u, p;
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < 6; ++i)
  {
    if (chain.joints()[i].prismatic)
      return std::nullopt;
    frame = frame * chain.joints()[i].before;
    u[i] = frame.linear() * chain.joints()[i].axis;
    p[i] = frame.translation();
  }
  const Eigen::Vector3d tip_position = (frame * chain.tipOffset()).translation();
  const auto parallel = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return a.cross(b).norm() < kParallel;
  };
  const auto perpendicular_axes = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::abs(a.dot(b)) < kParallel;
  };
  if (!perpendicular_axes(u[0], u[1]) || !parallel(u[1], u[2]) || !parallel(u[1], u[3]) ||
      !perpendicular_axes(u[3], u[4]) || !perpendicular_axes(u[4], u[5]))
    return std::nullopt;

  URParameters params;
  params.sign[2] = u[2].dot(u[1]) > 0 ? 1.0 : -1.0;
  params.sign[3] = u[3].dot(u[1]) > 0 ? 1.0 : -1.0;
  std::array<Eigen::Vector3d, 6> z;
  for (std::size_t i = 0; i < 6; ++i)
    z[i] = params.sign[i] * u[i];

  Eigen::Vector3d z_prev = z[0];
  Eigen::Vector3d origin_prev = p[0] - p[0].dot(z[0]) * z[0];
  Eigen::Vector3d x_prev = perpendicular(z[0]);
  params.base_to_dh.linear() << x_prev, z_prev.cross(x_prev), z_prev;
  params.base_to_dh.translation() = origin_prev;
  std::array<double, 6> a{}, d{};
  for (std::size_t i = 0; i < 5; ++i)
  {
    const Eigen::Vector3d& z_next = z[i + 1];
    Eigen::Vector3d x, origin;
    if (kAlpha[i] != 0.0)
    {
      const Eigen::Vector3d c = z_prev.cross(z_next);
      x = (kAlpha[i] > 0 ? c : Eigen::Vector3d(-c)).normalized();
      const Eigen::Vector3d w = origin_prev - p[i + 1];
      const double b = z_prev.dot(z_next), dw = z_prev.dot(w), ew = z_next.dot(w);
      const double denominator = 1.0 - b * b;
      const double t = (b * ew - dw) / denominator;
      const double s = (ew - b * dw) / denominator;
      const Eigen::Vector3d foot_prev = origin_prev + t * z_prev;
      origin = p[i + 1] + s * z_next;
      a[i] = (origin - foot_prev).dot(x);
      d[i] = t;
    }
    else
    {
      origin = p[i + 1] + (origin_prev - p[i + 1]).dot(z_next) * z_next;
      const Eigen::Vector3d v = origin - origin_prev;
      a[i] = v.norm();
      if (a[i] < 1e-6)
        return std::nullopt;
      x = v / a[i];
      d[i] = 0.0;
    }
    params.offset[i] = signedAngle(x_prev, x, z_prev);
    z_prev = z_next;
    x_prev = x;
    origin_prev = origin;
  }
  d[5] = (tip_position - origin_prev).dot(z_prev);
  if (std::abs(a[0]) > 1e-9 || std::abs(a[3]) > 1e-9 || std::abs(a[4]) > 1e-9)
    return std::nullopt;
  params.d1 = d[0];
  params.a2 = a[1];
  params.a3 = a[2];
  params.d4 = d[3];
  params.d5 = d[4];
  params.d6 = d[5];

  URAnalyticIK solver(chain, params);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
  solver.params_.dh_to_tip = solver.fk(zero).inverse() * chain.fk(zero);
  std::mt19937_64 rng(7);
  for (int sample = 0; sample < 20; ++sample)
  {
    Eigen::VectorXd q(6);
    for (int i = 0; i < 6; ++i)
      q[i] = std::uniform_real_distribution<double>(-M_PI, M_PI)(rng);
    const Eigen::Isometry3d expected = chain.fk(q);
    const Eigen::Isometry3d actual = solver.fk(q);
    if ((expected.matrix() - actual.matrix()).cwiseAbs().maxCoeff() > 1e-9)
      return std::nullopt;
  }
  return solver;
}

Eigen::Isometry3d URAnalyticIK::fk(const Eigen::VectorXd& q) const
{
  const double d[6] = { params_.d1, 0, 0, params_.d4, params_.d5, params_.d6 };
  const double a[6] = { 0, params_.a2, params_.a3, 0, 0, 0 };
  Eigen::Matrix4d t = params_.base_to_dh.matrix();
  for (int i = 0; i < 6; ++i)
    t = t * dhMatrix(params_.sign[i] * q[i] + params_.offset[i], d[i], a[i], i);
  Eigen::Isometry3d out;
  out.matrix() = t;
  return out * params_.dh_to_tip;
}

int URAnalyticIK::solveDH(const Eigen::Matrix4d& t06, std::array<std::array<double, 6>, 8>& solutions) const
{
  const URParameters& k = params_;
  const Eigen::Vector3d p = t06.topRightCorner<3, 1>();
  const Eigen::Vector3d p05 = p - k.d6 * t06.block<3, 1>(0, 2);
  const double r = std::hypot(p05.x(), p05.y());
  if (r < std::abs(k.d4) || r < 1e-12)
    return 0;
  const Eigen::Matrix4d t60 = [&] {
    Eigen::Matrix4d inv = Eigen::Matrix4d::Identity();
    inv.topLeftCorner<3, 3>() = t06.topLeftCorner<3, 3>().transpose();
    inv.topRightCorner<3, 1>() = -inv.topLeftCorner<3, 3>() * p;
    return inv;
  }();
  const double phi = std::atan2(p05.y(), p05.x());
  const double psi = std::acos(k.d4 / r);
  int count = 0;
  for (const double theta1 : { phi + psi + M_PI / 2, phi - psi + M_PI / 2 })
  {
    const double s1 = std::sin(theta1), c1 = std::cos(theta1);
    double cos5 = (p.x() * s1 - p.y() * c1 - k.d4) / k.d6;
    if (std::abs(cos5) > 1.0 + 1e-9)
      continue;
    cos5 = std::max(-1.0, std::min(1.0, cos5));
    const double acos5 = std::acos(cos5);
    for (const double theta5 : { acos5, -acos5 })
    {
      const double s5 = std::sin(theta5);
      double theta6 = 0.0;
      if (std::abs(s5) > 1e-12)
        theta6 = std::atan2((-t60(1, 0) * s1 + t60(1, 1) * c1) / s5, (t60(0, 0) * s1 - t60(0, 1) * c1) / s5);
      const Eigen::Matrix4d t14 =
          dhInverse(theta1, k.d1, 0, 0) * t06 * dhInverse(theta6, k.d6, 0, 5) * dhInverse(theta5, k.d5, 0, 4);
      const Eigen::Vector2d p13(t14(0, 3) - k.d4 * t14(0, 1), t14(1, 3) - k.d4 * t14(1, 1));
      const double p13_norm2 = p13.squaredNorm();
      double cos3 = (p13_norm2 - k.a2 * k.a2 - k.a3 * k.a3) / (2.0 * k.a2 * k.a3);
      if (std::abs(cos3) > 1.0 + 1e-9)
        continue;
      cos3 = std::max(-1.0, std::min(1.0, cos3));
      const double acos3 = std::acos(cos3);
      for (const double theta3 : { acos3, -acos3 })
      {
        const double theta2 = std::atan2(p13.y(), p13.x()) -
                              std::atan2(k.a3 * std::sin(theta3), k.a2 + k.a3 * std::cos(theta3));
        const Eigen::Matrix4d t34 =
            dhInverse(theta3, 0, k.a3, 2) * dhInverse(theta2, 0, k.a2, 1) * t14;
        const double theta4 = std::atan2(t34(1, 0), t34(0, 0));
        solutions[count++] = { { theta1, theta2, theta3, theta4, theta5, theta6 } };
      }
    }
  }
  return count;
}

bool URAnalyticIK::toJoint(const std::array<double, 6>& theta, const Eigen::VectorXd& reference,
                           Eigen::VectorXd& q) const
{
  q.resize(6);
  for (int i = 0; i < 6; ++i)
  {
    double value = reference[i] + wrap(params_.sign[i] * (theta[i] - params_.offset[i]) - reference[i]);
    if (value > upper_[i])
      value -= 2.0 * M_PI * std::ceil((value - upper_[i]) / (2.0 * M_PI) - 1e-12);
    if (value < lower_[i])
      value += 2.0 * M_PI * std::ceil((lower_[i] - value) / (2.0 * M_PI) - 1e-12);
    if (value < lower_[i] - 1e-9 || value > upper_[i] + 1e-9)
      return false;
    q[i] = std::max(lower_[i], std::min(upper_[i], value));
  }
  return true;
}

std::vector<Eigen::VectorXd> URAnalyticIK::solveAll(const Eigen::Isometry3d& tip_pose,
                                                    const Eigen::VectorXd& reference) const
{
  const Eigen::Matrix4d t06 =
      (params_.base_to_dh.inverse() * tip_pose * params_.dh_to_tip.inverse()).matrix();
  std::array<std::array<double, 6>, 8> theta;
  const int count = solveDH(t06, theta);
  std::vector<Eigen::VectorXd> out;
  Eigen::VectorXd q;
  for (int s = 0; s < count; ++s)
    if (toJoint(theta[s], reference, q))
      out.push_back(q);
  return out;
}

bool URAnalyticIK::solveNearest(const Eigen::Isometry3d& tip_pose, const Eigen::VectorXd& seed,
                                Eigen::VectorXd& q) const
{
  const std::vector<Eigen::VectorXd> all = solveAll(tip_pose, seed);
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::VectorXd& candidate : all)
  {
    const double distance = (candidate - seed).squaredNorm();
    if (distance < best)
    {
      best = distance;
      q = candidate;
    }
  }
  return !all.empty();
}
}  // namespace vrrw_kinematics
