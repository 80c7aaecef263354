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
// threads = 1] [one layout index: plan only that one and print both shots].
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

#include "billiard_shot_planner/planning/shot_planner.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
const bsp::ShotConfiguration CONFIGURATION;
const double R = CONFIGURATION.ball_radius;
const double HALF_LENGTH = 0.5 * CONFIGURATION.table.length, HALF_WIDTH = 0.5 * CONFIGURATION.table.width;
const double CUSHION_CLEARANCE = 2.0 * R + 0.01;  ///< m from a ball's centre to the cushion nose lines
const double BALL_SPACING = 2.0 * R + 0.001;      ///< m between the centres of two balls
const double POCKET_CLEARANCE = 0.05;             ///< m outside a pocket's capture circle
const double PLAN_BUDGET = 0.5;                   ///< s
const double BASELINE_SPEED = 2.0;                ///< m/s of the cue
const int OBJECT_BALL_COUNTS[] = {1, 3, 7, 15};
const unsigned FRESH_SEED_OFFSET = 7919u;  ///< of the fresh rollouts' generator: another stream than the planner's
constexpr int CORNER_PX_PY = 3, CORNER_MX_MY = 0, CORNER_MX_PY = 2;

struct Layout
{
  std::string group;
  unsigned seed = 0;
  std::vector<bsp::TableBall> balls;  ///< the cue ball first
  std::string target;                 ///< empty: any object ball
  int pocket = -1;                    ///< −1: any
};

/// A shot to measure: nothing to play when `target` is empty.
struct ChosenShot
{
  bool found = false;
  bsp::Stroke stroke;
  std::string target;
  const char* path = "straight";  ///< how the cue ball reaches the target (the planner's CueBallPath)
};

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

bsp::TableBall ballAt(const std::string& id, const Eigen::Vector2d& at)
{
  bsp::BallState state;
  state.position = {at.x(), at.y(), R};
  return {id, state};
}

std::string objectBallId(int k)
{
  return std::to_string(k);
}

bool farFromPockets(const Eigen::Vector2d& at)
{
  for (const bsp::Pocket& pocket : CONFIGURATION.table.pockets)
    if ((at - pocket.centre).norm() < pocket.radius + POCKET_CLEARANCE)
      return false;
  return true;
}

bool farFromBalls(const Eigen::Vector2d& at, const std::vector<bsp::TableBall>& balls)
{
  for (const bsp::TableBall& ball : balls)
    if ((at - ball.state.position.head<2>()).norm() < BALL_SPACING)
      return false;
  return true;
}

/// A place on the cloth, uniform among those clear of the cushions, the pockets and the balls already placed.
Eigen::Vector2d freePlace(const std::vector<bsp::TableBall>& balls, std::mt19937& random)
{
  std::uniform_real_distribution<double> x(-HALF_LENGTH + CUSHION_CLEARANCE, HALF_LENGTH - CUSHION_CLEARANCE);
  std::uniform_real_distribution<double> y(-HALF_WIDTH + CUSHION_CLEARANCE, HALF_WIDTH - CUSHION_CLEARANCE);
  for (;;)
  {
    const Eigen::Vector2d at(x(random), y(random));
    if (farFromPockets(at) && farFromBalls(at, balls))
      return at;
  }
}

std::string groupName(int object_balls)
{
  return std::to_string(object_balls) + (object_balls == 1 ? " ball" : " balls");
}

Layout randomLayout(unsigned index)
{
  const int object_balls = OBJECT_BALL_COUNTS[index % 4];
  Layout layout{groupName(object_balls), index, {}, "", -1};
  std::mt19937 random(index);
  layout.balls.push_back(ballAt(bsp::CUE_BALL_ID, freePlace(layout.balls, random)));
  for (int k = 1; k <= object_balls; ++k)
    layout.balls.push_back(ballAt(objectBallId(k), freePlace(layout.balls, random)));
  return layout;
}

Eigen::Vector2d rotated(const Eigen::Vector2d& v, double angle)
{
  return {std::cos(angle) * v.x() - std::sin(angle) * v.y(), std::sin(angle) * v.x() + std::cos(angle) * v.y()};
}

/// Ball "1" `distance` m from corner pocket `corner` towards the table's centre, the cue ball `behind` m from its
/// ghost ball at `cut_deg` to the pot's line, and ball "2" on the line from the cue ball to the ghost ball, at
/// `blocker_share` of the way, `side` ball radii to the left of it.
Layout blockedLayout(unsigned index, int corner, double distance, double cut_deg, double behind, double blocker_share,
                     double side = 0.0, const char* group = "blocked")
{
  const Eigen::Vector2d pocket = CONFIGURATION.table.pockets[static_cast<std::size_t>(corner)].centre;
  const Eigen::Vector2d line = -pocket.normalized();
  const Eigen::Vector2d object = pocket + distance * line;
  const Eigen::Vector2d ghost = object + 2.0 * R * line;
  const Eigen::Vector2d cue = ghost + behind * rotated(line, cut_deg * M_PI / 180.0);
  const Eigen::Vector2d along = (ghost - cue).normalized();
  const Eigen::Vector2d blocker =
      cue + blocker_share * (ghost - cue) + side * R * Eigen::Vector2d(-along.y(), along.x());
  return {group, index, {ballAt(bsp::CUE_BALL_ID, cue), ballAt("1", object), ballAt("2", blocker)}, "1", corner};
}

std::vector<Layout> blockedLayouts(unsigned first_index)
{
  return {blockedLayout(first_index, CORNER_PX_PY, 0.3, 20.0, 0.8, 0.5),
          blockedLayout(first_index + 1, CORNER_MX_MY, 0.25, 35.0, 1.0, 0.3),
          blockedLayout(first_index + 2, CORNER_MX_PY, 0.4, 0.0, 0.6, 0.7),
          blockedLayout(first_index + 3, CORNER_PX_PY, 0.15, 10.0, 0.8, 0.45, 0.3, "detour"),
          blockedLayout(first_index + 4, CORNER_PX_PY, 0.2, 30.0, 0.7, 0.4, 0.5, "detour"),
          blockedLayout(first_index + 5, CORNER_MX_MY, 0.25, -15.0, 0.9, 0.5, -0.4, "detour"),
          blockedLayout(first_index + 6, CORNER_MX_PY, 0.2, 20.0, 0.6, 0.35, 0.6, "detour")};
}

double distanceToSegment(const Eigen::Vector2d& point, const Eigen::Vector2d& from, const Eigen::Vector2d& to)
{
  const Eigen::Vector2d along = to - from;
  const double length2 = along.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((point - from).dot(along) / length2, 0.0, 1.0) : 0.0;
  return (from + s * along - point).norm();
}

/// Whether a ball moving from `from` to `to` passes 2R from every object ball but `target`.
bool pathIsClear(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Layout& layout, std::size_t target)
{
  for (std::size_t k = 1; k < layout.balls.size(); ++k)
    if (k != target && distanceToSegment(layout.balls[k].state.position.head<2>(), from, to) < 2.0 * R)
      return false;
  return true;
}

struct GhostBallCandidate
{
  bool clear = false;
  double cut = INFINITY;
  std::size_t target = 0;
  Eigen::Vector2d aim = Eigen::Vector2d::Zero();  ///< from the cue ball to the ghost ball
};

GhostBallCandidate ghostBallCandidate(const Layout& layout, std::size_t target, int pocket)
{
  const Eigen::Vector2d cue = layout.balls[0].state.position.head<2>();
  const Eigen::Vector2d object = layout.balls[target].state.position.head<2>();
  const Eigen::Vector2d hole = CONFIGURATION.table.pockets[static_cast<std::size_t>(pocket)].centre;
  const Eigen::Vector2d line = (hole - object).normalized();
  const Eigen::Vector2d ghost = object - 2.0 * R * line;
  GhostBallCandidate candidate;
  candidate.target = target;
  candidate.aim = ghost - cue;
  candidate.cut = std::acos(std::clamp(candidate.aim.normalized().dot(line), -1.0, 1.0));
  candidate.clear = pathIsClear(cue, ghost, layout, target) && pathIsClear(object, hole, layout, target);
  return candidate;
}

std::vector<bsp::TableBall> objectBalls(const Layout& layout)
{
  return {layout.balls.begin() + 1, layout.balls.end()};
}

/// The lowest elevation in steps of 2° (the planner's) whose cue clears the balls and the rails; level when none
/// does.
double lowestClearElevation(bsp::Stroke stroke, const Layout& layout)
{
  const bsp::RobotLimits limits;
  for (double theta = limits.min_theta; theta <= limits.max_theta + 1e-12; theta += 2.0 * M_PI / 180.0)
  {
    stroke.theta = theta;
    const auto cue = bsp::placeStroke(stroke, layout.balls[0].state.position.head<2>(), R);
    if (cue && bsp::cueClears(cue.value(), objectBalls(layout), CONFIGURATION.table, limits, R))
      return theta;
  }
  return 0.0;
}

bool better(const GhostBallCandidate& a, const GhostBallCandidate& b)
{
  return a.clear != b.clear ? a.clear : a.cut < b.cut;
}

/// The baseline: the ghost ball of the target–pocket pair with the smallest cut among the clear ones (none clear:
/// among all), a centre hit with a level cue at BASELINE_SPEED.
ChosenShot ghostBallShot(const Layout& layout)
{
  GhostBallCandidate best;
  for (std::size_t target = 1; target < layout.balls.size(); ++target)
  {
    if (!layout.target.empty() && layout.balls[target].id != layout.target)
      continue;
    for (int pocket = 0; pocket < static_cast<int>(CONFIGURATION.table.pockets.size()); ++pocket)
      if (layout.pocket < 0 || pocket == layout.pocket)
      {
        const GhostBallCandidate candidate = ghostBallCandidate(layout, target, pocket);
        if (better(candidate, best))
          best = candidate;
      }
  }
  ChosenShot shot;
  shot.found = best.clear;
  shot.target = layout.balls[best.target].id;
  shot.stroke.phi = std::atan2(best.aim.y(), best.aim.x());
  shot.stroke.speed = BASELINE_SPEED;
  shot.stroke.theta = lowestClearElevation(shot.stroke, layout);
  return shot;
}

bsp::PlanRequest planRequest(const Layout& layout, int threads)
{
  bsp::PlanRequest request;
  request.balls = layout.balls;
  request.target = layout.target;
  request.pocket = layout.pocket;
  request.budget = PLAN_BUDGET;
  request.seed = layout.seed;
  request.threads = threads;
  return request;
}

/// Whether `target` dropped (in `pocket`, unless −1) and the cue ball did not.
bool isPot(const bsp::TableTrajectory& run, const std::string& target, int pocket)
{
  // The cue ball must come to rest on the table: dropped, off the table (a jump that flies over a rail) or still
  // moving at the time limit is no pot, as the planner counts it.
  const bsp::MotionOutcome cue_ball = run.balls[0].outcome;
  if (cue_ball != bsp::MotionOutcome::Rest && cue_ball != bsp::MotionOutcome::AgainstCushion)
    return false;
  for (std::size_t k = 1; k < run.ids.size(); ++k)
    if (run.ids[k] == target)
      for (const bsp::MotionEvent& event : run.balls[k].events)
        if (event.type == bsp::MotionEventType::Pocketed)
          return pocket < 0 || event.pocket == pocket;
  return false;
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
  if (!bsp::cueClears(cue.value(), others, CONFIGURATION.table, bsp::RobotLimits{}, R))
    return false;  // the cue touches a ball or passes through a rail: a foul, not a pot
  const auto outcome = bsp::predictShot(cue.value(), CONFIGURATION, others);
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
  const auto plan = bsp::planShot(request, CONFIGURATION);
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
