#include "bench_support.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace vrrw_kinematics
{
std::string readFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("file " + path + ": cannot be read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

double threadCpuSeconds()
{
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double percentile(std::vector<double> samples, double p)
{
  if (samples.empty())
    return 0.0;
  std::sort(samples.begin(), samples.end());
  const std::size_t index =
      std::min(samples.size() - 1, static_cast<std::size_t>(p / 100.0 * static_cast<double>(samples.size())));
  return samples[index];
}
}  // namespace vrrw_kinematics
