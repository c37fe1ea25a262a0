#pragma once
#include <cstddef>
#include <optional>
#include <string>

namespace vrrw_dmp
{
/// \brief What multiplies the forcing term of a joint: the paper's (g - x0), or a constant.
enum class AmplitudeScaling
{
  goal_offset,     ///< (g - x0), equation 2 of the paper; the forcing term vanishes when g == x0
  demo_amplitude,  ///< the demonstration's range max(x) - min(x): a joint that returns to its start is kept
  automatic,       ///< demo_amplitude for the joints where g == x0 (see Dmp) or that hardly move, goal_offset elsewhere
};

/// \brief "goal", "amplitude" or "auto".
std::string toString(AmplitudeScaling scaling);
/// \brief Parses "goal", "amplitude" or "auto"; throws DmpError naming \a text otherwise.
AmplitudeScaling amplitudeScalingFromString(const std::string& text);

/// \brief Learning parameters of a Dmp. Defaults follow Ijspeert et al. 2013 (alpha_z = 25, beta_z = 6.25).
struct DmpParameters
{
  /// More basis functions than this are refused: far beyond what a demonstration resolves (a 60 s
  /// recording at 1 kHz has 6 samples per function), and a model's size grows with N.
  static constexpr std::size_t kMaxBasisCount = 10000;

  std::size_t basis_count = 50;  ///< N Gaussian basis functions
  double alpha = 4.0;            ///< canonical decay: s = exp(-alpha) at the end of the demonstration
  double K = 156.25;             ///< spring constant
  std::optional<double> D;       ///< damping; unset means critically damped, 2 sqrt(K)
  AmplitudeScaling scaling = AmplitudeScaling::goal_offset;
  double degenerate_ratio = 0.05;  ///< |g - x0| below this fraction of the demo's range counts as g == x0
  /// rad (m): with automatic scaling, a joint the demonstration moves less than this is scaled by its range
  /// too: its drift is not a motion to stretch to a new goal (a 3 mrad drift to a goal 80 mrad away would
  /// be mirrored and amplified 25 times). 0: off. 20 mrad, as vrrw_skills learns with: a joint held while the
  /// others move ripples by a few mrad in physics (drives, a held load), and the demo's `final` turns wrist_2 by
  /// 0.4 mrad, which the README's example goal mirrored 3.7 times.
  double still_range = 0.02;
  /// the local quadratic fit uses at least 2m+1 samples, and as many as half the basis spacing holds
  std::size_t derivative_half_window = 3;

  /// \brief D, or 2 sqrt(K) when D is unset.
  double damping() const;
  /// \brief Throws DmpError naming the first invalid parameter.
  void validate() const;
};
}  // namespace vrrw_dmp
