// vrrw_bench_ik: IK success rate and time on FK targets of uniform random states, seeded at
// mid-limits (the TRAC-IK protocol). Last line: one JSON object.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>

#include <vrrw_common/options.h>

#include "bench_support.h"
#include "vrrw_kinematics/ik_solver.h"


int main(int argc, char** argv)
{
  try
  {
    const vrrw_common::Options args(argc, argv, 1, { "urdf", "base", "tip", "tolerance", "timeout-ms", "samples", "seed" }, { "numeric" });
    const std::string urdf = vrrw_kinematics::readFile(args.text("urdf"));
    const auto chain = vrrw_kinematics::KinematicChain::fromUrdf(urdf, args.text("base"), args.text("tip"));
    const vrrw_kinematics::IkSolver solver(chain);
    vrrw_kinematics::IkOptions options;
    options.tolerance = args.number("tolerance", 1e-5);
    options.timeout = args.number("timeout-ms", 5.0) / 1000.0;
    options.allow_analytic = !args.has("numeric");
    const long samples = static_cast<long>(args.count("samples", 10000, 1, 100000000));
    std::mt19937_64 rng(static_cast<std::uint64_t>(args.count("seed", 1, 0, vrrw_common::Options::kMaxCount)));
    const Eigen::VectorXd seed = chain.midLimits();
    std::vector<double> times_us;
    long successes = 0;
    for (long s = 0; s < samples; ++s)
    {
      const Eigen::Isometry3d target = chain.fk(chain.randomState(rng));
      options.seed = static_cast<std::uint64_t>(s + 1);
      const auto start = std::chrono::steady_clock::now();
      const vrrw_kinematics::IkResult result = solver.solve(target, seed, options);
      times_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
      if (result.success && chain.withinLimits(result.q))
        ++successes;
    }
    double mean = 0.0;
    for (const double t : times_us)
      mean += t / static_cast<double>(times_us.size());
    std::printf("{\"urdf\": \"%s\", \"base\": \"%s\", \"tip\": \"%s\", \"dof\": %zu, \"solver\": \"%s\", "
                "\"samples\": %ld, \"success_rate\": %.6f, \"mean_us\": %.3f, \"median_us\": %.3f, "
                "\"p99_us\": %.3f}\n",
                args.text("urdf").c_str(), chain.baseLink().c_str(), chain.tipLink().c_str(), chain.size(),
                solver.hasAnalytic() && options.allow_analytic ? "ur_analytic" : "numeric", samples,
                static_cast<double>(successes) / static_cast<double>(samples), mean,
                vrrw_kinematics::percentile(times_us, 50), vrrw_kinematics::percentile(times_us, 99));
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_ik: " << e.what() << "\n";
    std::printf("{\"error\": \"%s\"}\n", e.what());
    return 2;
  }
}
