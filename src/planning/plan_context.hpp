#pragma once

// What every part of the planner shares: the request, the configuration its rollouts run with, where the cue ball
// is and the other balls, and how one stroke is judged.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "billiard_shot_planner/motion/table_outline.hpp"
#include "billiard_shot_planner/planning/shot_planner.hpp"
#include "rail_lines.hpp"

namespace billiard_shot_planner
{
namespace planning
{
using Clock = std::chrono::steady_clock;

/// A pocket as the planner aims at it and measures a shot's margin in. On the capture circles' table
/// (PocketModel::Circles) the capture circle, sitting at its centre. Under the jaws the mouth: its middle, as radius
/// the most a ball's centre may pass that middle by and still clear both jaw points (half the mouth less the cushion's
/// reach), its jaws' segments (facings and points), and sitting where the pocket's axis meets the rails' rectangle
/// (the corner, or the rail's middle).
struct PocketTarget
{
  std::string id;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
  Eigen::Vector2d place = Eigen::Vector2d::Zero();
  std::vector<NoseSegment> jaws;                   ///< empty on the capture circles' table
  double reach = 0.0;                              ///< m, the cushion's reach (cushionReach) for the planner's balls
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();  ///< unit, from the mouth's middle into the pocket
};

/// The pockets of `table`'s pocket model, as the planner aims at them. Errors: tableOutline's (under the jaws).
Expected<std::vector<PocketTarget>> pocketTargets(const Table& table, double ball_radius);

/// The index in `pockets` of the pocket with `id`, or −1.
int indexOf(const std::vector<PocketTarget>& pockets, const std::string& id);

struct PlanContext
{
  const PlanRequest& request;
  ShotConfiguration configuration;  ///< with the planning tolerance
  Eigen::Vector2d cue_ball;         ///< its centre on the cloth
  std::vector<TableBall> others;    ///< every ball but the cue ball, in the request's order
  Clock::time_point deadline;
  std::vector<PocketTarget> pockets;  ///< pocketTargets of the table; candidates index them
  std::array<RailLine, 4> rails;      ///< railLines of the table; a bank's candidate indexes them
  /// The cue ball touches a ball or a cushion: its strike moves them too (strikeBall), so no search may stand on the
  /// lone ball's strike.
  bool cue_ball_touches = false;

  double radius() const { return configuration.ball_radius; }
  /// Past `until` (by default the deadline), or asked to stop by the caller.
  bool shouldStop(Clock::time_point until) const
  {
    return Clock::now() >= until || (request.hooks.stop && request.hooks.stop());
  }
  bool pastDeadline() const { return shouldStop(deadline); }
};

/// Builds the context of a validated request.
PlanContext makeContext(const PlanRequest& request, const ShotConfiguration& configuration);

/// How one stroke aimed at `target` in `pocket` turned out.
struct StrokeEvaluation
{
  bool valid = false;   ///< the stroke could be played and predicted
  bool pots = false;    ///< the request's pot (target dropped, cue ball not, region and rules)
  double margin = 0.0;  ///< m: inside (> 0) or outside (< 0) `pocket`'s capture circle by how much the target passes
  Eigen::Vector2d target_end = Eigen::Vector2d::Zero();  ///< where the target stopped or dropped
};

/// Whether `a` is the better outcome: it pots and `b` does not, or both do (or neither) and it passes deeper.
inline bool isBetter(const StrokeEvaluation& a, const StrokeEvaluation& b)
{
  return a.pots != b.pots ? a.pots : a.margin > b.margin;
}

/// A margin no real shot reaches: strokes that cannot be played or predicted.
constexpr double UNPLAYABLE_MARGIN = -10.0;

/// Plays `stroke` (no noise) and judges it: the pot is the request's; the margin is measured in `pocket` (0 when it
/// names no pocket). A stroke whose cue would touch a ball or a rail, or that cannot be played, is not valid and has
/// UNPLAYABLE_MARGIN.
StrokeEvaluation evaluateStroke(const Stroke& stroke, const std::string& target, int pocket,
                                const PlanContext& context);

/// Room the cue keeps from the balls and the rails: `offset` everywhere and `per_metre` for each metre from its tip.
struct ClearanceMargin
{
  double offset = 0.0;     ///< m
  double per_metre = 0.0;  ///< m per m (rad)

  /// The room at `along` metres behind the tip.
  double at(double along) const { return offset + per_metre * along; }
};

/// Whether the cue, placed for the stroke, keeps clear of every other ball and passes above the rails, by `margin`.
bool cueClears(const CuePlacement& cue, const PlanContext& context, const ClearanceMargin& margin = {});

}  // namespace planning
}  // namespace billiard_shot_planner
