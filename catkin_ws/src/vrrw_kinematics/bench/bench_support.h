#pragma once
#include <map>
#include <string>
#include <vector>

namespace vrrw_kinematics
{
/// \brief `--key value` and `--flag` arguments of a benchmark executable.
class BenchArgs
{
public:
  BenchArgs(int argc, char** argv, const std::vector<std::string>& flags = {});
  bool has(const std::string& key) const { return values_.count(key) > 0; }
  std::string text(const std::string& key, const std::string& fallback = "") const;
  std::string required(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  long integer(const std::string& key, long fallback) const;

private:
  std::map<std::string, std::string> values_;
};

/// \brief Reads a whole file; throws std::runtime_error naming the file.
std::string readFile(const std::string& path);
/// \brief CPU time of the calling thread (s): unlike wall time it does not count time the machine gave
/// to other processes.
double threadCpuSeconds();
/// \brief Percentile (0..100) of unsorted samples.
double percentile(std::vector<double> samples, double p);
}  // namespace vrrw_kinematics
