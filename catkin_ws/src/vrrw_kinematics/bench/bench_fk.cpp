// vrrw_bench_fk: tip pose in the base frame for --q, or FK timing over random states (--samples N).
// Last line: one JSON object.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>
#include <sstream>

#include <vrrw_common/options.h>

#include "bench_support.h"
#include "vrrw_kinematics/kinematic_chain.h"


namespace
{
Eigen::VectorXd parseJoints(const std::string& text, std::size_t expected)
{
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    values.push_back(std::stod(item));
  if (values.size() != expected)
    throw std::runtime_error("argument --q: expected " + std::to_string(expected) + " values, got " +
                             std::to_string(values.size()));
  return Eigen::Map<Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const vrrw_common::Options args(argc, argv, 1, { "urdf", "base", "tip", "q", "samples", "seed" }, {});
    const std::string urdf = vrrw_kinematics::readFile(args.text("urdf"));
    const auto chain = vrrw_kinematics::KinematicChain::fromUrdf(urdf, args.text("base"), args.text("tip"));
    if (args.has("q"))
    {
      const Eigen::Isometry3d pose = chain.fk(parseJoints(args.text("q"), chain.size()));
      const Eigen::Quaterniond quaternion(pose.linear());
      std::printf("{\"xyz\": [%.12f, %.12f, %.12f], \"xyzw\": [%.12f, %.12f, %.12f, %.12f]}\n", pose.translation().x(),
                  pose.translation().y(), pose.translation().z(), quaternion.x(), quaternion.y(), quaternion.z(),
                  quaternion.w());
      return 0;
    }
    const long samples = static_cast<long>(args.count("samples", 100000, 1, 100000000));
    std::mt19937_64 rng(static_cast<std::uint64_t>(args.count("seed", 1, 0, vrrw_common::Options::kMaxCount)));
    std::vector<Eigen::VectorXd> states;
    for (long s = 0; s < samples; ++s)
      states.push_back(chain.randomState(rng));
    double checksum = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (const Eigen::VectorXd& q : states)
      checksum += chain.fk(q).translation().x();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("{\"samples\": %ld, \"mean_ns\": %.2f, \"fk_per_s\": %.0f, \"checksum\": %.6f}\n", samples,
                seconds / static_cast<double>(samples) * 1e9, static_cast<double>(samples) / seconds, checksum);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_fk: " << e.what() << "\n";
    std::printf("{\"error\": \"%s\"}\n", e.what());
    return 2;
  }
}
