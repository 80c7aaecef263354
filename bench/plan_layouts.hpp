// The layouts of the plan benchmark (bench/plan_benchmark.cpp) and its ghost-ball baseline shot, shared with the
// rollout benchmark (bench/rollout_benchmark.cpp): seeded random tables with 1, 3, 7 and 15 object balls, and
// hand-made layouts whose only pot is blocked or needs a detour.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "billiard_shot_planner/planning/shot_planner.hpp"

namespace plan_layouts
{
namespace bsp = billiard_shot_planner;

const bsp::ShotConfiguration CONFIGURATION;
const double R = CONFIGURATION.ball_radius;
const double HALF_LENGTH = 0.5 * CONFIGURATION.table.length, HALF_WIDTH = 0.5 * CONFIGURATION.table.width;
const double CUSHION_CLEARANCE = 2.0 * R + 0.01;  ///< m from a ball's centre to the cushion nose lines
const double BALL_SPACING = 2.0 * R + 0.001;      ///< m between the centres of two balls
const double POCKET_CLEARANCE = 0.05;             ///< m outside a pocket's capture circle
const double BASELINE_SPEED = 2.0;                ///< m/s of the cue
const int OBJECT_BALL_COUNTS[] = {1, 3, 7, 15};
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

inline bsp::TableBall ballAt(const std::string& id, const Eigen::Vector2d& at)
{
  bsp::BallState state;
  state.position = {at.x(), at.y(), R};
  return {id, state};
}

inline std::string objectBallId(int k)
{
  return std::to_string(k);
}

inline bool farFromPockets(const Eigen::Vector2d& at)
{
  for (const bsp::Pocket& pocket : CONFIGURATION.table.pockets)
    if ((at - pocket.centre).norm() < pocket.radius + POCKET_CLEARANCE)
      return false;
  return true;
}

inline bool farFromBalls(const Eigen::Vector2d& at, const std::vector<bsp::TableBall>& balls)
{
  for (const bsp::TableBall& ball : balls)
    if ((at - ball.state.position.head<2>()).norm() < BALL_SPACING)
      return false;
  return true;
}

/// A place on the cloth, uniform among those clear of the cushions, the pockets and the balls already placed.
inline Eigen::Vector2d freePlace(const std::vector<bsp::TableBall>& balls, std::mt19937& random)
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

inline std::string groupName(int object_balls)
{
  return std::to_string(object_balls) + (object_balls == 1 ? " ball" : " balls");
}

inline Layout randomLayout(unsigned index)
{
  const int object_balls = OBJECT_BALL_COUNTS[index % 4];
  Layout layout{groupName(object_balls), index, {}, "", -1};
  std::mt19937 random(index);
  layout.balls.push_back(ballAt(bsp::CUE_BALL_ID, freePlace(layout.balls, random)));
  for (int k = 1; k <= object_balls; ++k)
    layout.balls.push_back(ballAt(objectBallId(k), freePlace(layout.balls, random)));
  return layout;
}

inline Eigen::Vector2d rotated(const Eigen::Vector2d& v, double angle)
{
  return {std::cos(angle) * v.x() - std::sin(angle) * v.y(), std::sin(angle) * v.x() + std::cos(angle) * v.y()};
}

/// Ball "1" `distance` m from corner pocket `corner` towards the table's centre, the cue ball `behind` m from its
/// ghost ball at `cut_deg` to the pot's line, and ball "2" on the line from the cue ball to the ghost ball, at
/// `blocker_share` of the way, `side` ball radii to the left of it.
inline Layout blockedLayout(unsigned index, int corner, double distance, double cut_deg, double behind,
                            double blocker_share, double side = 0.0, const char* group = "blocked")
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

inline std::vector<Layout> blockedLayouts(unsigned first_index)
{
  return {blockedLayout(first_index, CORNER_PX_PY, 0.3, 20.0, 0.8, 0.5),
          blockedLayout(first_index + 1, CORNER_MX_MY, 0.25, 35.0, 1.0, 0.3),
          blockedLayout(first_index + 2, CORNER_MX_PY, 0.4, 0.0, 0.6, 0.7),
          blockedLayout(first_index + 3, CORNER_PX_PY, 0.15, 10.0, 0.8, 0.45, 0.3, "detour"),
          blockedLayout(first_index + 4, CORNER_PX_PY, 0.2, 30.0, 0.7, 0.4, 0.5, "detour"),
          blockedLayout(first_index + 5, CORNER_MX_MY, 0.25, -15.0, 0.9, 0.5, -0.4, "detour"),
          blockedLayout(first_index + 6, CORNER_MX_PY, 0.2, 20.0, 0.6, 0.35, 0.6, "detour")};
}

inline double distanceToSegment(const Eigen::Vector2d& point, const Eigen::Vector2d& from, const Eigen::Vector2d& to)
{
  const Eigen::Vector2d along = to - from;
  const double length2 = along.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((point - from).dot(along) / length2, 0.0, 1.0) : 0.0;
  return (from + s * along - point).norm();
}

/// Whether a ball moving from `from` to `to` passes 2R from every object ball but `target`.
inline bool pathIsClear(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Layout& layout,
                        std::size_t target)
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

inline GhostBallCandidate ghostBallCandidate(const Layout& layout, std::size_t target, int pocket)
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

inline std::vector<bsp::TableBall> objectBalls(const Layout& layout)
{
  return {layout.balls.begin() + 1, layout.balls.end()};
}

/// The lowest elevation in steps of 2° (the planner's) whose cue clears the balls and the rails; level when none
/// does.
inline double lowestClearElevation(bsp::Stroke stroke, const Layout& layout)
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

inline bool better(const GhostBallCandidate& a, const GhostBallCandidate& b)
{
  return a.clear != b.clear ? a.clear : a.cut < b.cut;
}

/// The baseline: the ghost ball of the target–pocket pair with the smallest cut among the clear ones (none clear:
/// among all), a centre hit with a level cue at BASELINE_SPEED.
inline ChosenShot ghostBallShot(const Layout& layout)
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

/// Whether `target` dropped (in `pocket`, unless −1) and the cue ball did not.
inline bool isPot(const bsp::TableTrajectory& run, const std::string& target, int pocket)
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

}  // namespace plan_layouts
