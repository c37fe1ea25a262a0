#pragma once
#include <cstddef>
#include <vector>

namespace vrrw_dmp
{
/// \brief N Gaussian basis functions psi_i(s) = exp(-h_i (s - c_i)^2) over the phase s in (0, 1]
/// (Ijspeert et al., "Dynamical movement primitives", Neural Computation 25(2), 2013).
///
/// Centres are evenly spaced in time: c_i = exp(-alpha i / (N - 1)); widths make neighbours overlap
/// by a fixed ratio: h_i = 1 / (kOverlap (c_i - c_{i+1}))^2 (the last copies its neighbour's width).
class GaussianBasis
{
public:
  /// \brief Relative basis values below exp(-kCutoff) are treated as zero (below double precision).
  static constexpr double kCutoff = 36.0;
  /// \brief Width of a basis in units of the spacing to its neighbour.
  static constexpr double kOverlap = 0.55;

  GaussianBasis() = default;
  /// \brief The standard layout for \a count functions and canonical decay \a alpha.
  GaussianBasis(std::size_t count, double alpha);
  /// \brief Explicit centres and widths (as loaded from a model file).
  GaussianBasis(std::vector<double> centers, std::vector<double> widths);

  std::size_t size() const { return centers_.size(); }
  const std::vector<double>& centers() const { return centers_; }
  const std::vector<double>& widths() const { return widths_; }

  /// \brief psi[i] = psi_i(s) / max_i psi_i(s) for i in the returned range [first, last) outside of
  /// which every ratio is below exp(-kCutoff) (entries there are not written); returns
  /// log(max_i psi_i(s)). \a psi has size() entries. Never allocates.
  double evaluate(double s, double* psi, std::size_t& first, std::size_t& last) const;

private:
  std::vector<double> centers_;
  std::vector<double> widths_;
};
}  // namespace vrrw_dmp
