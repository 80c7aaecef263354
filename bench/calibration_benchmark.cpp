// Time of one track fit (Google Benchmark): 20 shots of the cue ball alone into the cushions, tracked at 30 Hz for
// up to 5 s with 2 mm of noise, drawn from known constants; the sliding and rolling friction and the cushion's
// restitution fitted from the defaults. Argument: threads. Not part of the tests.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "billiard_shot_planner/calibration/track_fit.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double R = 0.0286;

/// A level stroke at φ (rad) and speed from (x, y), hit b radii above the centre.
bsp::CuePlacement stroke(const Eigen::Vector2d& ball, double phi, double speed, double b)
{
  const Eigen::Vector3d direction(std::cos(phi), std::sin(phi), 0.0);
  const Eigen::Vector3d hit =
      Eigen::Vector3d(ball.x(), ball.y(), R) +
      R * Eigen::Vector3d(-direction.x() * std::sqrt(1 - b * b), -direction.y() * std::sqrt(1 - b * b), b);
  return {hit, direction, speed, ball};
}

std::vector<bsp::ObservedShot> trackedShots(const bsp::ShotConfiguration& truth, int count)
{
  std::mt19937 rng(26);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> camera(0.0, 0.002);
  std::vector<bsp::ObservedShot> shots;
  while (static_cast<int>(shots.size()) < count)
  {
    const Eigen::Vector2d ball(-1.0 + 2.0 * unit(rng), -0.45 + 0.9 * unit(rng));
    const bsp::CuePlacement cue = stroke(ball, 2.0 * M_PI * unit(rng), 1.0 + 2.0 * unit(rng), 0.6 * unit(rng) - 0.3);
    const auto outcome = bsp::predictShot(cue, truth);
    if (!outcome)
      continue;
    bsp::ObservedShot shot{cue, {}, {}};
    const double end = std::min(5.0, outcome->trajectory.duration());
    for (double t = 0.0; t <= end; t += 1.0 / 30.0)
      shot.tracks[bsp::CUE_BALL_ID].push_back(
          {t, outcome->trajectory.at(t).position.head<2>() + Eigen::Vector2d(camera(rng), camera(rng))});
    shots.push_back(shot);
  }
  return shots;
}

void BM_TrackFit20Shots(benchmark::State& state)
{
  bsp::ShotConfiguration truth;
  truth.motion.sliding_friction = 0.2;
  truth.motion.rolling_friction = 0.015;
  truth.table.cushion.restitution = 0.75;
  const std::vector<bsp::ObservedShot> shots = trackedShots(truth, 20);
  const std::vector<bsp::FitParameter> parameters = {{"motion.sliding_friction", 0.152479, 0.01, 1.0},
                                                     {"motion.rolling_friction", 0.0209727, 0.001, 0.2},
                                                     {"table.cushion.restitution", 0.85, 0.0, 1.0}};
  bsp::FitOptions options;
  options.threads = static_cast<int>(state.range(0));
  int points = 0;
  for (const bsp::ObservedShot& shot : shots)
    points += static_cast<int>(shot.tracks.at(bsp::CUE_BALL_ID).size());
  for (auto _ : state)
  {
    const auto fit = bsp::fitTracks(bsp::ShotConfiguration{}, parameters, shots, 0.002, options);
    if (!fit)
    {
      state.SkipWithError(fit.error().describe().c_str());
      return;
    }
    state.counters["iterations"] = fit->fit.iterations;
    state.counters["chi2_per_point"] = 2.0 * fit->fit.final_cost / (2.0 * points);
    state.counters["sliding_error"] = fit->fit.parameters[0].value - 0.2;
    state.counters["restitution_error"] = fit->fit.parameters[2].value - 0.75;
  }
  state.counters["track_points"] = points;
}
BENCHMARK(BM_TrackFit20Shots)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(2);
}  // namespace

BENCHMARK_MAIN();
