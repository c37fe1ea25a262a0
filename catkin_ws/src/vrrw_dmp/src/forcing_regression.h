#pragma once
// Shared by the joint DMP (dmp_learning.cpp) and the orientation DMP (orientation_dmp.cpp).
#include <cmath>
#include <algorithm>
#include <cstddef>
#include <vector>

#include <string>

#include <vrrw_dmp/dmp_parameters.h>
#include <vrrw_dmp/gaussian_basis.h>

namespace vrrw_dmp
{
/// \brief Locally weighted regression of target forcing values on each basis function, over the samples
/// weighted by their share of the duration (trapezoid), so dense parts of a recording do not dominate:
///   w_i = sum_k dt_k psi_i(s_k) s_k f_k / sum_k dt_k psi_i(s_k) s_k^2,  s_k = exp(-alpha t_k / T).
/// \a times start at 0 and end at T; \a targets is sample-major (value of dimension d at sample k:
/// [k * dims + d]), already divided by each dimension's scale. Returns weights[d][i].
std::vector<std::vector<double>> regressForcing(const std::vector<double>& times, std::size_t dims,
                                                const std::vector<double>& targets, const GaussianBasis& basis,
                                                double alpha);

/// \brief What multiplies the forcing term at phase \a s: 1 during the demonstrated duration (s >= exp(-alpha)),
/// then (s / exp(-alpha))^kTailPower, which fades it out over a few hundredths of tau. Past the demonstration's
/// end the forcing term has nothing behind it (the last basis function's weight, fitted to the end of the
/// motion, extrapolated) and only holds the system off its goal: a 23 s joint demonstration with 0.1 mrad
/// of noise crept on to 2.2 tau before it was within 1 mrad without the fade.
inline double tailFade(double s, double alpha)
{
  constexpr double kTailPower = 20.0;  // with alpha = 4: exp(-80 (t - tau) / tau), an 0.0125 tau time constant
  const double end = std::exp(-alpha);
  return s >= end ? 1.0 : std::pow(s / end, kTailPower);
}

/// \brief The derivative fit's half window for \a samples: parameters.derivative_half_window, or more so the
/// window spans half the basis spacing. The forcing term resolves nothing finer than that spacing, and the
/// noise of a dense recording is divided by the sample interval twice: 23 s at 1 kHz with 0.1 mrad of noise
/// and 7 samples per fit ended 39 mrad off its goal; with the window at half the spacing, 0.4 mrad. At most
/// 25 (the fit keeps 2 x 51 weights per sample: 49 MB for a minute at 1 kHz).
inline std::size_t derivativeHalfWindow(const DmpParameters& parameters, std::size_t samples)
{
  constexpr std::size_t kMostAutomatic = 25;
  const std::size_t spacing = samples / (4 * std::max<std::size_t>(parameters.basis_count - 1, 1));
  return std::max(parameters.derivative_half_window, std::min(spacing, kMostAutomatic));
}

/// \brief The scaling \a parameters give a dimension whose demonstration moved \a offset from start to goal
/// within a range \a amplitude; \a degenerate: |offset| is within degenerate_ratio of the range (g == x0).
AmplitudeScaling scalingFor(double offset, double amplitude, const DmpParameters& parameters, bool& degenerate);

/// \brief FNV-1a 64 over the bit patterns of \a values, as 16 hex digits (a demonstration's checksum).
std::string checksumOf(const std::vector<double>& values);

}  // namespace vrrw_dmp
