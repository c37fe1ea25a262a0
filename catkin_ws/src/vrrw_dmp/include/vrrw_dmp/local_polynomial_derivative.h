#pragma once
#include <cstddef>
#include <vector>

namespace vrrw_dmp
{
/// \brief First and second time derivatives of samples taken at non-uniform times, by a local
/// least-squares quadratic fit (the Savitzky-Golay filter generalised to non-uniform spacing).
///
/// Why this and not finite differences: recorded demonstrations come at the render rate with jittery
/// time stamps and slightly noisy positions. Plain non-uniform differences divide that noise by h (and
/// by h^2 for accelerations), one sample pair at a time. The local fit uses the true time stamps, is
/// exact for quadratics (centred: O(h^2) error), and averages the noise over 2m+1 samples. The fit
/// depends only on the times, so its weights are computed once and applied to every joint.
class LocalPolynomialDerivative
{
public:
  /// \brief Prepares the fit for strictly increasing \a times; \a half_window m uses 2m+1 samples.
  LocalPolynomialDerivative(const std::vector<double>& times, std::size_t half_window = 3);

  /// \brief Derivatives of values[k * stride] (k = 0..samples-1) into first[k * stride], second[k * stride].
  void apply(const double* values, std::size_t stride, double* first, double* second) const;

  std::size_t samples() const { return begin_.size(); }

private:
  std::size_t width_ = 0;
  std::vector<std::size_t> begin_;  ///< first sample of each sample's window
  std::vector<double> first_;       ///< samples x width_ weights giving dx/dt
  std::vector<double> second_;      ///< samples x width_ weights giving d2x/dt2
};
}  // namespace vrrw_dmp
