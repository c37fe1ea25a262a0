#include "bench_args.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace vrrw_kinematics
{
BenchArgs::BenchArgs(int argc, char** argv, const std::vector<std::string>& flags)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0)
      throw std::runtime_error("argument " + arg + ": expected --key value");
    const std::string key = arg.substr(2);
    if (std::find(flags.begin(), flags.end(), key) != flags.end())
      values_[key] = "1";
    else if (i + 1 < argc)
      values_[key] = argv[++i];
    else
      throw std::runtime_error("argument " + arg + ": missing value");
  }
}

std::string BenchArgs::text(const std::string& key, const std::string& fallback) const
{
  const auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}

std::string BenchArgs::required(const std::string& key) const
{
  if (!has(key))
    throw std::runtime_error("argument --" + key + ": required");
  return text(key);
}

double BenchArgs::number(const std::string& key, double fallback) const
{
  if (!has(key))
    return fallback;
  try
  {
    return std::stod(text(key));
  }
  catch (const std::exception&)
  {
    throw std::runtime_error("argument --" + key + ": not a number: " + text(key));
  }
}

long BenchArgs::integer(const std::string& key, long fallback) const
{
  return static_cast<long>(number(key, static_cast<double>(fallback)));
}

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
