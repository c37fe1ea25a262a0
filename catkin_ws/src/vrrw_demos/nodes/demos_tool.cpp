// vrrw_demos: the demonstration tool behind `./vrrw demos ...`.
//   export BAG --csv FILE [--robot R] [--segment NAME]   one row per recorded state
//   import CSV --bag FILE --robot R [--gripper-joint J]
//   segment BAG [--out FILE.yaml]                          the pick-and-place instructions, YAML + table
//   plot BAG --out FILE.png [--robot R]                    joints, gripper and segment boundaries
//   replay BAG --mode fake|physics|real [--robot R] [--segment NAME] [--speed S] [--tolerance RAD] [--yes]
// Exit codes: 0 done, 1 bad input (one line on stderr naming the file, topic or field), 2 usage.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

#include <vrrw_demos/demo_csv.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/segmentation.h>
#include <vrrw_common/options.h>
#include <vrrw_trajectory/whole_file.h>

#include <vrrw_demos/ros/demo_bag.h>
#include "replay.h"
#include "segment_report.h"

using namespace vrrw_demos;
using vrrw_common::Options;

namespace
{
/// Seconds since the epoch of the stamps an imported CSV gets (its t = 0); any fixed value would do.
constexpr double kImportStart = 1e9;

bool exists(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}

void refuseExisting(const std::string& path)
{
  if (exists(path))
    throw DemoError(path + ": exists; not overwritten (remove it or choose another name)");
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
  refuseExisting(options.text("csv"));
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
  refuseExisting(options.text("bag"));
  RobotTrack track = importCsv(options.positional()[0], options.text("robot"));
  track.gripper_joint = options.text("gripper-joint", options.text("robot") + "_finger_joint");
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
  refuseExisting(out);
  const Demonstration demo = readDemonstration(bag);
  const SegmentReport report = segmentReport(bag, demo, SegmentationOptions{});
  vrrw_trajectory::writeWholeFile(out, report.yaml);
  std::cout << report.table << "written: " << out << "\n";
  return 0;
}

int plotCommand(const Options& options)
{
  if (options.positional().size() != 1 || !options.has("out"))
    throw std::invalid_argument("usage: plot BAG --out FILE.png [--robot R]");
  const std::string bag = options.positional()[0], out = options.text("out");
  refuseExisting(out);
  Demonstration demo;
  const RobotTrack track = pickTrack(bag, options, demo);
  char folder[] = "/tmp/vrrw_demo_plot_XXXXXX";
  if (!::mkdtemp(folder))
    throw DemoError("cannot create a temporary folder in /tmp");
  const std::string csv = std::string(folder) + "/demo.csv", segments = std::string(folder) + "/segments.yaml";
  exportCsv(track, csv);
  Demonstration one = demo;
  one.robots = { track };
  vrrw_trajectory::writeWholeFile(segments, segmentReport(bag, one, SegmentationOptions{}).yaml);
  const std::string command = "/usr/bin/python3 '" VRRW_DEMOS_SCRIPTS "/plot_demo.py' --csv '" + csv +
                              "' --segments '" + segments + "' --title '" + bag + " (" + track.robot + ")' --out '" +
                              out + "'";
  const int status = std::system(command.c_str());
  std::remove(csv.c_str());
  std::remove(segments.c_str());
  ::rmdir(folder);
  if (status != 0)
    throw DemoError(out + ": the plot script failed");
  std::cout << "written: " << out << "\n";
  return 0;
}
}  // namespace

int main(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  try
  {
    if (command == "replay")
      return runReplay(argc, argv);
    const Options options(argc, argv, 2, { "csv", "robot", "segment", "bag", "gripper-joint", "out" });
    if (command == "export")
      return exportCommand(options);
    if (command == "import")
      return importCommand(options);
    if (command == "segment")
      return segmentCommand(options);
    if (command == "plot")
      return plotCommand(options);
    std::cerr << "usage: vrrw demos export|import|segment|plot|replay|recover ... (./vrrw help)\n";
    return 2;
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "vrrw demos " << command << ": " << e.what() << "\n";
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw demos " << command << ": " << e.what() << "\n";
    return 1;
  }
}
