#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/local_polynomial_derivative.h>

using vrrw_dmp::LocalPolynomialDerivative;

namespace
{
std::vector<double> jitteredTimes(std::size_t n, double step, double jitter, unsigned seed = 3)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<double> times(n);
  for (std::size_t k = 0; k < n; ++k)
    times[k] = step * (static_cast<double>(k) + (k > 0 ? u(random) : 0.0));
  return times;
}
}  // namespace

TEST(LocalPolynomialDerivative, ExactForQuadraticsAtNonUniformTimesIncludingTheEnds)
{
  const auto times = jitteredTimes(40, 0.05, 0.4);
  std::vector<double> values(times.size() * 2);
  for (std::size_t k = 0; k < times.size(); ++k)
  {
    values[2 * k] = 1.0 - 2.0 * times[k] + 3.0 * times[k] * times[k];
    values[2 * k + 1] = -5.0;
  }
  const LocalPolynomialDerivative derivative(times);
  std::vector<double> first(values.size(), 9.0);
  std::vector<double> second(values.size(), 9.0);
  derivative.apply(values.data(), 2, first.data(), second.data());
  derivative.apply(values.data() + 1, 2, first.data() + 1, second.data() + 1);
  for (std::size_t k = 0; k < times.size(); ++k)
  {
    EXPECT_NEAR(first[2 * k], -2.0 + 6.0 * times[k], 1e-9) << k;
    EXPECT_NEAR(second[2 * k], 6.0, 1e-7) << k;
    EXPECT_NEAR(first[2 * k + 1], 0.0, 1e-9);
    EXPECT_NEAR(second[2 * k + 1], 0.0, 1e-7);
  }
}

TEST(LocalPolynomialDerivative, JitteryNoisySineBeatsPlainDifferences)
{
  const auto times = jitteredTimes(400, 0.01, 0.45);
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 1e-4);
  std::vector<double> values(times.size());
  for (std::size_t k = 0; k < times.size(); ++k)
    values[k] = std::sin(2.0 * times[k]) + noise(random);
  std::vector<double> first(times.size());
  std::vector<double> second(times.size());
  LocalPolynomialDerivative(times).apply(values.data(), 1, first.data(), second.data());
  double fit_error = 0.0;
  double difference_error = 0.0;
  for (std::size_t k = 5; k + 5 < times.size(); ++k)
  {
    fit_error = std::max(fit_error, std::abs(second[k] + 4.0 * std::sin(2.0 * times[k])));
    const double left = (values[k] - values[k - 1]) / (times[k] - times[k - 1]);
    const double right = (values[k + 1] - values[k]) / (times[k + 1] - times[k]);
    const double plain = 2.0 * (right - left) / (times[k + 1] - times[k - 1]);
    difference_error = std::max(difference_error, std::abs(plain + 4.0 * std::sin(2.0 * times[k])));
    EXPECT_NEAR(first[k], 2.0 * std::cos(2.0 * times[k]), 0.02) << k;
  }
  EXPECT_LT(fit_error, 1.0);
  EXPECT_LT(fit_error, difference_error / 3.0);
}

TEST(LocalPolynomialDerivative, NeedsThreeSamples)
{
  EXPECT_THROW(LocalPolynomialDerivative({ 0.0, 1.0 }), vrrw_dmp::DmpError);
  const LocalPolynomialDerivative three({ 0.0, 0.5, 2.0 });
  EXPECT_EQ(three.samples(), 3u);
}
