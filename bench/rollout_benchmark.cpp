// The cost of one planning rollout: a noisy stroke placed, checked for a clear cue and predicted to rest (the
// strike, every ball's path, every impact), at the planner's tolerance (PLANNING_TOLERANCE, relative 1e-5, absolute
// 1e-8), on the plan benchmark's seeded random layouts (test/fixtures/plan_layouts.hpp: 1, 3, 7 and 15 object balls, a
// quarter each). Each layout's shot is the ghost-ball baseline's (the plan benchmark's), so that the rollouts do not
// depend on a planner's search; each rollout draws its stroke from the planner's default ExecutionNoise with a
// generator seeded by the layout.
//
// Prints one markdown row per group: rollouts, the median, 95th percentile and mean time of one rollout on one
// thread, and rollouts per second on one thread and on two (the same rollouts split between two threads, each with its
// own configuration copy, as the planner runs them). Arguments: [layouts = 200] [rollouts per layout = 20] [relative
// tolerance = the planner's; the absolute one a hundredth of it, at most 1e-8].
//
// Built with -DBILLIARD_SHOT_PLANNER_BENCHMARKS=ON (scripts/bench runs it).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "../test/fixtures/plan_layouts.hpp"
#include "billiard_shot_planner/planning/shot_planner.hpp"

namespace bsp = billiard_shot_planner;
using namespace plan_layouts;  // NOLINT(google-build-using-namespace): the benchmark is about those layouts

namespace
{
double relative_tolerance = bsp::PLANNING_TOLERANCE;

using Clock = std::chrono::steady_clock;

/// One rollout to play: the layout's object balls, its cue ball and the noisy stroke.
struct Rollout
{
  std::string group;
  const Layout* layout = nullptr;
  bsp::Stroke stroke;
};

bsp::ShotConfiguration planningConfiguration()
{
  bsp::ShotConfiguration configuration = CONFIGURATION;
  configuration.solver.relative_tolerance = relative_tolerance;
  configuration.solver.absolute_tolerance = std::min(bsp::LOOSEST_ABSOLUTE_TOLERANCE, 1e-2 * relative_tolerance);
  return configuration;
}

/// Plays one rollout as the planner does; false when it could not be placed or predicted.
bool play(const Rollout& rollout, const bsp::ShotConfiguration& configuration)
{
  const std::vector<bsp::TableBall> others = objectBalls(*rollout.layout);
  const auto cue = bsp::placeStroke(rollout.stroke, rollout.layout->balls[0].state.position.head<2>(), R);
  if (!cue)
    return false;
  if (!bsp::cueClears(cue.value(), others, configuration.table, bsp::RobotLimits{}, R))
    return true;  // a foul: the planner stops there too
  return bsp::predictShot(cue.value(), configuration, others).ok();
}

double percentile(std::vector<double> values, double share)
{
  if (values.empty())
    return NAN;
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(share * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(index, values.size() - 1)];
}

/// Seconds to play every rollout of `rollouts`, split between `threads` threads.
double wallTime(const std::vector<const Rollout*>& rollouts, int threads)
{
  const auto start = Clock::now();
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t)
    workers.emplace_back(
        [&rollouts, t, threads]
        {
          const bsp::ShotConfiguration configuration = planningConfiguration();
          for (std::size_t k = static_cast<std::size_t>(t); k < rollouts.size(); k += static_cast<std::size_t>(threads))
            play(*rollouts[k], configuration);
        });
  for (std::thread& worker : workers)
    worker.join();
  return std::chrono::duration<double>(Clock::now() - start).count();
}
}  // namespace

int main(int argc, char** argv)
{
  const int layouts = argc > 1 ? std::max(1, std::atoi(argv[1])) : 200;
  const int per_layout = argc > 2 ? std::max(1, std::atoi(argv[2])) : 20;
  if (argc > 3)
    relative_tolerance = std::atof(argv[3]);

  std::vector<Layout> tables;
  tables.reserve(static_cast<std::size_t>(layouts));
  for (int k = 0; k < layouts; ++k)
    tables.push_back(randomLayout(static_cast<unsigned>(k)));
  std::vector<Rollout> rollouts;
  for (const Layout& layout : tables)
  {
    const ChosenShot shot = ghostBallShot(layout);
    std::mt19937 random(layout.seed);
    for (int k = 0; k < per_layout; ++k)
      rollouts.push_back({layout.group, &layout, bsp::noisyStroke(shot.stroke, bsp::ExecutionNoise{}, R, random)});
  }

  std::map<std::string, std::vector<double>> seconds;
  std::map<std::string, std::vector<const Rollout*>> by_group;
  int failed = 0;
  const bsp::ShotConfiguration configuration = planningConfiguration();
  for (const Rollout& rollout : rollouts)
  {
    const auto start = Clock::now();
    failed += play(rollout, configuration) ? 0 : 1;
    seconds[rollout.group].push_back(std::chrono::duration<double>(Clock::now() - start).count());
    by_group[rollout.group].push_back(&rollout);
  }

  std::printf("relative tolerance %g\n\n", relative_tolerance);
  std::printf("| group | rollouts | p50 | p95 | mean | rollouts/s, 1 thread | rollouts/s, 2 threads |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (int count : OBJECT_BALL_COUNTS)
  {
    const std::string group = groupName(count);
    const std::vector<double>& times = seconds[group];
    if (times.empty())
      continue;
    double total = 0.0;
    for (double t : times)
      total += t;
    const double one = wallTime(by_group[group], 1), two = wallTime(by_group[group], 2);
    const auto n = static_cast<double>(times.size());
    std::printf("| %s | %zu | %.3f ms | %.3f ms | %.3f ms | %.0f | %.0f |\n", group.c_str(), times.size(),
                1e3 * percentile(times, 0.5), 1e3 * percentile(times, 0.95), 1e3 * total / n, n / one, n / two);
  }
  std::printf("\nrollouts that could not be placed or predicted: %d of %zu\n", failed, rollouts.size());
  return 0;
}
