#include "billiard_shot_planner/planning/shot_planner.hpp"

#include <algorithm>
#include <optional>
#include <thread>
#include <utility>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/motion/table_strike.hpp"
#include "candidates.hpp"
#include "detour_candidates.hpp"
#include "noisy_rollouts.hpp"
#include "refinement.hpp"

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
/// Shares of the budget: the refinement of candidates ends at the first, the ranking of the shots that pot by their
/// rollouts at the second; the rest confirms the chosen shot's probability with rollouts of its own.
constexpr double REFINEMENT_SHARE = 0.5;
constexpr double RANKING_SHARE = 0.7;
/// When the leader's confirmation has had the time to this share, a runner-up that may be better is confirmed too.
constexpr double CONFIRMATION_HALFWAY = 0.85;
/// Seeds of the confirming rollouts: another stream than the ranking's.
constexpr unsigned CONFIRMATION_SEED_OFFSET = 1000003u;
/// The chosen shot's probability is confirmed with up to this many times the request's rollouts, as far as the
/// budget goes: 200 rollouts put the estimate within ±0.07 at 95 % near p = 0.5, 800 within ±0.035.
constexpr int CONFIRMATION_FACTOR = 4;
/// How many shots that pot are ranked by rollouts, and how many rollouts each gets per round.
constexpr std::size_t RANKED_SHOTS = 4;
constexpr int ROLLOUT_BATCH = 25;

int threadCount(const PlanRequest& request)
{
  if (request.threads > 0)
    return request.threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

Clock::time_point after(Clock::time_point start, double seconds)
{
  return start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

void report(const PlanContext& context, const PlanProgress& progress)
{
  if (context.request.hooks.progress)
    context.request.hooks.progress(progress);
}

/// Whether RANKED_SHOTS refined shots pot with half a capture radius to spare: the rollouts rank no more, so the
/// time is better spent on them.
bool enoughGoodShots(const std::vector<RefinedShot>& refined, const PlanContext& context)
{
  const auto good =
      std::count_if(refined.begin(), refined.end(),
                    [&](const RefinedShot& shot)
                    { return shot.evaluation.pots && shot.evaluation.margin >= goodMargin(shot.candidate, context); });
  return static_cast<std::size_t>(good) >= RANKED_SHOTS;
}

/// Refines candidates, easiest first, while the refinement's share of the budget lasts (the first always). A
/// candidate whose cue ball's straight path is blocked is refined as it is (a kiss or a combination may pot it) and
/// by its detours: a kick, a massé, a jump (the rollouts then rank them).
std::vector<RefinedShot> refineCandidates(const CandidateSearch& search, const PlanContext& context,
                                          Clock::time_point start, int& evaluations)
{
  const Clock::time_point until = after(start, REFINEMENT_SHARE * context.request.budget);
  std::vector<RefinedShot> refined;
  int pots = 0;
  auto refine_one = [&](const Candidate& candidate)
  {
    refined.push_back(refine(candidate, context, refined.empty() ? context.deadline : until));
    evaluations += refined.back().evaluations;
    pots += refined.back().evaluation.pots;
    report(context, {evaluations, pots, 0.0});
  };
  for (const Candidate& candidate : search.candidates)
  {
    if (!refined.empty() && (context.shouldStop(until) || enoughGoodShots(refined, context)))
      break;
    refine_one(candidate);
    if (!candidate.cue_path_blocked || candidate.route_blocked)
      continue;
    const DetourSearch detours = detourCandidates(candidate, context, until);
    evaluations += detours.evaluations;
    for (const Candidate& detour : detours.candidates)
      if (!context.shouldStop(until))
        refine_one(detour);
  }
  std::stable_sort(refined.begin(), refined.end(),
                   [](const RefinedShot& a, const RefinedShot& b) { return isBetter(a.evaluation, b.evaluation); });
  return refined;
}

PlannedShot plannedShot(const RefinedShot& shot, const PlanContext& context)
{
  PlannedShot planned;
  planned.stroke = shot.candidate.stroke;
  planned.cue = placeStroke(planned.stroke, context.cue_ball, context.radius()).value();
  planned.target = shot.candidate.target;
  planned.pocket = context.pockets[static_cast<std::size_t>(shot.candidate.pocket)].id;
  if (shot.candidate.bank_cushion >= 0)
    planned.bank_cushion = context.rails[static_cast<std::size_t>(shot.candidate.bank_cushion)].id;
  planned.cue_ball_path = shot.candidate.cue_ball_path;
  planned.margin = shot.evaluation.margin;
  return planned;
}

void setEstimate(PlannedShot& shot, const NoisyRollouts& rollouts)
{
  const PotEstimate& estimate = rollouts.estimate();
  shot.success_probability = estimate.probability();
  shot.confidence_low = estimate.low();
  shot.confidence_high = estimate.high();
  shot.rollouts = estimate.trials;
  shot.target_end_points = rollouts.targetEndPoints();
}

/// Rollouts of the shots that pot, in rounds, until each has the request's count or `until`; then the shots in order
/// of their estimated probability (the margin breaks ties).
std::vector<PlannedShot> rankByRollouts(const std::vector<RefinedShot>& refined, const PlanContext& context,
                                        Clock::time_point until, int& evaluations)
{
  std::vector<PlannedShot> shots;
  std::vector<NoisyRollouts> rollouts;
  for (std::size_t k = 0; k < refined.size() && shots.size() < RANKED_SHOTS && refined[k].evaluation.pots; ++k)
  {
    shots.push_back(plannedShot(refined[k], context));
    rollouts.emplace_back(shots.back().stroke, shots.back().target, refined[k].candidate.pocket,
                          context.request.seed + static_cast<unsigned>(k), context.request.rollouts, context);
  }
  const int threads = threadCount(context.request);
  int played = 0;
  for (bool more = true; more && !context.shouldStop(until);)
  {
    more = false;
    double best = 0.0;
    for (NoisyRollouts& shot : rollouts)
    {
      if (!shot.finished())
      {
        const int before = shot.estimate().trials;
        shot.play(ROLLOUT_BATCH, threads, until);
        played += shot.estimate().trials - before;
        more = true;
      }
      best = std::max(best, shot.estimate().probability());
    }
    report(context, {evaluations + played, static_cast<int>(shots.size()), best});
  }
  for (std::size_t k = 0; k < shots.size(); ++k)
    setEstimate(shots[k], rollouts[k]);
  evaluations += played;
  std::stable_sort(shots.begin(), shots.end(),
                   [](const PlannedShot& a, const PlannedShot& b)
                   {
                     return a.success_probability > b.success_probability ||
                            (a.success_probability == b.success_probability && a.margin > b.margin);
                   });
  return shots;
}

/// Plays `rollouts` in batches until they are done or `until` has passed (the last batch may end past it, by the
/// deadline at the latest: a batch cut short ends the shot's rollouts).
void playUntil(NoisyRollouts& rollouts, const PlanContext& context, Clock::time_point until)
{
  const int threads = threadCount(context.request);
  while (!rollouts.finished() && !context.shouldStop(until))
    rollouts.play(ROLLOUT_BATCH, threads, context.deadline);
}

NoisyRollouts confirmingRollouts(const PlannedShot& shot, unsigned stream, const PlanContext& context)
{
  return NoisyRollouts(shot.stroke, shot.target, indexOf(context.pockets, shot.pocket),
                       context.request.seed + CONFIRMATION_SEED_OFFSET + stream,
                       CONFIRMATION_FACTOR * context.request.rollouts, context);
}

/// Counts the rollouts played and, when any were, takes their estimate for `shot`.
void keepEstimate(PlannedShot& shot, const NoisyRollouts& rollouts, int& evaluations)
{
  evaluations += rollouts.estimate().trials;
  if (rollouts.estimate().trials > 0)
    setEstimate(shot, rollouts);
}

/// The chosen shot's probability from rollouts of its own: the highest of several noisy estimates is biased upwards
/// (the winner's curse), an estimate from other draws is not. When the leader's confirmed estimate falls below the
/// runner-up's ranking estimate by `halfway`, the runner-up is confirmed too in the time left, and the better of the
/// two confirmed shots leads. An estimate is kept only when some rollouts were played in time.
void confirm(std::vector<PlannedShot>& ranked, const PlanContext& context, Clock::time_point halfway, int& evaluations)
{
  NoisyRollouts leader = confirmingRollouts(ranked[0], 0, context);
  playUntil(leader, context, halfway);
  std::optional<NoisyRollouts> runner_up;
  if (leader.estimate().trials > 0 && leader.estimate().probability() < ranked[1].success_probability)
  {
    runner_up.emplace(confirmingRollouts(ranked[1], 1, context));
    playUntil(*runner_up, context, context.deadline);
  }
  else
    playUntil(leader, context, context.deadline);
  keepEstimate(ranked[0], leader, evaluations);
  if (!runner_up)
    return;
  keepEstimate(ranked[1], *runner_up, evaluations);
  if (runner_up->estimate().trials > 0 && runner_up->estimate().probability() > leader.estimate().probability())
    std::swap(ranked[0], ranked[1]);
}

std::string noPotExplanation(const CandidateSearch& search, const std::vector<RefinedShot>& refined,
                             const PlanContext& context)
{
  std::string text = std::to_string(search.pairs) + " target–pocket routes: " + std::to_string(search.blocked) +
                     " with a ball in the way (tried last), " + std::to_string(search.too_thin) +
                     " cut thinner than 80°, " + std::to_string(search.frozen_off_line) +
                     " frozen to the cue ball more than 8° off their line of centres, " +
                     std::to_string(search.cue_blocked) + " where the cue cannot clear the balls and rails";
  if (refined.empty())
    return "no shot to try (" + text + ")";
  const RefinedShot& closest = refined.front();
  return "no shot found that pots (" + text + "; " + std::to_string(refined.size()) +
         " refined): the closest, ball \"" + closest.candidate.target + "\" into pocket " +
         context.pockets[static_cast<std::size_t>(closest.candidate.pocket)].id + ", misses by " +
         std::to_string(-closest.evaluation.margin) + " m";
}
}  // namespace

PlanContext makeContext(const PlanRequest& request, const ShotConfiguration& configuration)
{
  PlanContext context{request, configuration, Eigen::Vector2d::Zero(), {}, {}, {}, {}, false};
  // A validated request's table lays out (validate(table) includes its outline).
  context.pockets = pocketTargets(configuration.table, configuration.ball_radius).value();
  context.rails = railLines(configuration.table, configuration.ball_radius);
  context.configuration.solver.relative_tolerance =
      std::max(configuration.solver.relative_tolerance, PLANNING_TOLERANCE);
  context.configuration.solver.absolute_tolerance = std::max(
      configuration.solver.absolute_tolerance, std::min(1e-2 * PLANNING_TOLERANCE, LOOSEST_ABSOLUTE_TOLERANCE));
  for (const TableBall& ball : request.balls)
    if (ball.id == request.cue_ball)
      context.cue_ball = ball.state.position.head<2>();
    else
      context.others.push_back(ball);
  std::vector<TableBall> balls{{request.cue_ball, {}}};
  balls.front().state.position = Eigen::Vector3d(context.cue_ball.x(), context.cue_ball.y(), configuration.ball_radius);
  balls.insert(balls.end(), context.others.begin(), context.others.end());
  context.cue_ball_touches = !strikeBodies(balls, 0, {configuration.ball_mass, configuration.ball_radius},
                                           configuration.table, configuration.ball_contact)
                                  .lone();
  return context;
}

}  // namespace planning

const char* toString(CueBallPath path)
{
  switch (path)
  {
    case CueBallPath::Kick:
      return "kick";
    case CueBallPath::Masse:
      return "masse";
    case CueBallPath::Jump:
      return "jump";
    case CueBallPath::Straight:
      break;
  }
  return "straight";
}

Expected<ShotPlan> planShot(const PlanRequest& request, const ShotConfiguration& configuration)
{
  using namespace planning;
  const Clock::time_point start = Clock::now();
  if (Status status = validate(request, configuration); !status)
    return status.error();
  PlanContext context = makeContext(request, configuration);
  context.deadline = after(start, request.budget);
  ShotPlan plan;
  const CandidateSearch search = candidateShots(context);
  const std::vector<RefinedShot> refined = refineCandidates(search, context, start, plan.evaluations);
  std::vector<PlannedShot> ranked =
      rankByRollouts(refined, context, after(start, RANKING_SHARE * request.budget), plan.evaluations);
  plan.found = !ranked.empty();
  if (plan.found)
  {
    if (ranked.size() > 1)
      confirm(ranked, context, after(start, CONFIRMATION_HALFWAY * request.budget), plan.evaluations);
    plan.best = ranked.front();
    plan.alternatives.assign(ranked.begin() + 1, ranked.end());
  }
  else
  {
    plan.explanation = noPotExplanation(search, refined, context);
    if (!refined.empty())
      plan.best = plannedShot(refined.front(), context);
  }
  if (plan.found || !refined.empty())
  {
    // The answer's prediction at the caller's own tolerance.
    auto outcome = predictShot(plan.best.cue, configuration, context.others);
    if (outcome)
      plan.outcome = std::move(outcome).value();
  }
  plan.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return plan;
}

}  // namespace billiard_shot_planner
