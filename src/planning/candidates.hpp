#pragma once

// Candidate shots: where to aim before any refinement.
#include <optional>
#include <string>
#include <vector>

#include "plan_context.hpp"

namespace billiard_shot_planner
{
namespace planning
{
struct Candidate
{
  std::string target;
  int pocket = -1;  ///< index into Table::pockets
  /// The first aim: at the ghost ball (at a frozen target, along the line of centres turned towards the route), the
  /// lowest elevation whose cue clears, a centre hit.
  Stroke stroke;
  double cut = 0.0;         ///< rad, between the cue ball's path and the target's (frozen: the route's turn)
  double difficulty = 0.0;  ///< smaller is easier: the paths' length over the cut's cosine (frozen: the route's)
  int bank_cushion = -1;    ///< the rail the target banks off (its index in PlanContext::rails); −1: straight in
  CueBallPath cue_ball_path = CueBallPath::Straight;
  Eigen::Vector2d ghost = Eigen::Vector2d::Zero();  ///< where the cue ball's centre meets the target
  Eigen::Vector2d line = Eigen::Vector2d::UnitX();  ///< the direction the target must leave in
  bool cue_path_blocked = false;                    ///< a ball stands on the cue ball's straight path to the ghost
  bool route_blocked = false;                       ///< a ball stands on the target's way to its pocket
};

/// Why the candidates are what they are (for the explanation of a plan that finds nothing).
struct CandidateSearch
{
  std::vector<Candidate> candidates;  ///< easiest first
  int pairs = 0;                      ///< target–pocket routes considered (straight in and off each cushion)
  int blocked = 0;                    ///< of them, with a ball in the way of the target or the cue ball (tried last)
  int too_thin = 0;                   ///< with a cut beyond MAX_CUT
  int frozen_off_line = 0;            ///< a target frozen to the cue ball, its route beyond FROZEN_MAX_TURN
  int cue_blocked = 0;                ///< where no elevation within the limits clears the cue
};

/// The thinnest cut tried: beyond it the object ball takes a sliver of the cue ball's speed and the throw's error
/// dominates.
constexpr double MAX_CUT = 80.0 * M_PI / 180.0;

/// The farthest a frozen target's way to its pocket may turn from the line of centres: the strike's throw turns the
/// target by a few degrees at most (docs/cue_strike.md, Frozen balls), and the refinement finds it.
constexpr double FROZEN_MAX_TURN = 8.0 * M_PI / 180.0;

/// Room the cue keeps from the balls and the rails in a planned stroke, so that noisy strokes rarely touch what the
/// nominal one clears (at the lowest elevation that clears without it, a quarter of the noisy strokes put the cue
/// into a rail): three standard deviations of the hit point's noise everywhere, and of the aim's and elevation's
/// noise times the distance from the tip (the cue turns about its tip).
ClearanceMargin clearanceMargin(const PlanContext& context);

/// The lowest elevation from `from` (at least the limits' minimum, in steps of 2°) whose cue clears the balls and the
/// rails with the clearance margin, if any within the limits.
std::optional<double> clearElevation(Stroke stroke, const PlanContext& context, double from);

/// Pots by the ghost ball (a target frozen to the cue ball: along the line of centres): for each target (the requested
/// one, or every object ball) and pocket (the requested one, or every pocket), straight in and off each cushion (by the
/// pocket's mirror image; banks after the direct pots of similar lengths); those whose straight paths — cue ball to
/// ghost ball, the target's legs — pass within 2R of another ball come last.
CandidateSearch candidateShots(const PlanContext& context);

}  // namespace planning
}  // namespace billiard_shot_planner
