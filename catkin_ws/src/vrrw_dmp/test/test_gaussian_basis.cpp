#include <gtest/gtest.h>

#include <cmath>

#include <vrrw_dmp/gaussian_basis.h>

using vrrw_dmp::GaussianBasis;

TEST(GaussianBasis, CentresAreEvenlySpacedInTime)
{
  const GaussianBasis basis(50, 4.0);
  ASSERT_EQ(basis.size(), 50u);
  EXPECT_DOUBLE_EQ(basis.centers().front(), 1.0);
  EXPECT_DOUBLE_EQ(basis.centers().back(), std::exp(-4.0));
  for (std::size_t i = 0; i + 1 < basis.size(); ++i)
  {
    EXPECT_NEAR(std::log(basis.centers()[i] / basis.centers()[i + 1]), 4.0 / 49.0, 1e-12);
    const double neighbour = std::exp(-basis.widths()[i] * std::pow(basis.centers()[i] - basis.centers()[i + 1], 2));
    EXPECT_NEAR(neighbour, std::exp(-1.0 / (GaussianBasis::kOverlap * GaussianBasis::kOverlap)), 1e-12);
  }
  EXPECT_EQ(basis.widths().back(), basis.widths()[48]);
}

TEST(GaussianBasis, EvaluateMatchesTheDefinitionAndCoversAllSignificantFunctions)
{
  const GaussianBasis basis(50, 4.0);
  std::vector<double> psi(basis.size(), -1.0);
  for (double s : { 1.0, 0.7, 0.31, 0.05, std::exp(-4.0), 0.01, 1e-4 })
  {
    std::size_t first = 0;
    std::size_t last = 0;
    const double log_peak = basis.evaluate(s, psi.data(), first, last);
    ASSERT_LT(first, last);
    double peak = -1e300;
    for (std::size_t i = 0; i < basis.size(); ++i)
      peak = std::max(peak, -basis.widths()[i] * std::pow(s - basis.centers()[i], 2));
    EXPECT_NEAR(log_peak, peak, 1e-12 * std::abs(peak) + 1e-12) << "s = " << s;
    for (std::size_t i = 0; i < basis.size(); ++i)
    {
      const double exact = std::exp(-basis.widths()[i] * std::pow(s - basis.centers()[i], 2) - peak);
      if (i >= first && i < last)
        EXPECT_NEAR(psi[i], exact, 1e-14) << "s = " << s << " i = " << i;
      else
        EXPECT_LT(exact, std::exp(-GaussianBasis::kCutoff)) << "s = " << s << " i = " << i;
    }
  }
}

TEST(GaussianBasis, SingleFunction)
{
  const GaussianBasis basis(1, 2.0);
  double psi = 0.0;
  std::size_t first = 9;
  std::size_t last = 9;
  basis.evaluate(0.4, &psi, first, last);
  EXPECT_EQ(first, 0u);
  EXPECT_EQ(last, 1u);
  EXPECT_EQ(psi, 1.0);
}
