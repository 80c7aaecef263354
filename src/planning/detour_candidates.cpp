#include "detour_candidates.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <map>
#include <tuple>

#include "billiard_shot_planner/core/plane_geometry.hpp"

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
/// Spacing in time of the samples of the cue ball's path (a ball at 4 m/s moves 8 mm between them; the contact
/// with the target is interpolated between two samples, and the refinement corrects what is left).
constexpr double PATH_SAMPLE_SPACING = 0.002;
/// How long the cue ball's path is followed: REACH_TIME_FACTOR times the time its first speed takes over the
/// detour's length (a ball that slows more than that stops short of the target), at most LONE_PATH_TIME.
constexpr double LONE_PATH_TIME = 4.0;
constexpr double REACH_TIME_FACTOR = 3.0;
/// The directions scanned for a sign change of the aim's error, around each kind's first aim.
constexpr double DEGREE = M_PI / 180.0;
constexpr double KICK_SPAN = 6.0 * DEGREE, KICK_STEP = 2.0 * DEGREE;
constexpr double MASSE_SPAN = 25.0 * DEGREE, MASSE_STEP = 4.0 * DEGREE;
constexpr double JUMP_SPAN = 3.0 * DEGREE, JUMP_STEP = 1.0 * DEGREE;
/// The aim's error is continuous away from the wrap at ±π: a sign change of larger errors is the wrap, not a root.
constexpr double LARGEST_BRACKETED_ERROR = 2.5;
/// How finely a root's direction is found: a tenth of the execution noise's σ_φ (2e-3 rad); the refinement on the
/// whole table does the rest.
constexpr double ROOT_TOLERANCE = 3e-4;
constexpr std::uintmax_t ROOT_ITERATIONS = 16;
/// The hit of a massé, across the cue, and of a jump, above the centre, as shares of the largest offset.
constexpr double MASSE_OFFSET_SHARE = 0.8, JUMP_OFFSET_SHARE = 0.8;
/// The cue's speeds of a jump, as shares of the largest: a jump needs a fast cue.
constexpr double JUMP_SPEED_SHARES[] = {0.6, 0.85};
/// Cue elevations tried, within the limits (the largest allowed below the lowest, when none is): a massé curves
/// more the steeper the cue; a jump needs the cue steep enough to drive the ball into the cloth, and not so steep
/// that the tip slips off (at 50° and more the strike is a miscue for most hits).
constexpr double MASSE_ELEVATIONS[] = {15.0 * DEGREE, 30.0 * DEGREE, 50.0 * DEGREE};
constexpr double JUMP_ELEVATIONS[] = {30.0 * DEGREE, 40.0 * DEGREE};

double angleOf(const Eigen::Vector2d& v)
{
  return std::atan2(v.y(), v.x());
}
double wrapped(double angle)
{
  return std::remainder(angle, 2.0 * M_PI);
}

/// Where the cue ball, played alone, meets the target (or passes it), judged against the candidate.
struct Approach
{
  bool valid = false;
  bool hits = false;
  /// rad, from the candidate's line to the direction the target would leave in (its centre minus the cue ball's
  /// at contact); for a miss, continued beyond ±π/2 by the miss distance in ball radii.
  double error = NAN;
  double clearance = INFINITY;  ///< m, the least distance less 2R to another ball before the contact
};

/// What each search shares: the blocked candidate, the target's centre, and the cue ball's strikes. A strike is
/// solved once for each elevation and hit point, at φ = 0 and a cue speed of 1 m/s: the impact has no length or
/// time scale, so its outcome is linear in the cue's speed, and the cloth is the same in every direction, so a
/// stroke at φ is that outcome turned by φ about the vertical.
class LonePaths
{
public:
  LonePaths(const Candidate& blocked, const PlanContext& context) : blocked_(blocked), context_(context)
  {
    motion_ = context.configuration.motion;
    motion_.max_time = std::min(motion_.max_time, LONE_PATH_TIME);
    motion_.impact = context.configuration.solver;
    for (const TableBall& ball : context.others)
      if (ball.id == blocked.target)
        target_ = ball.state.position.head<2>();
      else
        obstacles_.push_back(ball.state.position.head<2>());
  }

  /// The approach of the cue ball struck by `stroke` to the target, which it should meet after about `reach` m.
  Approach approach(const Stroke& stroke, double reach)
  {
    const std::optional<BallState> start = afterStrike(stroke);
    if (!start)
      return {};
    ++evaluations;
    const ShotConfiguration& c = context_.configuration;
    MotionParameters motion = motion_;
    motion.max_time = std::min(motion_.max_time, followedTime(*start, reach));
    auto path = predictTrajectory(*start, {c.ball_mass, c.ball_radius}, c.table, motion);
    if (!path)
      return {};
    return judge(path.value().sample(PATH_SAMPLE_SPACING));
  }

  int evaluations = 0;

private:
  static double followedTime(const BallState& start, double reach)
  {
    const double speed = start.velocity.head<2>().norm();
    return speed > 0.0 ? std::min(LONE_PATH_TIME, REACH_TIME_FACTOR * reach / speed) : LONE_PATH_TIME;
  }

  std::optional<BallState> afterStrike(const Stroke& stroke)
  {
    const auto key = std::make_tuple(stroke.theta, stroke.a, stroke.b);
    auto cached = unit_strikes_.find(key);
    if (cached == unit_strikes_.end())
      cached = unit_strikes_.emplace(key, unitStrike(stroke)).first;
    if (!cached->second)
      return std::nullopt;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(stroke.phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    BallState start;
    start.position = Eigen::Vector3d(context_.cue_ball.x(), context_.cue_ball.y(), context_.radius());
    start.velocity = stroke.speed * turn * cached->second->velocity;
    start.angular_velocity = stroke.speed * turn * cached->second->angular_velocity;
    return start;
  }

  std::optional<BallState> unitStrike(Stroke stroke)
  {
    ++evaluations;
    stroke.phi = 0.0;
    stroke.speed = 1.0;
    auto cue = placeStroke(stroke, context_.cue_ball, context_.radius());
    if (!cue)
      return std::nullopt;
    auto struck = strikeBall(cue.value(), context_.configuration);
    if (!struck || struck.value().miscue)
      return std::nullopt;
    BallState unit;
    unit.velocity = struck.value().velocity;
    unit.angular_velocity = struck.value().angular_velocity;
    return unit;
  }

private:
  Approach judge(const std::vector<TrajectorySample>& path) const
  {
    Approach result;
    if (path.size() < 2)
      return result;
    const double contact = 2.0 * context_.radius();
    const double centre_height = path.front().state.position.z();
    const Eigen::Vector3d target(target_.x(), target_.y(), centre_height);
    double closest = INFINITY;
    std::size_t closest_index = 0;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
      const Eigen::Vector3d& p = path[i].state.position;
      const double distance = (p - target).norm();
      if (distance <= contact && i > 0)
        return contactAt(path[i - 1].state.position, p, target, result);
      for (const Eigen::Vector2d& obstacle : obstacles_)
        result.clearance = std::min(result.clearance,
                                    (p - Eigen::Vector3d(obstacle.x(), obstacle.y(), centre_height)).norm() - contact);
      if (distance < closest)
      {
        closest = distance;
        closest_index = i;
      }
    }
    return miss(path, closest_index, result);
  }

  /// The contact between two samples, where the distance to the target crosses 2R (linearly interpolated).
  Approach contactAt(const Eigen::Vector3d& before, const Eigen::Vector3d& after, const Eigen::Vector3d& target,
                     Approach result) const
  {
    const double contact = 2.0 * context_.radius();
    const double d0 = (before - target).norm(), d1 = (after - target).norm();
    const double s = d0 > d1 ? std::clamp((d0 - contact) / (d0 - d1), 0.0, 1.0) : 1.0;
    const Eigen::Vector3d at = before + s * (after - before);
    result.valid = result.hits = true;
    result.error = wrapped(angleOf((target - at).head<2>()) - angleOf(blocked_.line));
    return result;
  }

  /// A path that never touches the target: the error goes on from ±π/2 (a grazing hit) by the miss in radii.
  Approach miss(const std::vector<TrajectorySample>& path, std::size_t index, Approach result) const
  {
    const Eigen::Vector2d at = path[index].state.position.head<2>();
    Eigen::Vector2d direction = path[index].state.velocity.head<2>();
    if (direction.norm() == 0.0)
      direction = at - path[index > 0 ? index - 1 : 0].state.position.head<2>();
    if (direction.norm() == 0.0)
      return result;
    direction.normalize();
    const double side = cross(direction, target_ - at);
    const double beyond = (std::abs(side) - 2.0 * context_.radius()) / context_.radius();
    result.valid = true;
    result.error = wrapped(angleOf(direction) - angleOf(blocked_.line)) + std::copysign(M_PI_2 + beyond, side);
    return result;
  }

  const Candidate& blocked_;
  const PlanContext& context_;
  MotionParameters motion_;
  std::map<std::tuple<double, double, double>, std::optional<BallState>> unit_strikes_;
  Eigen::Vector2d target_ = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> obstacles_;
};

/// One kind of detour: its stroke but for the direction, and the directions scanned around `centre`.
struct Variant
{
  CueBallPath path;
  Stroke stroke;
  double span, step;
  double reach;  ///< m, the length of the cue ball's way to the ghost ball (to its image, for a kick)
};

/// The direction within the bracket where the aim's error is zero, if TOMS 748 finds it.
std::optional<double> aimRoot(LonePaths& paths, Stroke stroke, double reach, double low, double high, double error_low,
                              double error_high)
{
  auto error = [&](double phi)
  {
    stroke.phi = phi;
    const Approach approach = paths.approach(stroke, reach);
    return approach.valid ? approach.error : NAN;
  };
  std::uintmax_t iterations = ROOT_ITERATIONS;
  try
  {
    const auto bracket = boost::math::tools::toms748_solve(
        error, low, high, error_low, error_high, [](double a, double b) { return std::abs(b - a) < ROOT_TOLERANCE; },
        iterations);
    return 0.5 * (bracket.first + bracket.second);
  }
  catch (const std::exception&)  // an invalid path inside the bracket: no root here
  {
    return std::nullopt;
  }
}

/// The detours of one variant: every root of the aim's error in its scan whose path clears the other balls.
void searchVariant(const Variant& variant, const Candidate& blocked, LonePaths& paths, const PlanContext& context,
                   Clock::time_point until, std::vector<std::pair<double, Candidate>>& found)
{
  const double centre = variant.stroke.phi;
  double previous_phi = NAN, previous_error = NAN;
  for (double offset = -variant.span; offset <= variant.span + 1e-12; offset += variant.step)
  {
    if (context.shouldStop(until))
      return;
    Stroke stroke = variant.stroke;
    stroke.phi = centre + offset;
    const Approach approach = paths.approach(stroke, variant.reach);
    const double error = approach.valid ? approach.error : NAN;
    const bool bracketed = std::abs(error) < LARGEST_BRACKETED_ERROR &&
                           std::abs(previous_error) < LARGEST_BRACKETED_ERROR &&
                           (error > 0.0) != (previous_error > 0.0);
    if (bracketed)
      if (const auto root =
              aimRoot(paths, variant.stroke, variant.reach, previous_phi, stroke.phi, previous_error, error))
      {
        stroke.phi = *root;
        const Approach at_root = paths.approach(stroke, variant.reach);
        if (at_root.hits && at_root.clearance > 0.0)
        {
          Candidate detour = blocked;
          detour.stroke = stroke;
          detour.cue_ball_path = variant.path;
          detour.cue_path_blocked = false;
          found.emplace_back(at_root.clearance, detour);
        }
      }
    previous_phi = stroke.phi = centre + offset;
    previous_error = error;
  }
}

/// The stroke at the lowest elevation from `theta` whose cue clears the balls and rails, if any.
std::optional<Stroke> withClearCue(Stroke stroke, double theta, const PlanContext& context)
{
  const auto clear = clearElevation(stroke, context, theta);
  if (!clear)
    return std::nullopt;
  stroke.theta = *clear;
  return stroke;
}

/// A kick off `rail`: aimed at the ghost ball's image in the line the cue ball's centre runs along at its nose.
std::optional<Variant> kickVariant(const Candidate& blocked, const RailLine& rail, const PlanContext& context)
{
  const Eigen::Vector2d image = rail.mirror(blocked.ghost);
  Stroke stroke = blocked.stroke;
  stroke.phi = angleOf(image - context.cue_ball);
  stroke.a = stroke.b = 0.0;
  const double straight = (blocked.ghost - context.cue_ball).norm();
  stroke.speed = std::clamp(stroke.speed * std::sqrt((image - context.cue_ball).norm() / std::max(straight, 1e-3)),
                            context.request.limits.min_speed, context.request.limits.max_speed);
  const auto clear = withClearCue(stroke, stroke.theta, context);
  if (!clear)
    return std::nullopt;
  return Variant{CueBallPath::Kick, *clear, KICK_SPAN, KICK_STEP, (image - context.cue_ball).norm()};
}

template <std::size_t N>
std::vector<double> elevations(const double (&wanted)[N], const RobotLimits& limits)
{
  std::vector<double> allowed;
  for (double theta : wanted)
  {
    const double clamped = std::clamp(theta, limits.min_theta, limits.max_theta);
    if (allowed.empty() || clamped > allowed.back() + 1e-9)
      allowed.push_back(clamped);
  }
  return allowed;
}

std::vector<Variant> variants(const Candidate& blocked, const PlanContext& context)
{
  const RobotLimits& limits = context.request.limits;
  const double straight = (blocked.ghost - context.cue_ball).norm();
  std::vector<Variant> all;
  for (const RailLine& rail : context.rails)
    if (const auto kick = kickVariant(blocked, rail, context))
      all.push_back(*kick);
  for (double theta : elevations(MASSE_ELEVATIONS, limits))
    for (double side : {1.0, -1.0})
    {
      Stroke stroke = blocked.stroke;
      stroke.a = side * MASSE_OFFSET_SHARE * limits.max_offset;
      stroke.b = 0.0;
      if (const auto clear = withClearCue(stroke, theta, context))
        all.push_back({CueBallPath::Masse, *clear, MASSE_SPAN, MASSE_STEP, straight});
    }
  for (double theta : elevations(JUMP_ELEVATIONS, limits))
    for (double share : JUMP_SPEED_SHARES)
    {
      Stroke stroke = blocked.stroke;
      stroke.a = 0.0;
      stroke.b = JUMP_OFFSET_SHARE * limits.max_offset;
      stroke.speed = std::max(limits.min_speed, share * limits.max_speed);
      if (const auto clear = withClearCue(stroke, theta, context))
        all.push_back({CueBallPath::Jump, *clear, JUMP_SPAN, JUMP_STEP, straight});
    }
  return all;
}
}  // namespace

DetourSearch detourCandidates(const Candidate& blocked, const PlanContext& context, Clock::time_point until)
{
  if (context.cue_ball_touches)
    return {};  // the lone ball's strike, which the detours scan, is not this cue ball's
  LonePaths paths(blocked, context);
  std::vector<std::pair<double, Candidate>> found;
  for (const Variant& variant : variants(blocked, context))
    searchVariant(variant, blocked, paths, context, until, found);
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  DetourSearch search;
  search.evaluations = paths.evaluations;
  std::map<CueBallPath, int> kept;
  for (const auto& [clearance, candidate] : found)
    if (kept[candidate.cue_ball_path]++ == 0)
      search.candidates.push_back(candidate);
  return search;
}

}  // namespace planning
}  // namespace billiard_shot_planner
