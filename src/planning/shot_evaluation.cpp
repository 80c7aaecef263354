// One stroke played without noise and judged against the request's pot.
#include <algorithm>
#include <cmath>

#include "plan_context.hpp"

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
/// Spacing of the samples on which a missing ball's closest approach to a pocket is measured: a ball at 3 m/s moves
/// 1.5 cm between them, and the margin only has to rank near misses.
constexpr double APPROACH_SAMPLE_SPACING = 0.005;

/// Spacing of the samples on which a ball's clearance from a pocket's jaws is measured: 2 mm of travel at 2 m/s, so
/// that the margin the refinement climbs is smooth to a fraction of a millimetre.
constexpr double JAW_SAMPLE_SPACING = 0.001;

int indexOf(const TableTrajectory& run, const std::string& id)
{
  const auto found = std::find(run.ids.begin(), run.ids.end(), id);
  return found == run.ids.end() ? -1 : static_cast<int>(found - run.ids.begin());
}

const MotionEvent* pocketedEvent(const BallTrajectory& path)
{
  for (const MotionEvent& event : path.events)
    if (event.type == MotionEventType::Pocketed)
      return &event;
  return nullptr;
}

/// How far the ball's path keeps from the pocket's jaws (PocketTarget::jaws) until it crosses the mouth: for a ball
/// that drops there, its closest approach to a jaw's facing or point less the cushion's reach (0 where it touches
/// one) up to the mouth's line, at most the mouth's half-width; otherwise (≤ 0) less its closest approach to the
/// mouth's middle, so that a search among misses, a rattle out of the jaws among them, still has a slope to climb. The
/// clearance at the mouth, not the distance from its middle, is what noise eats: a shot along a rail into a corner
/// clears the near jaw best on a line deeper than the mouth's middle. Beyond the mouth the facings close in and a ball
/// that glances off one mostly drops (docs/tables.md, effective targets), so they do not count there.
double mouthMargin(const BallTrajectory& path, const PocketTarget& pocket)
{
  const MotionEvent* dropped = pocketedEvent(path);
  double clearance = INFINITY, closest = INFINITY;
  for (const TrajectorySample& sample : path.sample(JAW_SAMPLE_SPACING))
  {
    if (dropped && sample.time > dropped->time)
      break;
    const Eigen::Vector2d centre = sample.state.position.head<2>();
    closest = std::min(closest, (centre - pocket.centre).norm());
    for (const NoseSegment& jaw : pocket.jaws)
      clearance = std::min(clearance, (centre - jaw.closestPoint(centre)).norm() - pocket.reach);
    if ((centre - pocket.centre).dot(pocket.axis) > 0.0)
      break;  // past the mouth's line
  }
  if (dropped && dropped->pocket == pocket.id)
    return std::min(clearance, pocket.radius);
  return -closest;
}

/// How far inside the pocket's capture circle the ball's path passes (on the capture circles' table; under the jaws
/// mouthMargin): for a ball that drops there, the capture radius less the distance from the pocket's centre to the
/// line it enters along; otherwise (≤ 0) the capture radius less its closest approach.
double pocketMargin(const BallTrajectory& path, const PocketTarget& pocket)
{
  if (!pocket.jaws.empty())
    return mouthMargin(path, pocket);
  const MotionEvent* dropped = pocketedEvent(path);
  if (dropped && dropped->pocket == pocket.id)
  {
    const Eigen::Vector2d to_centre = pocket.centre - dropped->state.position.head<2>();
    const Eigen::Vector2d velocity = dropped->state.velocity.head<2>();
    if (velocity.norm() == 0.0)
      return pocket.radius - to_centre.norm();
    const Eigen::Vector2d along = velocity.normalized();
    return pocket.radius - std::abs(along.x() * to_centre.y() - along.y() * to_centre.x());
  }
  double closest = INFINITY;
  for (const TrajectorySample& sample : path.sample(APPROACH_SAMPLE_SPACING))
    closest = std::min(closest, (sample.state.position.head<2>() - pocket.centre).norm());
  return pocket.radius - closest;
}

/// Whether the ball dropped, into the pocket with id `pocket` when it names one.
bool dropsIn(const BallTrajectory& path, const std::string& pocket)
{
  const MotionEvent* dropped = pocketedEvent(path);
  return dropped && (pocket.empty() || dropped->pocket == pocket);
}

/// The request's pot, on a predicted table (the cue ball is ball 0).
bool isPot(const TableTrajectory& run, int target, const PlanContext& context)
{
  const PlanRequest& request = context.request;
  const BallTrajectory& cue_ball = run.balls[0];
  if (target < 0 || !dropsIn(run.balls[static_cast<std::size_t>(target)], request.pocket))
    return false;
  if (cue_ball.outcome != MotionOutcome::Rest && cue_ball.outcome != MotionOutcome::AgainstCushion)
    return false;  // dropped, off the table or unfinished
  if (request.rules.target_first && firstContact(run, 0) != run.ids[static_cast<std::size_t>(target)])
    return false;
  if (request.rules.only_target)
    for (std::size_t i = 1; i < run.balls.size(); ++i)
      if (static_cast<int>(i) != target && run.balls[i].outcome == MotionOutcome::Pocketed)
        return false;
  if (request.cue_region)
    return (cue_ball.finalState().position.head<2>() - request.cue_region->centre).norm() <= request.cue_region->radius;
  return true;
}
}  // namespace

StrokeEvaluation evaluateStroke(const Stroke& stroke, const std::string& target, int pocket, const PlanContext& context)
{
  StrokeEvaluation evaluation;
  evaluation.margin = UNPLAYABLE_MARGIN;
  auto cue = placeStroke(stroke, context.cue_ball, context.radius());
  if (!cue || !cueClears(cue.value(), context))
    return evaluation;
  auto outcome = predictShot(cue.value(), context.configuration, context.others);
  if (!outcome)
    return evaluation;
  const TableTrajectory& run = outcome.value().table;
  const int target_index = indexOf(run, target);
  if (target_index < 0)
    return evaluation;
  evaluation.valid = true;
  evaluation.pots = isPot(run, target_index, context);
  evaluation.target_end = run.balls[static_cast<std::size_t>(target_index)].finalState().position.head<2>();
  const PocketTarget& aimed = context.pockets[static_cast<std::size_t>(pocket)];
  evaluation.margin = pocketMargin(run.balls[static_cast<std::size_t>(target_index)], aimed);
  if (run.balls[0].outcome == MotionOutcome::Pocketed || run.balls[0].outcome == MotionOutcome::OffTable)
    evaluation.margin = std::min(evaluation.margin, -aimed.radius);
  return evaluation;
}

}  // namespace planning
}  // namespace billiard_shot_planner
