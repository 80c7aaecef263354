// Instructions per solve of the package's main problems, counted by callgrind around a loop of solves. Unlike the
// times of impact_benchmarks they do not move with the load of a shared host, so they compare runs of different
// days (bench/NOTES.md). ./scripts/bench runs
//   valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file=/dev/null instruction_counts PROBLEM SOLVES
// and divides the instructions collected by SOLVES; without valgrind the program only solves.
// PROBLEM: table1, chain10, masse, landing, cushion, trajectory, prediction (the service's massé shot, library side).
#include <valgrind/callgrind.h>

#include <cstdio>
#include <functional>
#include <map>
#include <string>

#include "../test/fixtures/bench_problems.hpp"
#include "../test/fixtures/paper_masse.hpp"

namespace
{
namespace bsp = billiard_shot_planner;

/// Whether the solve succeeded: a failing problem must not be counted as a cheap one.
template <class Result>
bool succeeded(const bsp::Expected<Result>& result)
{
  return static_cast<bool>(result);
}

const std::map<std::string, std::function<bool()>>& problems()
{
  static const std::map<std::string, std::function<bool()>> all = {
      {"table1", [] { return succeeded(bsp::solve(bench::table1())); }},
      {"chain10", [] { return succeeded(bsp::solve(bench::elasticChain(10))); }},
      {"masse", [] { return succeeded(bsp::solve(fixtures::paperMasseStrike())); }},
      {"landing", [] { return succeeded(bsp::solve(bench::masseLanding())); }},
      {"cushion", [] { return succeeded(bsp::solve(bench::cushionHit())); }},
      {"trajectory",
       []
       {
         const bench::ThreeCushionShot shot = bench::threeCushionShot();
         return succeeded(bsp::predictTrajectory(shot.start, bsp::BallProperties{}, shot.table));
       }},
      {"prediction", [] { return succeeded(bsp::predictShot(bench::serviceMasseShot(), bsp::ShotConfiguration{})); }},
  };
  return all;
}
}  // namespace

int main(int argc, char** argv)
{
  const auto problem = argc == 3 ? problems().find(argv[1]) : problems().end();
  if (problem == problems().end())
  {
    std::fprintf(stderr, "usage: instruction_counts PROBLEM SOLVES (PROBLEM: ");
    for (const auto& [name, solve] : problems())
      std::fprintf(stderr, "%s ", name.c_str());
    std::fprintf(stderr, ")\n");
    return 2;
  }
  const int solves = std::stoi(argv[2]);
  // One solve first, outside the count: the first call's lazy symbol binding and the allocator's first growth.
  if (!problem->second())
    return 1;
  CALLGRIND_TOGGLE_COLLECT;
  bool ok = true;
  for (int i = 0; i < solves; ++i)
    ok = problem->second() && ok;
  CALLGRIND_TOGGLE_COLLECT;
  return ok ? 0 : 1;
}
