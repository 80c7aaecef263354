#include "candidates.hpp"

#include <algorithm>
#include <cmath>

#include "billiard_shot_planner/scenarios/ball_collision.hpp"

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
/// Factor on the difficulty of a candidate with a ball in the way of the cue ball or the target: after every clear
/// one.
constexpr double BLOCKED_PENALTY = 1e3;

/// Factor on the difficulty of a bank: after the direct pots of similar lengths (the rebound's angle depends on the
/// ball's speed and spin, which the refinement must find).
constexpr double BANK_PENALTY = 3.0;

/// Steps of the cue's elevation tried from the lowest allowed until the cue clears.
constexpr double ELEVATION_STEP = 2.0 * M_PI / 180.0;

/// Distance from `point` to the segment [from, to].
double distanceToSegment(const Eigen::Vector2d& point, const Eigen::Vector2d& from, const Eigen::Vector2d& to)
{
  const Eigen::Vector2d along = to - from;
  const double length2 = along.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((point - from).dot(along) / length2, 0.0, 1.0) : 0.0;
  return (from + s * along - point).norm();
}

/// Whether a ball rolling from `from` to `to` passes 2R from every other ball than `ignored`.
bool pathIsClear(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const std::string& ignored,
                 const PlanContext& context)
{
  for (const TableBall& ball : context.others)
    if (ball.id != ignored && distanceToSegment(ball.state.position.head<2>(), from, to) < 2.0 * context.radius())
      return false;
  return true;
}

/// m/s², the rolling deceleration (sliding included) the first speeds assume; the cue ball's speed off the tip over
/// the cue's.
constexpr double DECELERATION = 0.5, BALL_OVER_CUE = 1.2;

/// The object ball's speed that carries it `object_path` m and 0.3 m beyond (into the pocket, whatever the refinement
/// takes off).
double objectSpeedFor(double object_path)
{
  return std::sqrt(2.0 * DECELERATION * (object_path + 0.3));
}

/// A cue speed that sends the target about `object_path` m and the cue ball `cue_path` m before it, at this cut: the
/// object ball leaves at (1 + e)/2 cos(cut) of the cue ball's speed and needs v² = 2·a·(path + 0.3 m) with a rolling
/// deceleration of about 0.5 m/s² (sliding included); the cue ball loses little on the way, and leaves the tip at
/// about 1.2 times the cue's speed. A starting point: the refinement adjusts it.
double initialSpeed(double cue_path, double object_path, double cut, const PlanContext& context)
{
  const double e = context.configuration.ball_contact.ball_ball.restitution;
  const double object = objectSpeedFor(object_path);
  const double cue_ball =
      std::sqrt(std::pow(object / (0.5 * (1.0 + e) * std::cos(cut)), 2) + 2.0 * DECELERATION * cue_path);
  const RobotLimits& limits = context.request.limits;
  return std::clamp(cue_ball / BALL_OVER_CUE, limits.min_speed, limits.max_speed);
}

/// A cue ball frozen to the target sends it along their line of centres (turned by the throw): the target leaves with
/// about half the cue ball's lone speed, as the two balls share the cue's push while they touch.
double frozenSpeed(double object_path, const PlanContext& context)
{
  const double object = objectSpeedFor(object_path);
  const RobotLimits& limits = context.request.limits;
  return std::clamp(2.0 * object / BALL_OVER_CUE, limits.min_speed, limits.max_speed);
}

std::vector<int> pocketsToTry(const PlanContext& context)
{
  if (!context.request.pocket.empty())
    return {indexOf(context.pockets, context.request.pocket)};
  std::vector<int> all(context.pockets.size());
  for (std::size_t k = 0; k < all.size(); ++k)
    all[k] = static_cast<int>(k);
  return all;
}

/// The target's way to its pocket: straight, or off one cushion.
struct Route
{
  Eigen::Vector2d first_leg_end;  ///< the pocket, or the point where the target meets the cushion
  double length = 0.0;            ///< m, along both legs
  int bank_cushion = -1;          ///< index in PlanContext::rails; −1: straight
};

bool routeIsClear(const Eigen::Vector2d& object, const Eigen::Vector2d& hole, const Route& route,
                  const std::string& target, const PlanContext& context)
{
  return pathIsClear(object, route.first_leg_end, target, context) &&
         (route.bank_cushion < 0 || pathIsClear(route.first_leg_end, hole, target, context));
}

/// The difficulty's factor for a route: a ball in the way, a bank.
double penalty(bool blocked, const Route& route)
{
  return (blocked ? BLOCKED_PENALTY : 1.0) * (route.bank_cushion >= 0 ? BANK_PENALTY : 1.0);
}

/// Raises the stroke's cue to the lowest elevation that clears (clearElevation); false, counted, when none does.
bool raiseToClear(Stroke& stroke, const PlanContext& context, CandidateSearch& search)
{
  const auto theta = clearElevation(stroke, context, context.request.limits.min_theta);
  if (!theta)
  {
    ++search.cue_blocked;
    return false;
  }
  stroke.theta = *theta;
  return true;
}

/// The target touches the cue ball: the strike moves both at once, and the target leaves along the line of centres
/// turned by the throw, so the cue aims along that line, turned towards the route. The throw turns the target by a
/// fraction of the cue's turn (docs/cue_strike.md, Frozen balls), so the first aim turns the cue three times as far
/// as the route; the refinement finds the rest.
void addFrozenCandidate(const TableBall& target, int pocket, const Route& route, const PlanContext& context,
                        CandidateSearch& search)
{
  const Eigen::Vector2d object = target.state.position.head<2>();
  const Eigen::Vector2d centres = (object - context.cue_ball).normalized();
  const Eigen::Vector2d line = (route.first_leg_end - object).normalized();
  const double turn = std::atan2(centres.x() * line.y() - centres.y() * line.x(), centres.dot(line));
  if (std::abs(turn) > FROZEN_MAX_TURN)
  {
    ++search.frozen_off_line;
    return;
  }
  const bool route_blocked =
      !routeIsClear(object, context.pockets[static_cast<std::size_t>(pocket)].centre, route, target.id, context);
  search.blocked += route_blocked;
  Stroke stroke;
  stroke.phi = std::atan2(centres.y(), centres.x()) + 3.0 * turn;
  stroke.speed = frozenSpeed(route.length, context);
  if (!raiseToClear(stroke, context, search))
    return;
  search.candidates.push_back({target.id, pocket, stroke, std::abs(turn), penalty(route_blocked, route) * route.length,
                               route.bank_cushion, CueBallPath::Straight, context.cue_ball, line, false,
                               route_blocked});
}

void addCandidate(const TableBall& target, int pocket, const Route& route, const PlanContext& context,
                  CandidateSearch& search)
{
  ++search.pairs;
  if ((target.state.position.head<2>() - context.cue_ball).norm() <= 2.0 * context.radius() + TOUCHING_GAP)
  {
    addFrozenCandidate(target, pocket, route, context, search);
    return;
  }
  const Eigen::Vector2d object = target.state.position.head<2>();
  const Eigen::Vector2d hole = context.pockets[static_cast<std::size_t>(pocket)].centre;
  const Eigen::Vector2d line = (route.first_leg_end - object).normalized();
  const Eigen::Vector2d ghost = object - 2.0 * context.radius() * line;
  const Eigen::Vector2d aim = ghost - context.cue_ball;
  const double cut = std::acos(std::clamp(aim.normalized().dot(line), -1.0, 1.0));
  if (cut > MAX_CUT)
  {
    ++search.too_thin;
    return;
  }
  // A ball in the way is tried last rather than dropped: the simulation decides whether the shot still pots (the
  // cue ball may drive the ball in the way into the target, a kiss may clear it).
  const bool cue_path_blocked = !pathIsClear(context.cue_ball, ghost, target.id, context);
  const bool route_blocked = !routeIsClear(object, hole, route, target.id, context);
  const bool blocked = cue_path_blocked || route_blocked;
  search.blocked += blocked;
  Stroke stroke;
  stroke.phi = std::atan2(aim.y(), aim.x());
  stroke.speed = initialSpeed(aim.norm(), route.length, cut, context);
  if (!raiseToClear(stroke, context, search))
    return;
  const double difficulty = penalty(blocked, route) * (aim.norm() + route.length) / std::max(std::cos(cut), 0.05);
  search.candidates.push_back({target.id, pocket, stroke, cut, difficulty, route.bank_cushion, CueBallPath::Straight,
                               ghost, line, cue_path_blocked, route_blocked});
}

/// The route off rail `rail` (context.rails) to `pocket`, by the mirror image of its aim in the line the target's
/// centre runs along when it touches the rail's nose; none when the pocket lies on that rail, or the target would meet
/// the rail within a pocket's reach (its jaws).
std::optional<Route> bankRoute(const Eigen::Vector2d& object, const PocketTarget& pocket, int rail,
                               const PlanContext& context)
{
  const RailLine& off = context.rails[static_cast<std::size_t>(rail)];
  if (off.holds(pocket.place))
    return std::nullopt;  // the pocket is on this rail
  const Eigen::Vector2d mirrored = off.mirror(pocket.centre);
  const double t = off.crossing(object, mirrored);
  if (!(t > 0.0 && t < 1.0))
    return std::nullopt;
  const Eigen::Vector2d bounce = object + t * (mirrored - object);
  for (const PocketTarget& p : context.pockets)
    if ((bounce - p.centre).norm() < p.radius + 2.0 * context.radius())
      return std::nullopt;
  return Route{bounce, (mirrored - object).norm(), rail};
}

void addCandidates(const TableBall& target, int pocket, const PlanContext& context, CandidateSearch& search)
{
  const Eigen::Vector2d object = target.state.position.head<2>();
  const PocketTarget& place = context.pockets[static_cast<std::size_t>(pocket)];
  const Eigen::Vector2d& hole = place.centre;
  addCandidate(target, pocket, Route{hole, (hole - object).norm(), -1}, context, search);
  for (std::size_t rail = 0; rail < context.rails.size(); ++rail)
    if (const auto route = bankRoute(object, place, static_cast<int>(rail), context))
      addCandidate(target, pocket, *route, context, search);
}
}  // namespace

ClearanceMargin clearanceMargin(const PlanContext& context)
{
  const ExecutionNoise& noise = context.request.noise;
  return {3.0 * std::hypot(noise.a, noise.b), 3.0 * std::hypot(noise.phi, noise.theta)};
}

std::optional<double> clearElevation(Stroke stroke, const PlanContext& context, double from)
{
  const RobotLimits& limits = context.request.limits;
  const ClearanceMargin margin = clearanceMargin(context);
  for (double theta = std::max(from, limits.min_theta); theta <= limits.max_theta + 1e-12; theta += ELEVATION_STEP)
  {
    stroke.theta = theta;
    auto cue = placeStroke(stroke, context.cue_ball, context.radius());
    if (cue && cueClears(cue.value(), context, margin))
      return theta;
  }
  return std::nullopt;
}

CandidateSearch candidateShots(const PlanContext& context)
{
  CandidateSearch search;
  for (const TableBall& ball : context.others)
  {
    if (!context.request.target.empty() && ball.id != context.request.target)
      continue;
    for (int pocket : pocketsToTry(context))
      addCandidates(ball, pocket, context, search);
  }
  std::sort(search.candidates.begin(), search.candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.difficulty < b.difficulty; });
  return search;
}

}  // namespace planning
}  // namespace billiard_shot_planner
