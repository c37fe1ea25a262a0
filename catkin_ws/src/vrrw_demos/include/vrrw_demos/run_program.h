#pragma once
#include <string>
#include <vector>

namespace vrrw_demos
{
/// \brief Runs the program \a argv[0] (searched on PATH) with the arguments exactly as given: no shell, so
/// no character of a path or name is ever interpreted. Waits for it; returns its exit status (-1 when it
/// could not start or died of a signal). \a output (optional) receives its standard output; \a quiet
/// sends its standard error to /dev/null.
int runProgram(const std::vector<std::string>& argv, std::string* output = nullptr, bool quiet = false);
}  // namespace vrrw_demos
