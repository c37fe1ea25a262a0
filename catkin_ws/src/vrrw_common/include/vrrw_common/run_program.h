#pragma once
#include <string>
#include <vector>

namespace vrrw_common
{
/// \brief What a program run by runProgram reads and what of its output is kept.
struct ProgramStreams
{
  const std::string* input = nullptr;  ///< written to its standard input (then closed); none: it reads nothing
  std::string* output = nullptr;       ///< receives its standard output; none: it goes to ours
  std::string* errors = nullptr;       ///< receives its standard error; none: it goes to ours (or nowhere, quiet)
  bool quiet = false;                  ///< an uncaptured standard error goes to /dev/null
};

/// \brief Runs the program \a argv[0] (searched on PATH) with the arguments exactly as given: no shell, so no
/// character of a path or name is ever interpreted (`y';touch PWNED;'.png` is one argument). Waits for it;
/// returns its exit status, -1 when it could not start or died of a signal.
int runProgram(const std::vector<std::string>& argv, const ProgramStreams& streams);

/// \brief The same with \a output (optional) receiving its standard output; \a quiet sends its standard error
/// to /dev/null.
int runProgram(const std::vector<std::string>& argv, std::string* output = nullptr, bool quiet = false);

/// \brief How a program ended and what it printed.
struct ProgramRun
{
  int status = -1;     ///< as runProgram returns it
  std::string output;  ///< its standard output, then its standard error
};

/// \brief Runs \a argv as runProgram does, keeping all it prints: a tool run as a user runs it (the tools' tests).
ProgramRun runCapturing(const std::vector<std::string>& argv);
}  // namespace vrrw_common
