#pragma once
#include <atomic>

namespace vrrw_demos
{
/// \brief `record --out FILE [--robots a,b] [--wait S] [--check]`: records with the workspace's recorder
/// until \a interrupted (Ctrl-C); returns the exit code (0 stopped and closed, 1 the recording failed).
/// Throws DemoError for bad input (nothing started then) and std::invalid_argument for bad usage.
/// `--check`: only checks the options and the file (before `./vrrw record SCENE` brings a scene up).
int runRecord(int argc, char** argv, const std::atomic<bool>& interrupted);
}  // namespace vrrw_demos
