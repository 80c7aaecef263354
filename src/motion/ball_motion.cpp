#include "billiard_shot_planner/motion/ball_motion.hpp"

#include <chrono>
#include <cmath>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"
#include "phase_dynamics.hpp"
#include "table_events.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Landing speed (m/s) below which a touch-down is no impact but round-off: the engine needs an approach.
constexpr double TOUCH_DOWN_SPEED = 1e-9;

/// Cushion speed (m/s) below which a ball that comes back to the cushion it just left is pressed against it: the
/// Zeno sequence of hits has converged (what is left of it lasts some 1e-5 s). In 3 000 random shots near a rail,
/// the sequences that end with the ball leaving the rail never went below 8e-4 m/s; those that do not went on to
/// 1e-12 m/s and then through the cushion. The same holds for a ball riding a nose below its centre in the air,
/// each hop shorter than the one before.
constexpr double SUSTAINED_CONTACT_SPEED = 1e-6;

/// Where one phase ends: by itself, at a cushion, in a pocket or at the time limit.
struct SegmentEnd
{
  double duration;
  MotionEventType event;
  int cushion = -1;
  int pocket = -1;
  NoseContact contact = NoseContact::Impact;
};

Status checkStart(const BallState& start, const Ball& ball, const Table& table)
{
  if (Status status =
          firstError({requireFinite(start.position, "position"), requireFinite(start.velocity, "v"),
                      requireFinite(start.angular_velocity, "omega"), requirePlausibleSpeed(start.velocity.norm(), "v"),
                      requirePlausibleSpeed(start.angular_velocity.norm() * ball.radius, "omega")});
      !status)
    return status;
  const double reach = cushionReach(table, ball.radius);
  const double x = std::abs(start.position.x()), y = std::abs(start.position.y());
  if (x > 0.5 * table.length || y > 0.5 * table.width)
    return invalidArgument("position", "the ball is off the table");
  if (x > 0.5 * table.length - reach + CONTACT_DISTANCE || y > 0.5 * table.width - reach + CONTACT_DISTANCE)
    return invalidArgument("position", "the ball overlaps a cushion");
  for (std::size_t i = 0; i < table.pockets.size(); ++i)
    if ((start.position.head<2>() - table.pockets[i].centre).norm() <= table.pockets[i].radius)
      return invalidArgument("position", "the ball is inside pocket " + std::to_string(i) + "'s capture region");
  return {};
}

class TrajectoryPredictor
{
public:
  TrajectoryPredictor(const Ball& ball, const Table& table, const MotionParameters& p)
      : ball_(ball),
        table_(table),
        p_(p),
        deadline_(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                         std::chrono::duration<double>(p.impact.max_seconds)))
  {
  }

  Expected<BallTrajectory> run(BallState state)
  {
    state.position.z() = ball_.radius;
    if (p_.planar || state.velocity.z() < 0.0)
      state.velocity.z() = 0.0;  // planar: the paper's choice; a downward v_z is absorbed by the cloth
    double t = 0.0;
    trajectory_.events.push_back({MotionEventType::Start, 0.0, state});
    while (true)
    {
      if (static_cast<int>(trajectory_.events.size()) >= p_.max_events || t >= p_.max_time)
        return finish(MotionEventType::TimeLimit, MotionOutcome::TimeLimit, t, state);
      const MotionPhase phase = classify(state, ball_.radius);
      if (phase == MotionPhase::Stationary)
        return finish(MotionEventType::Rest, MotionOutcome::Rest, t, state);
      auto next = advance(phase, state, t);
      if (!next)
        return next.error();
      if (next.value())
        return trajectory_;
    }
  }

private:
  /// Runs one segment and its closing event. Returns true when the trajectory has ended.
  Expected<bool> advance(MotionPhase phase, BallState& state, double& t)
  {
    const PhaseMotion motion = phaseMotion(phase, state, ball_, p_);
    MotionSegment segment{phase, t, t, state, motion.acceleration, motion.angular_acceleration};
    const SegmentEnd end = segmentEnd(segment, motion, t);
    segment.end_time = t + end.duration;
    trajectory_.segments.push_back(segment);
    t = segment.end_time;
    state = segment.at(t);
    switch (end.event)
    {
      case MotionEventType::Pocketed:
        trajectory_.events.push_back({end.event, t, state, -1, end.pocket});
        trajectory_.outcome = MotionOutcome::Pocketed;
        return true;
      case MotionEventType::TimeLimit:
        finish(end.event, MotionOutcome::TimeLimit, t, state);
        return true;
      case MotionEventType::CushionHit:
        return hitCushion(end.cushion, end.contact, state, t);
      case MotionEventType::Landing:
        return land(state, t);
      default:
        state = snapPhaseEnd(end.event, state, ball_.radius);
        trajectory_.events.push_back({end.event, t, state});
        return false;
    }
  }

  SegmentEnd segmentEnd(const MotionSegment& segment, const PhaseMotion& motion, double t) const
  {
    SegmentEnd end{motion.end, motion.end_event};
    if (p_.max_time - t < end.duration)
      end = {p_.max_time - t, MotionEventType::TimeLimit};
    if (auto hit = firstCushionHit(segment, table_, ball_.radius, end.duration))
      end = {hit->time, MotionEventType::CushionHit, hit->rail, -1, hit->contact};
    if (auto entry = firstPocketEntry(segment, table_, end.duration))
      end = {entry->time, MotionEventType::Pocketed, -1, entry->index};
    return end;
  }

  Expected<bool> hitCushion(int rail, NoseContact contact, BallState& state, double t)
  {
    if (contact == NoseContact::Over)
    {
      trajectory_.events.push_back({MotionEventType::CushionHit, t, state, rail});
      trajectory_.outcome = MotionOutcome::OffTable;  // its bottom above the nose, the ball passes over it
      return true;
    }
    // Touching the cloth, the ball meets the nose and the cloth at once; a cloth contact that separates from the
    // start takes part only if the impact brings it back.
    const bool on_cloth = state.position.z() <= ball_.radius * (1.0 + 1e-9);
    const Eigen::Vector3d normal = cushionNormal(rail, table_, state.position);
    const double approach = -state.velocity.dot(normal);
    if (contact == NoseContact::Pressed ||
        pressedAgainst(rail, on_cloth, on_cloth ? speedTowards(rail, state) : approach))
    {
      trajectory_.events.push_back({MotionEventType::CushionContact, t, state, rail});
      trajectory_.outcome = MotionOutcome::AgainstCushion;
      return true;
    }
    CushionImpact impact{ball_.mass, ball_.radius,   state.velocity, state.angular_velocity,        normal,
                         on_cloth,   table_.cushion, table_.cloth,   table_.cushion_stiffness_ratio};
    auto options = impactOptions();
    if (!options)
      return options.error();
    auto result = solve(impact, options.value());
    if (!result)
      return result.error();
    state.velocity = result.value().velocity;
    state.angular_velocity = result.value().angular_velocity;
    if (p_.planar)
      state.velocity.z() = 0.0;
    trajectory_.events.push_back({MotionEventType::CushionHit, t, state, rail});
    last_hit_ = {rail, on_cloth, on_cloth ? -speedTowards(rail, state) : state.velocity.dot(normal)};
    return false;
  }

  /// The impact solver's options with what is left of the trajectory's wall-clock budget (SolverOptions::
  /// max_seconds bounds the whole trajectory, all its impacts included).
  Expected<SolverOptions> impactOptions() const
  {
    const double left = std::chrono::duration<double>(deadline_ - std::chrono::steady_clock::now()).count();
    if (!(left > 0.0))
      return Error{ErrorCode::TimeLimitExceeded, "",
                   "the trajectory did not end within " + formatNumber(p_.impact.max_seconds) + " s (" +
                       std::to_string(trajectory_.events.size()) + " events)"};
    SolverOptions options = p_.impact;
    options.max_seconds = left;
    return options;
  }

  /// Horizontal speed of the ball's centre towards cushion `rail` (0: −x, 1: +x, 2: −y, 3: +y).
  static double speedTowards(int rail, const BallState& state)
  {
    const int axis = rail / 2;
    return rail % 2 == 1 ? state.velocity(axis) : -state.velocity(axis);
  }

  /// Whether the ball has come back to the cushion it last left, on the cloth or in the air as then, both times
  /// slower than SUSTAINED_CONTACT_SPEED (on the cloth horizontally, in the air along the contact normal): it is
  /// pressed into the rail, by its spin on the cloth, by its weight on a nose below its centre in the air. The hits
  /// would go on as a Zeno sequence of ever smaller ones until the last, approaching to round-off, was missed and the
  /// ball went through the cushion (6 of 3 000 random shots near a rail, up to 0.5 m off the table). Sustained contact
  /// is not modelled: the path ends.
  bool pressedAgainst(int rail, bool on_cloth, double approach) const
  {
    return last_hit_.rail == rail && last_hit_.on_cloth == on_cloth &&
           last_hit_.rebound_speed < SUSTAINED_CONTACT_SPEED && approach < SUSTAINED_CONTACT_SPEED;
  }

  Expected<bool> land(BallState& state, double t)
  {
    state.position.z() = ball_.radius;
    if (state.velocity.z() > -TOUCH_DOWN_SPEED)
    {
      // The round-off of a hop of nothing (a cushion hit that left v_z at 1e-16): no impact, the ball is on the cloth.
      state.velocity.z() = 0.0;
      trajectory_.events.push_back({MotionEventType::Landing, t, state});
      return false;
    }
    auto options = impactOptions();
    if (!options)
      return options.error();
    auto result = solve(BallTableImpact{ball_.mass, ball_.radius, state.velocity, state.angular_velocity, table_.cloth},
                        options.value());
    if (!result)
      return result.error();
    state.velocity = result.value().velocity;
    state.angular_velocity = result.value().angular_velocity;
    if (state.velocity.z() < p_.min_bounce_speed)
      state.velocity.z() = 0.0;  // the last bounce: from now on the ball stays on the cloth
    trajectory_.events.push_back({MotionEventType::Landing, t, state});
    return false;
  }

  BallTrajectory finish(MotionEventType event, MotionOutcome outcome, double t, const BallState& state)
  {
    trajectory_.events.push_back({event, t, state});
    trajectory_.outcome = outcome;
    return trajectory_;
  }

  const Ball& ball_;
  const Table& table_;
  const MotionParameters& p_;
  std::chrono::steady_clock::time_point deadline_;  ///< of the whole trajectory (SolverOptions::max_seconds)
  BallTrajectory trajectory_;
  struct CushionHitRecord
  {
    int rail = -1;
    bool on_cloth = false;
    double rebound_speed = 0.0;  ///< m/s away from the cushion: horizontally on the cloth, along the normal in the air
  } last_hit_;
};
}  // namespace
}  // namespace detail

Status validate(const MotionParameters& p)
{
  if (Status status = firstError(
          {requirePositive(p.gravity, "gravity"), requirePositive(p.sliding_friction, "sliding_friction"),
           requirePositive(p.rolling_friction, "rolling_friction"),
           requirePositive(p.spinning_friction, "spinning_friction"),
           requireNonNegative(p.min_bounce_speed, "min_bounce_speed"),
           requireWithin(p.max_time, 1e-3, MAX_TRAJECTORY_TIME, "max_time", "seconds; a ball stops within a minute")});
      !status)
    return status;
  if (p.max_events < 2)
    return invalidArgument("max_events", "must be at least 2");
  return {};
}

Expected<BallTrajectory> predictTrajectory(const BallState& start, const Ball& ball, const Table& table,
                                           const MotionParameters& parameters)
{
  if (Status status = firstError({requirePositive(ball.mass, "ball_mass"), requirePositive(ball.radius, "ball_radius"),
                                  validate(parameters), validate(table)});
      !status)
    return status.error();
  if (Status status = validateCushionHeight(table.cushion_height, ball.radius, "table.cushion_height"); !status)
    return status.error();
  if (Status status = detail::checkStart(start, ball, table); !status)
    return status.error();
  return detail::TrajectoryPredictor(ball, table, parameters).run(start);
}

}  // namespace billiard_shot_planner
