// vrrw_demos: the demonstration tool behind `./vrrw demos ...` and `./vrrw record`.
//   export BAG --csv FILE [--robot R] [--segment NAME]   one row per recorded state
//   import CSV --bag FILE --robot R [--gripper-joint J]
//   segment BAG [--out FILE.yaml]                          the pick-and-place instructions, YAML + table
//   plot BAG --out FILE.png [--robot R]                    joints, gripper and segment boundaries
//   replay BAG --mode fake|physics|real [--robot R] [--segment NAME] [--speed S] [--tolerance RAD] [--rtf max|N]
//          [--yes]                                         physics: in lockstep (held, stepped at --rtf)
//   record --out FILE.bag [--robots a,b] [--wait S]        with the workspace's recorder until Ctrl-C
// Exit codes: 0 done, 1 a failure while running (a goal failed, a recording stopped, no workspace runs), 2 bad
// input or usage (one line on stderr naming the file, topic, option or field; nothing was written or sent).
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include <vrrw_demos/demo_csv.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/new_file.h>
#include <vrrw_common/run_program.h>
#include <vrrw_demos/segmentation.h>

#include <vrrw_common/options.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_demos/ros/demo_bag.h>

#include "../src/ros/record_command.h"
#include "../src/ros/replay_command.h"
#include "../src/ros/segment_report.h"

using namespace vrrw_demos;
using vrrw_common::Options;

namespace
{
/// Seconds since the epoch of the stamps an imported CSV gets (its t = 0); any fixed value would do.
constexpr double kImportStart = 1e9;

/// Set by SIGINT / SIGTERM: replay and record cancel what they started (lock-free, so signal-safe).
std::atomic<bool> g_interrupted{ false };

/// \a path must be free and its folder must take a new file: tried before any work, so a refusal costs
/// nothing (a read-only or missing folder is one line, not a failure at the end).
void refuseUnwritable(const std::string& path)
{
  refuseTaken(path);
  std::remove(temporaryBeside(path).c_str());
}

/// The track of --robot, or of the only robot of the bag.
RobotTrack pickTrack(const std::string& bag, const Options& options, Demonstration& demo)
{
  demo = readDemonstration(bag, options.has("robot") ? std::vector<std::string>{ options.text("robot") }
                                                     : std::vector<std::string>{});
  if (demo.robots.size() > 1)
  {
    std::string names;
    for (const RobotTrack& track : demo.robots)
      names += (names.empty() ? "" : ", ") + track.robot;
    throw DemoError(bag + ": " + std::to_string(demo.robots.size()) + " robots (" + names + "): choose one with --robot");
  }
  RobotTrack track = demo.robots.front();
  if (options.has("segment"))
  {
    const Segment segment = findSegment(demo, track, options.text("segment"));
    track = slice(track, segment.start, segment.end);
  }
  return track;
}

int exportCommand(const Options& options)
{
  if (options.positional().size() != 1 || !options.has("csv"))
    throw std::invalid_argument("usage: export BAG --csv FILE [--robot R] [--segment NAME]");
  refuseUnwritable(options.text("csv"));
  Demonstration demo;
  const RobotTrack track = pickTrack(options.positional()[0], options, demo);
  exportCsv(track, options.text("csv"));
  std::cout << options.text("csv") << ": robot " << track.robot << ", " << track.states.size() << " states, "
            << track.joint_names.size() << " joints" << (track.gripper_joint.empty() ? "" : " + gripper") << "\n";
  return 0;
}

int importCommand(const Options& options)
{
  if (options.positional().size() != 1 || !options.has("bag") || !options.has("robot"))
    throw std::invalid_argument("usage: import CSV --bag FILE --robot R [--gripper-joint J]");
  refuseUnwritable(options.text("bag"));
  const std::string robot = options.text("robot");
  RobotTrack track = importCsv(options.positional()[0], robot);
  track.gripper_joint = options.text("gripper-joint", robot + "_finger_joint");
  if (track.gripper_joint.rfind(robot + "_", 0) != 0)
    throw DemoError("--gripper-joint: '" + track.gripper_joint + "' is not a joint of robot '" + robot +
                    "' (its joints are named " + robot + "_<joint>)");
  BagMetadata metadata;
  metadata.start_stamp = kImportStart;
  writeTrackBag(options.text("bag"), track, metadata);
  std::cout << options.text("bag") << ": " << track.states.size() << " joint_states of robot " << track.robot << "\n";
  return 0;
}

int segmentCommand(const Options& options)
{
  if (options.positional().size() != 1)
    throw std::invalid_argument("usage: segment BAG [--out FILE.yaml]");
  const std::string bag = options.positional()[0];
  std::string out = options.text("out", "");
  if (out.empty())
    out = (bag.size() > 4 && bag.substr(bag.size() - 4) == ".bag" ? bag.substr(0, bag.size() - 4) : bag) +
          ".segments.yaml";
  refuseUnwritable(out);
  const Demonstration demo = readDemonstration(bag);
  const SegmentReport report = segmentReport(bag, demo, SegmentationOptions{});
  writeNewFile(out, report.yaml);
  std::cout << report.table << "written: " << out << "\n";
  return 0;
}

/// The plot script gets every path as its own argument (no shell); it writes a temporary beside the
/// target, which then appears under the target's name only if that is still free.
int plotCommand(const Options& options)
{
  if (options.positional().size() != 1 || !options.has("out"))
    throw std::invalid_argument("usage: plot BAG --out FILE.png [--robot R]");
  const std::string bag = options.positional()[0], out = options.text("out");
  refuseUnwritable(out);
  Demonstration demo;
  const RobotTrack track = pickTrack(bag, options, demo);
  char folder[] = "/tmp/vrrw_demo_plot_XXXXXX";
  if (!::mkdtemp(folder))
    throw DemoError("cannot create a temporary folder in /tmp");
  const std::string csv = std::string(folder) + "/demo.csv", segments = std::string(folder) + "/segments.yaml";
  exportCsv(track, csv);
  Demonstration one = demo;
  one.robots = { track };
  writeNewFile(segments, segmentReport(bag, one, SegmentationOptions{}).yaml);
  const std::string picture = temporaryBeside(out);
  const int status = vrrw_common::runProgram({ "/usr/bin/python3", VRRW_DEMOS_SCRIPTS "/plot_demo.py", "--csv", csv,
                                               "--segments", segments, "--title", bag + " (" + track.robot + ")",
                                               "--out", picture });
  std::remove(csv.c_str());
  std::remove(segments.c_str());
  ::rmdir(folder);
  if (status != 0)
  {
    std::remove(picture.c_str());
    throw DemoError(out + ": the plot script failed (exit status " + std::to_string(status) + ")");
  }
  publishNewFile(picture, out);
  std::cout << "written: " << out << "\n";
  return 0;
}

int run(const std::string& command, int argc, char** argv)
{
  if (command == "replay")
    return runReplay(argc, argv, g_interrupted);
  if (command == "record")
    return runRecord(argc, argv, g_interrupted);
  const Options options(argc, argv, 2, { "csv", "robot", "segment", "bag", "gripper-joint", "out" });
  if (command == "export")
    return exportCommand(options);
  if (command == "import")
    return importCommand(options);
  if (command == "segment")
    return segmentCommand(options);
  if (command == "plot")
    return plotCommand(options);
  throw std::invalid_argument("usage: vrrw demos export|import|segment|plot|replay|recover ... (./vrrw demos help)");
}
}  // namespace

int main(int argc, char** argv)
{
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress reaches a pipe line by line
  std::signal(SIGINT, [](int) { g_interrupted = true; });
  std::signal(SIGTERM, [](int) { g_interrupted = true; });
  const std::string command = argc > 1 ? argv[1] : "";
  const std::string tool = command == "record" ? "vrrw record" : "vrrw demos " + command;  // as the user typed it
  try
  {
    return run(command, argc, argv);
  }
  catch (const vrrw_common::WorkspaceError& e)  // no (whole) workspace: a failure to run, not bad input
  {
    std::cerr << tool << ": " << e.what() << "\n";
    return 1;
  }
  catch (const std::exception& e)  // DemoError: bad input; OptionError / invalid_argument: usage, options
  {
    std::cerr << tool << ": " << e.what() << "\n";
    return 2;
  }
}
