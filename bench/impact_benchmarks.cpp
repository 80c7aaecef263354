// Time per solve of the multiple-impact engine (Google Benchmark). Run by ./scripts/bench; not part of the tests.
#include <benchmark/benchmark.h>

#include <cmath>

#include "../test/fixtures/paper_masse.hpp"
#include "bench_support.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "paper_impulse_method.hpp"
#include "paper_masse_method.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
/// Argument: −log10 of the relative tolerance (12 is the default).
template <class Problem>
void solveRepeatedly(benchmark::State& state, const Problem& problem, bool closed_form = true)
{
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  bench::timeSolves(state, problem, closed_form ? bench::withTolerance(tolerance) : bench::integratedOnly(tolerance));
}

void BM_Table1(benchmark::State& state)
{
  solveRepeatedly(state, bench::table1());
}

/// The same with every state integrated numerically: what the closed form saves.
void BM_Table1Integrated(benchmark::State& state)
{
  solveRepeatedly(state, bench::table1(), false);
}

void BM_ElasticChain10(benchmark::State& state)
{
  solveRepeatedly(state, bench::elasticChain(10));
}

void BM_MasseStrike(benchmark::State& state)
{
  solveRepeatedly(state, fixtures::paperMasseStrike());
}
void BM_Landing(benchmark::State& state)
{
  solveRepeatedly(state, bench::masseLanding());
}

void BM_LandingIntegrated(benchmark::State& state)
{
  solveRepeatedly(state, bench::masseLanding(), false);
}

void BM_CushionHit(benchmark::State& state)
{
  solveRepeatedly(state, bench::cushionHit());
}

/// The massé strike and the cushion hit as the integrator alone solves them in plain time: what the separation
/// clock and the quasi-steady slip save.
void BM_MassePlainTime(benchmark::State& state)
{
  bench::timeSolves(state, fixtures::paperMasseStrike(),
                    bench::plainIntegration(std::pow(10.0, -double(state.range(0)))));
}

void BM_CushionHitPlainTime(benchmark::State& state)
{
  bench::timeSolves(state, bench::cushionHit(), bench::plainIntegration(std::pow(10.0, -double(state.range(0)))));
}

/// A sliding ball on a 9-ft table without pockets that hits three cushions (hopping after each) before it stops.
void BM_TrajectoryThreeCushions(benchmark::State& state)
{
  const bench::ThreeCushionShot shot = bench::threeCushionShot();
  int hits = 0;
  for (auto _ : state)
  {
    const auto trajectory = bsp::predictTrajectory(shot.start, bsp::BallProperties{}, shot.table);
    hits = 0;
    for (const auto& event : trajectory.value().events)
      hits += event.type == bsp::MotionEventType::CushionHit;
    benchmark::DoNotOptimize(trajectory);
  }
  state.counters["cushion_hits"] = hits;
}
/// A table of balls from the first motion to the rest of every ball (strike excluded); argument: −log10 of the
/// impacts' relative tolerance (12 is the default). Counters: ball impacts and events of all balls.
void simulateRepeatedly(benchmark::State& state, const std::vector<bsp::TableBall>& balls)
{
  bsp::MotionParameters parameters;
  parameters.impact = bench::withTolerance(std::pow(10.0, -static_cast<double>(state.range(0))));
  parameters.impact.max_seconds = 60.0;
  std::size_t impacts = 0, events = 0;
  for (auto _ : state)
  {
    const auto run = bsp::simulateTable(balls, bsp::BallProperties{}, bsp::Table{}, parameters);
    if (!run)
    {
      state.SkipWithError(run.error().describe().c_str());
      return;
    }
    impacts = run.value().ball_impacts.size();
    events = 0;
    for (const bsp::BallTrajectory& ball : run.value().balls)
      events += ball.events.size();
  }
  state.counters["ball_impacts"] = static_cast<double>(impacts);
  state.counters["events"] = static_cast<double>(events);
}

void BM_TableCutShot(benchmark::State& state)
{
  simulateRepeatedly(state, bench::cutShot());
}

void BM_TableBreak(benchmark::State& state)
{
  simulateRepeatedly(state, bench::breakShot());
}

/// How the break's cost grows with the rack: a rack of 2 to 5 rows (3, 6, 10 or 15 balls; the argument), every ball
/// to rest at the default tolerance.
void BM_TableBreakRows(benchmark::State& state)
{
  const std::vector<bsp::TableBall> balls = bench::breakShot(8.0, static_cast<int>(state.range(0)));
  bsp::MotionParameters parameters;
  parameters.impact.max_seconds = 60.0;
  for (auto _ : state)
    benchmark::DoNotOptimize(bsp::simulateTable(balls, bsp::BallProperties{}, bsp::Table{}, parameters));
  state.counters["balls"] = static_cast<double>(balls.size() - 1);
}

/// The break's first impact alone: the cue ball (sliding at 8 m/s, no spin) and the 15 racked balls, 47 contacts.
void BM_RackImpact(benchmark::State& state)
{
  bsp::BallCollision rack;
  for (const bsp::TableBall& ball : bench::breakShot())
    rack.balls.push_back({ball.state.position.head<2>(), ball.state.velocity, ball.state.angular_velocity, 0.0});
  rack.balls[0].position.x() = rack.balls[1].position.x() - std::sqrt(std::pow(2.0 * rack.ball_radius, 2) - 1e-4);
  bsp::SolverOptions options = bench::withTolerance(std::pow(10.0, -static_cast<double>(state.range(0))));
  options.max_seconds = 60.0;
  for (auto _ : state)
    benchmark::DoNotOptimize(bsp::solve(rack, options));
}

/// A level centre hit at 2 m/s on the cue ball at `ball` along `direction`, with the other balls of the table;
/// argument: −log10 of the relative tolerance. Reports the strike's contacts.
void strikeRepeatedly(benchmark::State& state, const Eigen::Vector2d& ball, const Eigen::Vector2d& direction,
                      const std::vector<bsp::TableBall>& others)
{
  bsp::ShotConfiguration configuration;
  configuration.solver = bench::withTolerance(std::pow(10.0, -static_cast<double>(state.range(0))));
  bsp::CuePlacement cue;
  cue.ball = ball;
  cue.direction = Eigen::Vector3d(direction.x(), direction.y(), 0.0).normalized();
  cue.tip =
      Eigen::Vector3d(ball.x(), ball.y(), configuration.ball_radius) - 1.5 * configuration.ball_radius * cue.direction;
  cue.speed = 2.0;
  std::size_t contacts = 0;
  for (auto _ : state)
  {
    auto struck = bsp::strikeBall(cue, configuration, others);
    if (!struck)
    {
      state.SkipWithError(struck.error().describe().c_str());
      return;
    }
    contacts = struck.value().contacts.size();
  }
  state.counters["contacts"] = static_cast<double>(contacts);
}

/// The lone strike, for scale: the cue ball alone on the table.
void BM_LoneStrike(benchmark::State& state)
{
  strikeRepeatedly(state, {-0.4, 0.1}, {std::cos(0.35), std::sin(0.35)}, {});
}

/// A frozen pair: the object ball 2R from the cue ball along +x, the cue turned 20° from the line of centres.
void BM_FrozenPairStrike(benchmark::State& state)
{
  const double radius = bsp::ShotConfiguration{}.ball_radius;
  bsp::TableBall one{"one", {}};
  one.state.position = Eigen::Vector3d(-0.4 + 2.0 * radius, 0.1, radius);
  strikeRepeatedly(state, {-0.4, 0.1}, {std::cos(0.35), std::sin(0.35)}, {one});
}

/// A cue ball frozen to the side of the racked 15 balls (outside the rack's lower side, touching the third row's
/// outer ball), struck straight into the rack: the cue's, 15 ball–ball, 16 cloth contacts in one impact.
void BM_FrozenRackSideStrike(benchmark::State& state)
{
  const double radius = bsp::ShotConfiguration{}.ball_radius;
  std::vector<bsp::TableBall> rack = bench::breakShot();
  rack.erase(rack.begin());                                          // the cue ball of the break
  const Eigen::Vector2d outward(-0.5, -0.5 * std::sqrt(3.0));        // away from the rack, across its lower side
  const Eigen::Vector2d touched = rack[3].state.position.head<2>();  // row 2, the lower side's ball
  strikeRepeatedly(state, touched + 2.0 * radius * outward, -outward, rack);
}

/// The paper's fixed-step impulse method on Table 1; argument: −log10 of the impulse step. Error against the
/// converged values of docs/validation.md, Table 1 (v1 = 0.6139494, v2 = 0.2097195).
void BM_Table1PaperMethod(benchmark::State& state)
{
  const double step = std::pow(10.0, -static_cast<double>(state.range(0)));
  const bsp::BallBallTable c = bench::table1();
  paper_method::Result result{};
  for (auto _ : state)
  {
    result = paper_method::solve(c.m1, c.m2, c.stiffness_ratio, c.e1, c.e2, c.v0, step);
    benchmark::DoNotOptimize(result);
  }
  state.counters["velocity_error"] = std::max(std::abs(result.v1 - 0.6139494), std::abs(result.v2 - 0.2097195));
  state.counters["steps"] = static_cast<double>(result.steps);
}

/// The paper's method on the massé strike; argument: −log10 of the impulse step in units of m_ball·v_cue.
void BM_MassePaperMethod(benchmark::State& state)
{
  const bsp::CueStrike strike = fixtures::paperMasseStrike();
  const bsp::ImpactProblem problem = bsp::makeImpactProblem(strike).value();
  const double step = std::pow(10.0, -static_cast<double>(state.range(0))) * strike.ball_mass * strike.cue_speed;
  paper_method::MasseResult result;
  for (auto _ : state)
  {
    result = paper_method::solveMasse(problem, step);
    benchmark::DoNotOptimize(result);
  }
  state.counters["velocity_error"] = (result.velocity - bench::referenceVelocities(strike)).cwiseAbs().maxCoeff();
  state.counters["steps"] = static_cast<double>(result.steps);
}
}  // namespace

BENCHMARK(BM_Table1PaperMethod)->Arg(3)->Arg(4)->Arg(5)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MassePaperMethod)->Arg(3)->Arg(4)->Arg(5)->Arg(6)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TrajectoryThreeCushions)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TableCutShot)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RackImpact)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TableBreak)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TableBreakRows)->Arg(2)->Arg(3)->Arg(4)->Arg(5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoneStrike)->Arg(8)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FrozenPairStrike)->Arg(8)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FrozenRackSideStrike)->Arg(8)->Arg(12)->Unit(benchmark::kMicrosecond);

// Argument: −log10 of the relative tolerance (12 is the default; the closed form does not depend on it).
// velocity_error: against the reference of bench_problems.hpp.
BENCHMARK(BM_Table1)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Table1Integrated)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ElasticChain10)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MasseStrike)->Arg(8)->Arg(10)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Landing)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LandingIntegrated)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MassePlainTime)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CushionHit)->Arg(8)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CushionHitPlainTime)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
