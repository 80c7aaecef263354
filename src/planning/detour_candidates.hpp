#pragma once

// Candidates whose cue ball goes around a ball standing on its straight path: off a cushion, curving, or over it.
#include <vector>

#include "candidates.hpp"

namespace billiard_shot_planner
{
namespace planning
{
struct DetourSearch
{
  std::vector<Candidate> candidates;  ///< the widest clearance first
  int evaluations = 0;                ///< cue-ball paths simulated
};

/// Strokes for a candidate whose cue ball cannot reach the ghost ball straight: a kick off each cushion (aimed at the
/// ghost ball's mirror image, a centre hit), a massé (the cue raised, hit off the centre on either side) and a jump
/// (the cue raised as far as the limits allow, hit above the centre). The cue ball's path is simulated alone on the
/// table, so that the cushions' and the cloth's effects on a spinning or flying ball are the model's own; each
/// stroke's direction is the root, found by Boost's TOMS 748, of the angle between the direction the target would
/// leave in and the candidate's line. Kept: the roots whose path passes every other ball by more than 2R before it
/// meets the target, the best of each kind. Ends early at `until`; none for a cue ball that touches a ball or a cushion
/// (its strike moves them too, which the lone ball's paths do not know).
DetourSearch detourCandidates(const Candidate& blocked, const PlanContext& context, Clock::time_point until);

}  // namespace planning
}  // namespace billiard_shot_planner
