#include "vrrw_dmp/gaussian_basis.h"

#include <cmath>
#include <limits>

namespace vrrw_dmp
{
GaussianBasis::GaussianBasis(std::size_t count, double alpha) : centers_(count), widths_(count)
{
  for (std::size_t i = 0; i < count; ++i)
    centers_[i] = count == 1 ? 1.0 : std::exp(-alpha * static_cast<double>(i) / static_cast<double>(count - 1));
  for (std::size_t i = 0; i + 1 < count; ++i)
  {
    const double spacing = kOverlap * (centers_[i] - centers_[i + 1]);
    widths_[i] = 1.0 / (spacing * spacing);
  }
  if (count == 1)
    widths_[0] = 1.0 / (kOverlap * kOverlap);
  else
    widths_[count - 1] = widths_[count - 2];
}

GaussianBasis::GaussianBasis(std::vector<double> centers, std::vector<double> widths)
  : centers_(std::move(centers)), widths_(std::move(widths))
{
}

double GaussianBasis::evaluate(double s, double* psi, std::size_t& first, std::size_t& last) const
{
  const std::size_t n = centers_.size();
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i)
  {
    const double d = s - centers_[i];
    psi[i] = -widths_[i] * d * d;
    best = psi[i] > best ? psi[i] : best;
  }
  first = n;
  last = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double exponent = psi[i] - best;
    if (exponent > -kCutoff)
    {
      psi[i] = std::exp(exponent);
      first = i < first ? i : first;
      last = i + 1;
    }
    else
    {
      psi[i] = 0.0;
    }
  }
  return best;
}
}  // namespace vrrw_dmp
