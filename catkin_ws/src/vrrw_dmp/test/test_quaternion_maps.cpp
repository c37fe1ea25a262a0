#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <vrrw_dmp/quaternion_maps.h>

using vrrw_dmp::angleBetween;
using vrrw_dmp::quaternionExp;
using vrrw_dmp::quaternionLog;
using vrrw_dmp::rotationBetween;

namespace
{
Eigen::Quaterniond randomQuaternion(std::mt19937& random)
{
  std::normal_distribution<double> gauss;
  return Eigen::Quaterniond(gauss(random), gauss(random), gauss(random), gauss(random)).normalized();
}
}  // namespace

TEST(QuaternionMaps, ExpInvertsLogUpToSign)
{
  std::mt19937 random(3);
  for (int k = 0; k < 1000; ++k)
  {
    const Eigen::Quaterniond q = randomQuaternion(random);
    const Eigen::Quaterniond back = quaternionExp(quaternionLog(q));
    EXPECT_NEAR(std::abs(back.coeffs().dot(q.coeffs())), 1.0, 1e-14);
    EXPECT_LE(quaternionLog(q).norm(), M_PI / 2 + 1e-15);  // the shorter way round
    EXPECT_NEAR(std::abs(back.norm() - 1.0), 0.0, 1e-15);
  }
}

TEST(QuaternionMaps, QAndMinusQHaveOneLogarithm)
{
  const Eigen::Quaterniond q(Eigen::AngleAxisd(2.5, Eigen::Vector3d(1, 2, 3).normalized()));
  Eigen::Quaterniond minus = q;
  minus.coeffs() = -q.coeffs();
  EXPECT_LT((quaternionLog(q) - quaternionLog(minus)).norm(), 1e-15);
}

TEST(QuaternionMaps, RotationVectorMatchesAngleAxis)
{
  for (double angle : { 1e-9, 0.01, 1.0, 3.0, M_PI - 1e-6 })
  {
    const Eigen::Vector3d axis = Eigen::Vector3d(-0.3, 0.5, 0.8).normalized();
    const Eigen::Quaterniond b(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()));
    const Eigen::Quaterniond a = Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)) * b;
    const Eigen::Vector3d r = rotationBetween(a, b);
    EXPECT_NEAR((r - angle * axis).norm(), 0.0, 1e-12 * std::max(1.0, angle)) << "angle " << angle;
    EXPECT_NEAR(angleBetween(a, b), angle, 1e-12) << "angle " << angle;
    // exp of half the rotation vector turns b into a
    EXPECT_NEAR(angleBetween(quaternionExp(0.5 * r) * b, a), 0.0, 1e-7);
  }
}
