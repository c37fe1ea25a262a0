#include <vrrw_dmp/gaussian_basis.h>

#include <cmath>

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
  auto exponent = [this, s](std::size_t i) {
    const double d = s - centers_[i];
    return -widths_[i] * d * d;
  };
  std::size_t low = 0;
  std::size_t high = n;
  while (low < high)
  {
    const std::size_t middle = (low + high) / 2;
    if (centers_[middle] > s)
      low = middle + 1;
    else
      high = middle;
  }
  std::size_t nearest = low == n ? n - 1 : low;
  if (low > 0 && low < n && centers_[low - 1] - s < s - centers_[low])
    nearest = low - 1;
  // exponents are unimodal in i (h_i c_i^2 is the same for every i), so grow the range from the
  // nearest centre until they fall kCutoff below the largest
  double best = exponent(nearest);
  psi[nearest] = best;
  first = nearest;
  while (first > 0)
  {
    const double e = exponent(first - 1);
    if (e < best - kCutoff)
      break;
    psi[--first] = e;
    best = e > best ? e : best;
  }
  last = nearest + 1;
  while (last < n)
  {
    const double e = exponent(last);
    if (e < best - kCutoff)
      break;
    psi[last++] = e;
    best = e > best ? e : best;
  }
  for (std::size_t i = first; i < last; ++i)
    psi[i] = std::exp(psi[i] - best);
  return best;
}
}  // namespace vrrw_dmp
