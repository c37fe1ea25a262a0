#include "forcing_regression.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>

namespace vrrw_dmp
{
std::vector<std::vector<double>> regressForcing(const std::vector<double>& times, std::size_t dims,
                                                const std::vector<double>& targets, const GaussianBasis& basis,
                                                double alpha)
{
  const std::size_t samples = times.size();
  const std::size_t count = basis.size();
  const double duration = times.back();
  std::vector<double> numerator(dims * count, 0.0);
  std::vector<double> denominator(count, 0.0);
  std::vector<double> psi(count);
  for (std::size_t k = 0; k < samples; ++k)
  {
    const double s = std::exp(-alpha * times[k] / duration);
    const double quadrature = 0.5 * (times[std::min(k + 1, samples - 1)] - times[k > 0 ? k - 1 : 0]);
    std::size_t first = 0;
    std::size_t last = 0;
    const double peak = std::exp(basis.evaluate(s, psi.data(), first, last));
    const double* target = targets.data() + k * dims;
    for (std::size_t i = first; i < last; ++i)
    {
      const double weight = quadrature * peak * psi[i] * s;
      denominator[i] += weight * s;
      double* row = numerator.data() + i * dims;
      for (std::size_t d = 0; d < dims; ++d)
        row[d] += weight * target[d];
    }
  }
  std::vector<std::vector<double>> weights(dims, std::vector<double>(count, 0.0));
  for (std::size_t i = 0; i < count; ++i)
    if (denominator[i] > 0.0)
      for (std::size_t d = 0; d < dims; ++d)
        weights[d][i] = numerator[i * dims + d] / denominator[i];
  return weights;
}

AmplitudeScaling scalingFor(double offset, double amplitude, const DmpParameters& parameters, bool& degenerate)
{
  degenerate = amplitude > 0.0 && std::abs(offset) <= parameters.degenerate_ratio * amplitude;
  if (parameters.scaling != AmplitudeScaling::automatic)
    return parameters.scaling;
  return degenerate || amplitude < parameters.still_range ? AmplitudeScaling::demo_amplitude
                                                          : AmplitudeScaling::goal_offset;
}

std::string checksumOf(const std::vector<double>& values)
{
  std::uint64_t hash = 1469598103934665603ull;
  for (double value : values)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof(bits));
    hash = (hash ^ bits) * 1099511628211ull;
  }
  char buffer[20];
  std::snprintf(buffer, sizeof(buffer), "%016llx", static_cast<unsigned long long>(hash));
  return buffer;
}

std::string utcNow()
{
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buffer;
}
}  // namespace vrrw_dmp
