#pragma once

// A candidate's aim and speed refined until the target passes well inside its pocket.
#include "candidates.hpp"

namespace billiard_shot_planner
{
namespace planning
{
struct RefinedShot
{
  Candidate candidate;  ///< with the refined stroke
  StrokeEvaluation evaluation;
  int evaluations = 0;  ///< strokes played
};

/// Maximises the target's margin in its pocket over the cue's direction (within ±MAX_AIM_CORRECTION of the ghost
/// ball's: throw and squirt move the pot by a few degrees at most) and speed (within the limits) with NLopt's Sbplx,
/// a derivative-free simplex method on subspaces: the margin is a simulation's output, continuous but with kinks
/// where the ball's path changes its events. Stops at a margin of half the capture radius, after MAX_EVALUATIONS
/// strokes, or at `deadline`.
RefinedShot refine(const Candidate& candidate, const PlanContext& context, Clock::time_point deadline);

/// Half the capture radius of the candidate's pocket: a margin at which the refinement stops.
double goodMargin(const Candidate& candidate, const PlanContext& context);

constexpr double MAX_AIM_CORRECTION = 4.0 * M_PI / 180.0;
constexpr int MAX_EVALUATIONS = 40;

}  // namespace planning
}  // namespace billiard_shot_planner
