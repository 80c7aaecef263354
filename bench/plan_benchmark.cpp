// The shot planner against a ghost-ball baseline, side by side in one run, on seeded random tables (1, 3, 7 and 15
// object balls, a quarter each), three hand-made layouts whose only pot is blocked by a ball on the cue ball's
// line to the ghost ball ("blocked": a combination can still pot them), and four where that ball stands a little to
// the side of the line ("detour": the straight shot hits it thin and pots nothing; a kick, a massé or a jump can). For
// each planner and layout: whether it found a pot (the baseline: whether a ghost-ball shot with clear paths existed),
// the pot probability of the shot it returns measured by fresh noisy rollouts drawn here (the planner's default
// ExecutionNoise, the same draws for both planners, replayed at the configuration's own tolerance), the planning time,
// and the planner's own estimate against the fresh measurement. Prints one markdown row per group, and the layouts
// whose estimate and fresh measurement disagree by more than three standard deviations.
//
// A pot: the target (the plan's, or the baseline's chosen ball) drops in any pocket (the requested one in the
// blocked layouts) and the cue ball comes to rest on the table (it does not drop or fly off). A plan that found no pot
// is measured on the closest attempt it returns (none: probability 0). The baseline aims the cue ball's centre at the
// ghost ball of the target–pocket pair with the smallest cut among those whose straight paths pass 2R from the other
// object balls (none: the smallest cut), a centre hit at a cue speed of 2 m/s and the lowest elevation whose cue clears
// the balls and the rails (the planner's rule, without its margin). A noisy stroke whose cue touches a ball or a rail
// is a miss for both.
//
// Layout k of the random ones is drawn by std::mt19937(k) and planned with seed k; the blocked ones follow as
// layouts N to N + 2, the detour ones as N + 3 to N + 6. Arguments: [layouts N = 200] [fresh rollouts = 1000] [planner
// threads = 1] [one layout index: plan only that one and print both shots; -1: all]. PLAN_BENCHMARK_POCKET_MODEL=jaws
// plans and replays every shot on the jaws (table.pocket_model) instead of the capture circles.
//
// Built with -DBILLIARD_SHOT_PLANNER_BENCHMARKS=ON (scripts/bench runs it); by hand from the repository's root:
//   g++ -O2 -std=c++17 -Iinclude -I/usr/include/eigen3 bench/plan_benchmark.cpp -Lbuild/devel/lib
//     -lbilliard_shot_planner_planning -lbilliard_shot_planner_core -Wl,-rpath,$PWD/build/devel/lib
//     -o /tmp/plan_benchmark
//   /tmp/plan_benchmark 40 300 1
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "../test/fixtures/plan_layouts.hpp"
#include "billiard_shot_planner/planning/shot_planner.hpp"

namespace bsp = billiard_shot_planner;
using namespace plan_layouts;  // NOLINT(google-build-using-namespace): the benchmark is about those layouts

namespace
{
const double PLAN_BUDGET = 0.5;            ///< s
const unsigned FRESH_SEED_OFFSET = 7919u;  ///< of the fresh rollouts' generator: another stream than the planner's

/// The layouts' configuration, on the pocket model PLAN_BENCHMARK_POCKET_MODEL names (circles by default).
const bsp::ShotConfiguration& benchConfiguration()
{
  static const bsp::ShotConfiguration configuration = []
  {
    bsp::ShotConfiguration c = CONFIGURATION;
    const char* model = std::getenv("PLAN_BENCHMARK_POCKET_MODEL");
    if (model && std::string(model) == "jaws")
      c.table.pocket_model = bsp::PocketModel::Jaws;
    return c;
  }();
  return configuration;
}

struct LayoutResult
{
  std::string group;
  unsigned seed = 0;
  ChosenShot planner, baseline;
  double planner_fresh = 0.0, baseline_fresh = 0.0;
  double planner_estimate = 0.0;
  int planner_estimate_rollouts = 0;
  double planning_seconds = 0.0;
  double first_pot_seconds = NAN;  ///< when the planner first reported a shot that pots (NaN: never)
};

struct Settings
{
  int random_layouts = 200;
  int fresh_rollouts = 1000;
  int threads = 1;
  int only_layout = -1;
};

bsp::PlanRequest planRequest(const Layout& layout, int threads)
{
  bsp::PlanRequest request;
  request.balls = layout.balls;
  request.target = layout.target;
  if (layout.pocket >= 0)
    request.pocket = bsp::pocketId(CONFIGURATION.table.pockets, static_cast<std::size_t>(layout.pocket));
  request.budget = PLAN_BUDGET;
  request.seed = layout.seed;
  request.threads = threads;
  return request;
}

int unpredictable_rollouts = 0;  ///< rollouts whose stroke could not be placed or predicted (counted as misses)

bool noisyRolloutPots(const ChosenShot& shot, const Layout& layout, const std::vector<bsp::TableBall>& others,
                      std::mt19937& random)
{
  const bsp::Stroke stroke = bsp::noisyStroke(shot.stroke, bsp::ExecutionNoise{}, R, random);
  const auto cue = bsp::placeStroke(stroke, layout.balls[0].state.position.head<2>(), R);
  if (!cue)
  {
    ++unpredictable_rollouts;
    return false;
  }
  if (!bsp::cueClears(cue.value(), others, benchConfiguration().table, bsp::RobotLimits{}, R))
    return false;  // the cue touches a ball or passes through a rail: a foul, not a pot
  const auto outcome = bsp::predictShot(cue.value(), benchConfiguration(), others);
  if (!outcome)
  {
    ++unpredictable_rollouts;
    return false;
  }
  return isPot(outcome.value().table, shot.target, layout.pocket);
}

/// The shot's pot probability from `rollouts` noisy strokes of a generator seeded by the layout alone, so that both
/// planners' shots are played with the same noise.
double freshPotProbability(const ChosenShot& shot, const Layout& layout, int rollouts)
{
  if (shot.target.empty() || rollouts <= 0)
    return 0.0;
  const std::vector<bsp::TableBall> others(layout.balls.begin() + 1, layout.balls.end());
  std::mt19937 random(FRESH_SEED_OFFSET + layout.seed);
  int pots = 0;
  for (int k = 0; k < rollouts; ++k)
    pots += noisyRolloutPots(shot, layout, others, random);
  return static_cast<double>(pots) / rollouts;
}

LayoutResult measure(const Layout& layout, const Settings& settings)
{
  LayoutResult result;
  result.group = layout.group;
  result.seed = layout.seed;
  bsp::PlanRequest request = planRequest(layout, settings.threads);
  const auto start = std::chrono::steady_clock::now();
  request.hooks.progress = [&](const bsp::PlanProgress& progress)
  {
    if (progress.shots_that_pot > 0 && std::isnan(result.first_pot_seconds))
      result.first_pot_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const auto plan = bsp::planShot(request, benchConfiguration());
  if (!plan)
  {
    std::fprintf(stderr, "layout %u: %s\n", layout.seed, plan.error().describe().c_str());
    std::exit(1);
  }
  result.planner = {plan.value().found, plan.value().best.stroke, plan.value().best.target,
                    bsp::toString(plan.value().best.cue_ball_path)};
  result.planner_estimate = plan.value().best.success_probability;
  result.planner_estimate_rollouts = plan.value().best.rollouts;
  result.planning_seconds = plan.value().seconds;
  result.baseline = ghostBallShot(layout);
  result.planner_fresh = freshPotProbability(result.planner, layout, settings.fresh_rollouts);
  result.baseline_fresh = freshPotProbability(result.baseline, layout, settings.fresh_rollouts);
  return result;
}

double mean(const std::vector<double>& values)
{
  double sum = 0.0;
  for (double v : values)
    sum += v;
  return values.empty() ? NAN : sum / static_cast<double>(values.size());
}

/// Nearest-rank percentile.
double percentile(std::vector<double> values, double share)
{
  if (values.empty())
    return NAN;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(share * static_cast<double>(values.size())));
  return values[std::max<std::size_t>(rank, 1) - 1];
}

/// The value in printf's `format`, or "–" when it is not a number (a mean of nothing).
std::string formatted(const char* format, double value)
{
  if (std::isnan(value))
    return "–";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

double estimateError(const LayoutResult& r)
{
  return std::abs(r.planner_estimate - r.planner_fresh);
}

void printHeader()
{
  std::printf(
      "| group | layouts | planner found | baseline found | planner P(pot) | baseline P(pot) | planner − baseline "
      "(planner found) | first pot p50 s | plan p50 s | plan p95 s | mean \\|estimate − fresh\\| | largest "
      "\\|estimate − fresh\\| (seed) | estimate within ±0.05 | its rollouts p50 |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void printRow(const std::string& group, const std::vector<LayoutResult>& results)
{
  std::vector<double> planner, baseline, difference, seconds, errors, first_pot, estimate_rollouts;
  int planner_found = 0, baseline_found = 0;
  const LayoutResult* worst = nullptr;
  for (const LayoutResult& r : results)
  {
    planner.push_back(r.planner_fresh);
    baseline.push_back(r.baseline_fresh);
    seconds.push_back(r.planning_seconds);
    planner_found += r.planner.found;
    baseline_found += r.baseline.found;
    if (!r.planner.found)
      continue;
    difference.push_back(r.planner_fresh - r.baseline_fresh);
    errors.push_back(estimateError(r));
    estimate_rollouts.push_back(r.planner_estimate_rollouts);
    if (!std::isnan(r.first_pot_seconds))
      first_pot.push_back(r.first_pot_seconds);
    if (!worst || estimateError(r) > estimateError(*worst))
      worst = &r;
  }
  const double n = static_cast<double>(results.size());
  const std::string largest =
      worst ? formatted("%.3f", estimateError(*worst)) + " (" + std::to_string(worst->seed) + ")" : "–";
  const auto within = std::count_if(errors.begin(), errors.end(), [](double e) { return e <= 0.05; });
  const std::string within_share =
      errors.empty() ? "–" : formatted("%.0f %%", 100.0 * static_cast<double>(within) / errors.size());
  const std::string rollouts_p50 =
      estimate_rollouts.empty() ? "–" : formatted("%.0f", percentile(estimate_rollouts, 0.5));
  std::printf("| %s | %zu | %.0f %% | %.0f %% | %s | %s | %s (%zu) | %s | %s | %s | %s | %s | %s | %s |\n",
              group.c_str(), results.size(), 100.0 * planner_found / n, 100.0 * baseline_found / n,
              formatted("%.3f", mean(planner)).c_str(), formatted("%.3f", mean(baseline)).c_str(),
              formatted("%+.3f", mean(difference)).c_str(), difference.size(),
              first_pot.empty() ? "–" : formatted("%.3f", percentile(first_pot, 0.5)).c_str(),
              formatted("%.3f", percentile(seconds, 0.5)).c_str(), formatted("%.3f", percentile(seconds, 0.95)).c_str(),
              formatted("%.3f", mean(errors)).c_str(), largest.c_str(), within_share.c_str(), rollouts_p50.c_str());
}

/// Whether the planner's estimate and the fresh measurement differ by more than three standard deviations of their
/// difference (p(1 − p) at least 0.01, as the planner's test).
bool estimateDisagrees(const LayoutResult& r, int fresh_rollouts)
{
  if (!r.planner.found || r.planner_estimate_rollouts == 0)
    return false;
  const double p = 0.5 * (r.planner_estimate + r.planner_fresh);
  const double sigma =
      std::sqrt(std::max(p * (1.0 - p), 0.01) * (1.0 / fresh_rollouts + 1.0 / r.planner_estimate_rollouts));
  return estimateError(r) > 3.0 * sigma;
}

void printDisagreements(const std::vector<LayoutResult>& results, int fresh_rollouts)
{
  std::printf("\nLayouts whose planner estimate and fresh measurement differ by more than 3σ:\n");
  bool any = false;
  for (const LayoutResult& r : results)
    if (estimateDisagrees(r, fresh_rollouts))
    {
      std::printf("- seed %u (%s): estimate %.3f over %d rollouts, fresh %.3f over %d; baseline %.3f\n", r.seed,
                  r.group.c_str(), r.planner_estimate, r.planner_estimate_rollouts, r.planner_fresh, fresh_rollouts,
                  r.baseline_fresh);
      any = true;
    }
  if (!any)
    std::printf("- none\n");
}

/// The layouts where the baseline's shot pots more often than the planner's by more than BASELINE_WIN.
void printBaselineWins(const std::vector<LayoutResult>& results)
{
  constexpr double BASELINE_WIN = 0.1;
  std::printf("\nLayouts where the baseline's fresh pot probability exceeds the planner's by more than %.1f:\n",
              BASELINE_WIN);
  bool any = false;
  for (const LayoutResult& r : results)
    if (r.baseline_fresh > r.planner_fresh + BASELINE_WIN)
    {
      std::printf("- seed %u (%s): planner %.3f (found %d, target \"%s\"), baseline %.3f (clear %d, target \"%s\")\n",
                  r.seed, r.group.c_str(), r.planner_fresh, r.planner.found, r.planner.target.c_str(), r.baseline_fresh,
                  r.baseline.found, r.baseline.target.c_str());
      any = true;
    }
  if (!any)
    std::printf("- none\n");
}

/// The hand-made layouts one by one: the planner's kind of shot beside both fresh probabilities.
void printHandMade(const std::vector<LayoutResult>& results)
{
  std::printf("\nHand-made layouts (planner: kind, fresh P, its estimate; baseline: fresh P):\n");
  for (const LayoutResult& r : results)
    if (r.group == "blocked" || r.group == "detour")
      std::printf("- %s %u: %s %.3f (estimate %.3f); baseline %.3f\n", r.group.c_str(), r.seed, r.planner.path,
                  r.planner_fresh, r.planner_estimate, r.baseline_fresh);
}

void printTable(const std::vector<LayoutResult>& results, const Settings& settings)
{
  std::map<std::string, std::vector<LayoutResult>> groups;
  for (const LayoutResult& r : results)
    groups[r.group].push_back(r);
  printHeader();
  for (int count : OBJECT_BALL_COUNTS)
    if (groups.count(groupName(count)))
      printRow(groupName(count), groups[groupName(count)]);
  for (const char* group : {"blocked", "detour"})
    if (groups.count(group))
      printRow(group, groups[group]);
  printDisagreements(results, settings.fresh_rollouts);
  printBaselineWins(results);
  printHandMade(results);
}

void printShot(const char* name, const ChosenShot& shot, double fresh)
{
  std::printf("%s: found %d, target \"%s\", φ %.4f rad, θ %.4f rad, V %.3f m/s, a %.3f, b %.3f: fresh P %.3f\n", name,
              shot.found, shot.target.c_str(), shot.stroke.phi, shot.stroke.theta, shot.stroke.speed, shot.stroke.a,
              shot.stroke.b, fresh);
}

void printLayout(const Layout& layout, const LayoutResult& result)
{
  std::printf("layout %u (%s)\n", layout.seed, layout.group.c_str());
  for (const bsp::TableBall& ball : layout.balls)
    std::printf("  %s at (%.4f, %.4f)\n", ball.id.c_str(), ball.state.position.x(), ball.state.position.y());
  printShot("planner", result.planner, result.planner_fresh);
  std::printf("  its estimate %.3f over %d rollouts, %.3f s\n", result.planner_estimate,
              result.planner_estimate_rollouts, result.planning_seconds);
  printShot("baseline", result.baseline, result.baseline_fresh);
}

Settings parseSettings(int argc, char** argv)
{
  Settings settings;
  if (argc > 1)
    settings.random_layouts = std::atoi(argv[1]);
  if (argc > 2)
    settings.fresh_rollouts = std::atoi(argv[2]);
  if (argc > 3)
    settings.threads = std::atoi(argv[3]);
  if (argc > 4)
    settings.only_layout = std::atoi(argv[4]);
  return settings;
}

std::vector<Layout> allLayouts(const Settings& settings)
{
  std::vector<Layout> layouts;
  for (int k = 0; k < settings.random_layouts; ++k)
    layouts.push_back(randomLayout(static_cast<unsigned>(k)));
  for (Layout& layout : blockedLayouts(static_cast<unsigned>(settings.random_layouts)))
    layouts.push_back(std::move(layout));
  return layouts;
}
}  // namespace

int main(int argc, char** argv)
{
  const auto start = std::chrono::steady_clock::now();
  const Settings settings = parseSettings(argc, argv);
  const std::vector<Layout> layouts = allLayouts(settings);
  if (settings.only_layout >= 0)
  {
    const Layout& layout = layouts.at(static_cast<std::size_t>(settings.only_layout));
    printLayout(layout, measure(layout, settings));
    return 0;
  }
  std::vector<LayoutResult> results;
  for (const Layout& layout : layouts)
    results.push_back(measure(layout, settings));
  std::printf(
      "%d random layouts + 3 blocked + 4 detour, budget %.1f s, %d planner thread(s), %d fresh rollouts per shot\n\n",
      settings.random_layouts, PLAN_BUDGET, settings.threads, settings.fresh_rollouts);
  printTable(results, settings);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("\nFresh rollouts that could not be predicted (counted as misses): %d\n", unpredictable_rollouts);
  std::printf("Total run time: %.1f s\n", total);
  return 0;
}
