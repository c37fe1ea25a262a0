#pragma once
#include <string>
#include <vector>

namespace vrrw_kinematics
{
/// \brief Reads a whole file; throws std::runtime_error naming the file.
std::string readFile(const std::string& path);
/// \brief CPU time of the calling thread (s): unlike wall time it does not count time the machine gave
/// to other processes.
double threadCpuSeconds();
/// \brief Percentile (0..100) of unsorted samples.
double percentile(std::vector<double> samples, double p);
}  // namespace vrrw_kinematics
