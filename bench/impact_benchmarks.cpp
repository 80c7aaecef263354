// Time per solve of the multiple-impact engine (Google Benchmark). Run by ./scripts/bench; not part of the tests.
#include <benchmark/benchmark.h>

#include <cmath>

#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
bsp::BallBallTable table1()
{
  return {1.0, 2.0 / std::sqrt(3.0), 1.0, 0.9, 0.7, -1.0};
}

bsp::BallChain elasticChain(std::size_t balls)
{
  bsp::BallChain chain;
  chain.masses.assign(balls, 1.0);
  chain.velocities.assign(balls, 0.0);
  chain.velocities[0] = 1.0;
  chain.stiffness.assign(balls - 1, 1.0);
  chain.restitution.assign(balls - 1, 1.0);
  return chain;
}

bsp::SolverOptions withTolerance(double relative)
{
  bsp::SolverOptions options;
  options.relative_tolerance = relative;
  options.absolute_tolerance = relative * 1e-2;
  return options;
}

/// Error of the final velocities against a solve at 1e-13.
template <class Problem>
double velocityError(const Problem& problem, const bsp::SolverOptions& options)
{
  const auto reference = bsp::solve(problem, withTolerance(1e-13)).value();
  const auto result = bsp::solve(problem, options).value();
  return (result.velocity - reference.velocity).cwiseAbs().maxCoeff();
}

template <class Problem>
void solveRepeatedly(benchmark::State& state, const Problem& problem)
{
  const bsp::SolverOptions options = withTolerance(std::pow(10.0, -static_cast<double>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(bsp::solve(problem, options));
  state.counters["velocity_error"] = velocityError(problem, options);
}

void BM_Table1(benchmark::State& state)
{
  solveRepeatedly(state, table1());
}

void BM_ElasticChain10(benchmark::State& state)
{
  solveRepeatedly(state, elasticChain(10));
}
}  // namespace

// Argument: −log10 of the relative tolerance (12 is the default).
BENCHMARK(BM_Table1)->Arg(8)->Arg(10)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ElasticChain10)->Arg(8)->Arg(10)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
