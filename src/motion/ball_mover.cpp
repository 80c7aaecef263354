#include "ball_mover.hpp"

#include <cmath>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Landing speed (m/s) below which a touch-down is no impact but round-off: the engine needs an approach.
constexpr double TOUCH_DOWN_SPEED = 1e-9;

/// Cushion speed (m/s) below which a ball that comes back to the cushion it just left is pressed against it: the
/// Zeno sequence of hits has converged (what is left of it lasts some 1e-5 s). Sequences that end with the ball
/// leaving the rail stay far above it (near 1e-3 m/s); those that do not go on towards round-off and, unstopped,
/// through the cushion. The same holds for a ball riding a nose below its centre in the air, each hop shorter than
/// the one before.
constexpr double SUSTAINED_CONTACT_SPEED = 1e-6;

}  // namespace

Deadline deadlineAfter(double seconds)
{
  return std::chrono::steady_clock::now() +
         std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

Status checkMotionSetting(const BallProperties& ball, const Table& table, const MotionParameters& parameters)
{
  if (Status status = firstError({requirePositive(ball.mass, "ball_mass"), requirePositive(ball.radius, "ball_radius"),
                                  validate(parameters), validate(table)});
      !status)
    return status;
  return validateForBall(table, ball.radius);
}

Status checkStart(const BallState& start, const BallProperties& ball, const Table& table,
                  const MotionGeometry& geometry, const std::string& prefix)
{
  if (Status status =
          firstError({requireFinite(start.position, prefix + "position"), requireFinite(start.velocity, prefix + "v"),
                      requireFinite(start.angular_velocity, prefix + "omega"),
                      requirePlausibleSpeed(start.velocity.norm(), prefix + "v"),
                      requirePlausibleSpeed(start.angular_velocity.norm() * ball.radius, prefix + "omega")});
      !status)
    return status;
  const std::string field = prefix + "position";
  const Eigen::Vector2d centre = start.position.head<2>();
  if (geometry.offTable(start.position))
    return invalidArgument(field, "the ball is off the table");
  const double reach = cushionReach(table, ball.radius);
  for (const NosePiece& piece : geometry.noses)
    if (piece.covers(centre) && piece.overlaps(centre, reach, CONTACT_DISTANCE))
      return invalidArgument(field, "the ball overlaps a cushion");
  for (const DropRegion& drop : geometry.drops)
    if ((centre - drop.centre).norm() <= drop.radius)
      return invalidArgument(field, "the ball is inside " + drop.describe());
  return {};
}

BallMover::BallMover(const BallProperties& ball, const Table& table, const MotionGeometry& geometry,
                     const MotionParameters& parameters, const Deadline& deadline)
    : ball_(ball), table_(table), geometry_(geometry), p_(parameters), deadline_(deadline)
{
}

void BallMover::begin(BallState state)
{
  state.position.z() = ball_.radius;
  if (p_.planar || state.velocity.z() < 0.0)
    state.velocity.z() = 0.0;  // planar: the paper's choice; a downward v_z is absorbed by the cloth
  trajectory_.events.push_back({MotionEventType::Start, 0.0, state});
  plan(state, 0.0);
}

double BallMover::nextEventTime() const
{
  return status_ == Status::Moving ? segment_.start_time + end_.duration : std::numeric_limits<double>::infinity();
}

void BallMover::plan(const BallState& state, double t)
{
  ++version_;
  if (static_cast<int>(trajectory_.events.size()) >= p_.max_events || t >= p_.max_time)
    return end(MotionEventType::TimeLimit, MotionOutcome::TimeLimit, t, state);
  const MotionPhase phase = classify(state, ball_.radius);
  if (phase == MotionPhase::Stationary)
  {
    trajectory_.events.push_back({MotionEventType::Rest, t, state});
    trajectory_.outcome = MotionOutcome::Rest;
    segment_ = MotionSegment{MotionPhase::Stationary, t, t, state};
    status_ = Status::Resting;
    return;
  }
  const PhaseMotion motion = phaseMotion(phase, state, ball_, p_);
  segment_ = MotionSegment{phase, t, t, state, motion.acceleration, motion.angular_acceleration};
  end_ = segmentEnd(segment_, motion, t);
  status_ = Status::Moving;
}

Expected<bool> BallMover::runOwnEvent()
{
  const double t = nextEventTime();
  segment_.end_time = t;
  trajectory_.segments.push_back(segment_);
  BallState state = segment_.at(t);
  switch (end_.event)
  {
    case MotionEventType::Pocketed:
      trajectory_.events.push_back(
          {end_.event, t, state, {}, geometry_.drops[static_cast<std::size_t>(end_.pocket)].pocket});
      trajectory_.outcome = MotionOutcome::Pocketed;
      status_ = Status::Ended;
      return true;
    case MotionEventType::TimeLimit:
      end(end_.event, MotionOutcome::TimeLimit, t, state);
      return true;
    case MotionEventType::CushionHit:
    {
      auto ended = hitCushion(end_.piece, end_.contact, state, t);
      if (ended && !ended.value())
        plan(state, t);
      return ended;
    }
    case MotionEventType::Landing:
    {
      auto ended = land(state, t);
      if (ended && !ended.value())
        plan(state, t);
      return ended;
    }
    default:
      state = snapPhaseEnd(end_.event, state, ball_.radius);
      trajectory_.events.push_back({end_.event, t, state});
      plan(state, t);
      return false;
  }
}

void BallMover::closeSegment(double t)
{
  // A resting ball's path holds still from its rest to the hit: the segment makes BallTrajectory::at exact there.
  if (status_ == Status::Moving || t > segment_.start_time)
  {
    segment_.end_time = t;
    trajectory_.segments.push_back(segment_);
  }
}

void BallMover::interrupt(double t, const BallState& after, int other)
{
  closeSegment(t);
  MotionEvent event{MotionEventType::BallCollision, t, after};
  event.ball = other;
  trajectory_.events.push_back(event);
  plan(after, t);
}

void BallMover::continueAt(double t)
{
  if (t > segment_.start_time)
  {
    segment_.end_time = t;
    trajectory_.segments.push_back(segment_);
  }
}

void BallMover::follow(double t, const MotionSegment& next)
{
  continueAt(t);
  ++version_;
  if (static_cast<int>(trajectory_.events.size()) >= p_.max_events || t >= p_.max_time)
    return end(MotionEventType::TimeLimit, MotionOutcome::TimeLimit, t, next.start);
  segment_ = next;
  end_ = segmentEnd(segment_, PhaseMotion{}, t);
  status_ = Status::Moving;
}

void BallMover::release(double t, const BallState& state)
{
  continueAt(t);
  plan(state, t);
}

BallMover::SegmentEnd BallMover::segmentEnd(const MotionSegment& segment, const PhaseMotion& motion, double t) const
{
  SegmentEnd end{motion.end, motion.end_event};
  if (p_.max_time - t < end.duration)
    end = {p_.max_time - t, MotionEventType::TimeLimit};
  if (auto hit = firstCushionHit(segment, geometry_, table_, ball_.radius, end.duration))
    end = {hit->time, MotionEventType::CushionHit, hit->piece, -1, hit->contact};
  if (auto entry = firstPocketEntry(segment, geometry_, end.duration))
    end = {entry->time, MotionEventType::Pocketed, -1, entry->index};
  return end;
}

Expected<bool> BallMover::hitCushion(int piece, NoseContact contact, BallState& state, double t)
{
  const NosePiece& nose = geometry_.noses[static_cast<std::size_t>(piece)];
  if (contact == NoseContact::Over)
  {
    trajectory_.events.push_back({MotionEventType::CushionHit, t, state, geometry_.cushionId(nose)});
    trajectory_.outcome = MotionOutcome::OffTable;  // its bottom above the nose, the ball passes over it
    status_ = Status::Ended;
    return true;
  }
  // Touching the cloth, the ball meets the nose and the cloth at once; a cloth contact that separates from the
  // start takes part only if the impact brings it back.
  const bool on_cloth = state.position.z() <= ball_.radius * (1.0 + 1e-9);
  const Eigen::Vector3d normal = cushionNormal(nose, table_, state.position);
  const Eigen::Vector2d outward = nose.outwardAt(state.position.head<2>());
  auto outward_part = [&](const Eigen::Vector3d& v)
  { return nose.shape == NosePiece::Shape::Line ? nose.line.outwardPart(v) : outward.dot(v.head<2>()); };
  const double approach = -state.velocity.dot(normal);
  if (contact == NoseContact::Pressed ||
      pressedAgainst(piece, on_cloth, on_cloth ? outward_part(state.velocity) : approach))
  {
    trajectory_.events.push_back({MotionEventType::CushionContact, t, state, geometry_.cushionId(nose)});
    trajectory_.outcome = MotionOutcome::AgainstCushion;
    status_ = Status::Ended;
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
  trajectory_.events.push_back({MotionEventType::CushionHit, t, state, geometry_.cushionId(nose)});
  last_hit_ = {piece, on_cloth, on_cloth ? -outward_part(state.velocity) : state.velocity.dot(normal)};
  return false;
}

/// The impact solver's options with what is left of the simulation's wall-clock budget (SolverOptions::
/// max_seconds bounds the whole simulation, all its impacts included).
Expected<SolverOptions> BallMover::impactOptions() const
{
  const double left = std::chrono::duration<double>(deadline_ - std::chrono::steady_clock::now()).count();
  if (!(left > 0.0))
    return Error{ErrorKind::TimeLimitExceeded, "",
                 "the trajectory did not end within " + formatNumber(p_.impact.max_seconds) + " s (" +
                     std::to_string(trajectory_.events.size()) + " events)"};
  SolverOptions options = p_.impact;
  options.max_seconds = left;
  return options;
}

/// Whether the ball has come back to the cushion it last left, on the cloth or in the air as then, both times
/// slower than SUSTAINED_CONTACT_SPEED (on the cloth horizontally, in the air along the contact normal): it is
/// pressed into the rail, by its spin on the cloth, by its weight on a nose below its centre in the air. The hits
/// would go on as a Zeno sequence of ever smaller ones until the last, approaching to round-off, was missed and the
/// ball went through the cushion. Sustained contact is not modelled: the path ends.
bool BallMover::pressedAgainst(int piece, bool on_cloth, double approach) const
{
  return last_hit_.piece == piece && last_hit_.on_cloth == on_cloth &&
         last_hit_.rebound_speed < SUSTAINED_CONTACT_SPEED && approach < SUSTAINED_CONTACT_SPEED;
}

Expected<bool> BallMover::land(BallState& state, double t)
{
  state.position.z() = ball_.radius;
  if (geometry_.offTable(state.position))
  {
    // It flew over a pocket's jaws or the cushion beside them and comes down beyond the rails: off the table.
    trajectory_.events.push_back({MotionEventType::Landing, t, state});
    trajectory_.outcome = MotionOutcome::OffTable;
    status_ = Status::Ended;
    return true;
  }
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

void BallMover::end(MotionEventType event, MotionOutcome outcome, double t, const BallState& state)
{
  trajectory_.events.push_back({event, t, state});
  trajectory_.outcome = outcome;
  segment_ = MotionSegment{MotionPhase::Stationary, t, t, state};
  status_ = Status::Ended;
}

}  // namespace detail
}  // namespace billiard_shot_planner
