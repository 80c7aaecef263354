#pragma once

// The timed solve loop of the Google Benchmark programs, over the problems of bench_problems.hpp.
#include <benchmark/benchmark.h>

#include "../test/fixtures/bench_problems.hpp"

namespace bench
{
/// Times the solve and reports its velocity error as the counter velocity_error.
template <class Problem>
void timeSolves(benchmark::State& state, const Problem& problem, const bsp::SolverOptions& options)
{
  for (auto _ : state)
    benchmark::DoNotOptimize(bsp::solve(problem, options));
  state.counters["velocity_error"] = velocityError(problem, options);
}

}  // namespace bench
