#include "linked_pair.hpp"

#include <algorithm>
#include <cmath>

#include "ball_contact_time.hpp"
#include "phase_dynamics.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Longest step (s) of a linked pair; the steps are exact where nothing turns (a pair on one line).
constexpr double MAX_LINK_STEP = 0.01;
/// Shortest step (s) that a turning slip or velocity bounds a step to.
constexpr double MIN_LINK_STEP = 1e-5;
/// Angle (rad) a slip or a velocity may turn in one step while its friction keeps its direction.
constexpr double MAX_TURN = 0.02;
/// Gap (m) that the balls' curved relative motion may open or close within a step (its ends are closed exactly).
constexpr double MAX_GAP_DRIFT = 1e-10;
/// A holding force above −this share of the balls' own accelerations (times m) is none: balls that decelerate
/// alike (both rolling) stay linked at zero force instead of being let go on round-off, where they would meet
/// again at once.
constexpr double FORCE_ROUND_OFF = 1e-9;

Eigen::Vector2d perp(const Eigen::Vector2d& v)
{
  return {-v.y(), v.x()};
}  // ẑ × v

/// How a ball on the cloth answers a push F (N) along `push`: a = free + compliance · F/m · push.
struct Response
{
  Eigen::Vector2d free = Eigen::Vector2d::Zero();
  Eigen::Vector2d push = Eigen::Vector2d::Zero();
  double compliance = 0.0;  ///< 1 sliding, 5/7 rolling (static friction takes 2/7 of the push), 0 held at rest
  MotionPhase phase = MotionPhase::Stationary;
};

Response responseOf(const BallState& s, const Eigen::Vector2d& push, const BallProperties& ball,
                    const MotionParameters& p)
{
  Response r;
  r.push = push;
  r.phase = classify(s, ball.radius);
  if (r.phase == MotionPhase::Sliding)
  {
    r.free = -p.sliding_friction * p.gravity * contactSlip(s, ball.radius).normalized();
    r.compliance = 1.0;
  }
  else if (r.phase == MotionPhase::Rolling)
  {
    r.free = -rollingDeceleration(p) * s.velocity.head<2>().normalized();
    r.compliance = 5.0 / 7.0;
  }
  return r;  // at rest in the plane: held by the cloth until the push overcomes rolling resistance
}

/// A ball whose hop above the cloth (its height and what its upward speed adds) stays within LINK_EXCURSION is on
/// the cloth: the limit's impact lifts a ball that the balls' rubbing contact pushes up, by far less (its speed near
/// μ v, a few 1e-5 m/s, a hop of 1e-10 m). Dropping the hop only dissipates. Other balls are left in the air.
BallState onCloth(BallState s, double radius, double gravity)
{
  const double rise = std::max(s.velocity.z(), 0.0);
  if (s.position.z() - radius + rise * rise / (2.0 * gravity) > LINK_EXCURSION)
    return s;
  s.position.z() = radius;
  s.velocity.z() = 0.0;
  return s;
}

/// The pair with its gap closed: a link met at a graze (a gap within the touching tolerance) or carrying the round-off
/// of its last step starts with the centres exactly `distance` apart, each ball moved by half the gap along the line
/// of centres. A step that starts apart cannot be closed by its force where its free motion does not close it
/// within the step (the force does not pull): the balls would end it approaching, which the next step's constant
/// force overshoots into an overlap.
std::array<BallState, 2> closed(BallState a, BallState b, double distance)
{
  const Eigen::Vector2d d = (b.position - a.position).head<2>();
  const double gap = d.norm() - distance;
  if (std::abs(gap) > BALL_TOUCHING_TOLERANCE)
    return {a, b};
  const Eigen::Vector2d shift = 0.5 * gap * d.normalized();
  a.position.head<2>() += shift;
  b.position.head<2>() -= shift;
  return {a, b};
}

/// The pair's geometry and relative motion at the step's start.
struct Relative
{
  Eigen::Vector2d d, n, w;
  double tangential_speed2;
};

Relative relativeOf(const BallState& a, const BallState& b)
{
  Relative r;
  r.d = (b.position - a.position).head<2>();
  r.n = r.d.normalized();
  r.w = (b.velocity - a.velocity).head<2>();
  r.tangential_speed2 = std::max(r.w.squaredNorm() - std::pow(r.w.dot(r.n), 2), 0.0);
  return r;
}

/// The force that keeps the gap's second derivative at zero: (a_b − a_a)·n + |w_t|²/|d| = 0.
double holdingForce(const Relative& rel, const Response& a, const Response& b, double mass)
{
  const double k = a.compliance + b.compliance;
  if (k == 0.0)
    return 0.0;
  return -mass * ((b.free - a.free).dot(rel.n) + rel.tangential_speed2 / rel.d.norm()) / k;
}

/// The constant force over a step of length h that ends it with the centres exactly `distance` apart.
double closingForce(const Relative& rel, const Response& a, const Response& b, double mass, double distance, double h,
                    double fallback)
{
  const Eigen::Vector2d e = rel.d + rel.w * h + 0.5 * (b.free - a.free) * h * h;
  const double q = 0.5 * (a.compliance + b.compliance) / mass * h * h;
  const double en = e.dot(rel.n);
  const double discriminant = en * en - e.squaredNorm() + distance * distance;
  if (q <= 0.0 || discriminant < 0.0)
    return fallback;
  return std::max((std::sqrt(discriminant) - en) / q, 0.0);
}

Eigen::Vector2d accelerationOf(const Response& r, double force, double mass)
{
  return r.free + r.compliance * force / mass * r.push;
}

/// A ball held at rest starts rolling where its share of the push overcomes rolling resistance.
bool letsGo(Response& r, double force, const BallProperties& ball, const MotionParameters& p)
{
  if (r.compliance != 0.0 || r.phase == MotionPhase::Airborne ||
      5.0 / 7.0 * force / ball.mass <= rollingDeceleration(p))
    return false;
  r.compliance = 5.0 / 7.0;
  r.free = -rollingDeceleration(p) * r.push;
  r.phase = MotionPhase::Rolling;
  return true;
}

/// The end of one ball's step under force `force`: the first of its phase's end, a turn of its friction's
/// direction by MAX_TURN, and its spin's stop.
struct BallStepEnd
{
  double duration = MAX_LINK_STEP;
  MotionEventType event = MotionEventType::Rest;
};

void bound(BallStepEnd& end, double duration, MotionEventType event = MotionEventType::Rest)
{
  if (duration < end.duration)
    end = {duration, event};
}

/// Bounds by a vector x moving at ẋ that friction holds along its direction: its turn, and its zero along it.
void boundByDirection(BallStepEnd& end, const Eigen::Vector2d& x, const Eigen::Vector2d& rate, MotionEventType zero)
{
  const Eigen::Vector2d dir = x.normalized();
  const double along = rate.dot(dir), across = std::abs(rate.dot(perp(dir)));
  if (across > 0.0)
    bound(end, std::max(MAX_TURN * x.norm() / across, MIN_LINK_STEP));
  if (along < 0.0)
    bound(end, -x.norm() / along, zero);
}

BallStepEnd ballStepEnd(const BallState& s, const Response& r, double force, const BallProperties& ball,
                        const MotionParameters& p)
{
  BallStepEnd end;
  const Eigen::Vector2d a = accelerationOf(r, force, ball.mass);
  if (r.phase == MotionPhase::Sliding)
    boundByDirection(end, contactSlip(s, ball.radius),
                     a - 2.5 * p.sliding_friction * p.gravity * (-r.free.normalized()), MotionEventType::SlideToRoll);
  else if (r.phase == MotionPhase::Rolling && s.velocity.head<2>().norm() > REST_SPEED)
    boundByDirection(end, s.velocity.head<2>(), a, MotionEventType::RollToSpin);
  if (std::abs(s.angular_velocity.z()) * ball.radius > REST_SPEED)
    bound(end, std::abs(s.angular_velocity.z()) / spinDeceleration(ball, p), MotionEventType::SpinStop);
  return end;
}

/// Bounds the step where the balls' curved relative motion would drift the gap by MAX_GAP_DRIFT.
double geometricStep(const Relative& rel, const Response& a, const Response& b)
{
  const double wt = std::sqrt(rel.tangential_speed2);
  const double bt = std::abs((b.free - a.free).dot(perp(rel.n)));
  const double jerk = wt * wt * wt / rel.d.squaredNorm() + 3.0 * wt * bt / rel.d.norm();
  const double third = jerk > 0.0 ? std::cbrt(6.0 * MAX_GAP_DRIFT / jerk) : MAX_LINK_STEP;
  // the tangential acceleration alone opens the gap by b_t² τ⁴ / (8 |d|)
  const double fourth = bt > 0.0 ? std::sqrt(std::sqrt(8.0 * rel.d.norm() * MAX_GAP_DRIFT) / bt) : MAX_LINK_STEP;
  return std::min(third, fourth);
}

MotionSegment segmentOf(const BallState& s, const Response& r, double force, double t, const BallProperties& ball,
                        const MotionParameters& p)
{
  MotionSegment segment{r.phase, t, t, s};
  const Eigen::Vector2d a = accelerationOf(r, force, ball.mass);
  segment.acceleration.head<2>() = a;
  if (r.phase == MotionPhase::Sliding)
    segment.angular_acceleration.head<2>() = 2.5 / ball.radius * perp(-r.free);  // (5μ_s g/2R) ẑ × û
  else if (r.phase == MotionPhase::Rolling)
    segment.angular_acceleration.head<2>() = perp(a) / ball.radius;  // keeps ω_xy = ẑ × v / R
  if (std::abs(s.angular_velocity.z()) * ball.radius > REST_SPEED)
    segment.angular_acceleration.z() = -std::copysign(spinDeceleration(ball, p), s.angular_velocity.z());
  return segment;
}
}  // namespace

PairPress pairPress(const MotionSegment& a, const MotionSegment& b, double t)
{
  const BallState sa = a.at(t), sb = b.at(t);
  const Relative rel = relativeOf(sa, sb);
  PairPress press;
  press.normal.head<2>() = rel.n;
  press.approach = -rel.w.dot(rel.n);
  press.press = -(b.acceleration - a.acceleration).head<2>().dot(rel.n) - rel.tangential_speed2 / rel.d.norm();
  return press;
}

bool isSequenceLimit(const PairPress& press)
{
  return press.press > 0.0 && press.approach * press.approach <= 2.0 * press.press * LINK_EXCURSION;
}

LinkStep linkStep(const BallState& a_in, const BallState& b_in, double t, const BallProperties& ball,
                  const MotionParameters& p)
{
  LinkStep step;
  const auto [a, b] =
      closed(onCloth(a_in, ball.radius, p.gravity), onCloth(b_in, ball.radius, p.gravity), 2.0 * ball.radius);
  const Relative rel = relativeOf(a, b);
  Response ra = responseOf(a, -rel.n, ball, p), rb = responseOf(b, rel.n, ball, p);
  if (ra.phase == MotionPhase::Airborne || rb.phase == MotionPhase::Airborne)
    return step;
  double force = holdingForce(rel, ra, rb, ball.mass);
  // Both balls are asked: each may start rolling under the same force.
  const bool a_goes = letsGo(ra, force, ball, p);
  const bool b_goes = letsGo(rb, force, ball, p);
  if (a_goes || b_goes)
    force = holdingForce(rel, ra, rb, ball.mass);
  const double scale = ball.mass * (ra.free.norm() + rb.free.norm() + rel.tangential_speed2 / rel.d.norm());
  if (!(force > -FORCE_ROUND_OFF * scale) || (force <= 0.0 && scale == 0.0))
    return step;
  force = std::max(force, 0.0);
  const double distance = 2.0 * ball.radius;
  BallStepEnd ea = ballStepEnd(a, ra, force, ball, p), eb = ballStepEnd(b, rb, force, ball, p);
  double h = std::min({ea.duration, eb.duration, geometricStep(rel, ra, rb)});
  const double closing = closingForce(rel, ra, rb, ball.mass, distance, h, force);
  ea = ballStepEnd(a, ra, closing, ball, p);
  eb = ballStepEnd(b, rb, closing, ball, p);
  if (std::min(ea.duration, eb.duration) < h)
    h = std::min(ea.duration, eb.duration);
  step.released = false;
  step.duration = h;
  step.force = closingForce(rel, ra, rb, ball.mass, distance, h, force);
  step.segments = {segmentOf(a, ra, step.force, t, ball, p), segmentOf(b, rb, step.force, t, ball, p)};
  step.ends = {ea.duration <= h ? ea.event : MotionEventType::Rest,
               eb.duration <= h ? eb.event : MotionEventType::Rest};
  return step;
}

BallState endLinkedPhase(MotionEventType event, BallState state, double radius)
{
  if (event != MotionEventType::SlideToRoll)
    return snapPhaseEnd(event, state, radius);
  // The friction impulse J = −(2/7) m u at the cloth takes the slip u to zero: Δv = J/m, Δω = −(5/(2mR)) ẑ × J.
  const Eigen::Vector2d u = contactSlip(state, radius);
  state.velocity.head<2>() -= 2.0 / 7.0 * u;
  state.angular_velocity.head<2>() += 5.0 / (7.0 * radius) * perp(u);
  return state;
}

}  // namespace detail
}  // namespace billiard_shot_planner
