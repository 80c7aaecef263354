#include "table_events.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "ball_contact_time.hpp"
#include "phase_dynamics.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// The zero of f in the bracket [lo, hi] (f changes sign between them), located with TOMS 748 to 1e-13 s: the upper
/// end of the final bracket, so that the event has numerically happened.
template <class Function>
double locateEvent(Function f, double lo, double hi, double f_lo, double f_hi)
{
  std::uintmax_t iterations = 100;
  auto tolerance = [](double a, double b) { return b - a <= 1e-13 * std::max(1.0, b); };
  return boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, tolerance, iterations).second;
}

/// The ball's centre's motion across the cloth relative to a fixed `point`: its offset, velocity and acceleration with
/// z = 0, as the balls' contact search takes the motion of one ball relative to another at rest.
struct PlanarMotion
{
  Eigen::Vector3d offset, velocity, acceleration;
};

PlanarMotion planarMotionFrom(const MotionSegment& segment, const Eigen::Vector2d& point)
{
  return {{segment.start.position.x() - point.x(), segment.start.position.y() - point.y(), 0.0},
          {segment.start.velocity.x(), segment.start.velocity.y(), 0.0},
          {segment.acceleration.x(), segment.acceleration.y(), 0.0}};
}

/// The first time in [0, horizon] at which the centre, moving as `m`, comes within `distance` of the point while
/// approaching it (earliestBallContact's contact).
std::optional<double> firstApproachWithin(const PlanarMotion& m, double distance, double horizon)
{
  return earliestBallContact(m.offset, m.velocity, m.acceleration, distance, horizon);
}

/// The roots in (lo, hi] of c + b τ + ½ a τ² = 0, in order.
std::vector<double> quadraticRoots(double c, double b, double a, double lo, double hi)
{
  std::vector<double> roots;
  auto keep = [&](double tau)
  {
    if (tau > lo && tau <= hi)
      roots.push_back(tau);
  };
  if (std::abs(a) < 1e-300)
  {
    if (b != 0.0)
      keep(-c / b);
    return roots;
  }
  const double discriminant = b * b - 2.0 * a * c;
  if (discriminant < 0.0)
    return roots;
  // Numerically stable pair of roots of ½a τ² + b τ + c.
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q != 0.0)
  {
    keep(q / a);
    keep(2.0 * c / q);
  }
  else
  {
    keep(0.0);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

/// The smallest root in (lo, hi] of c + b τ + ½ a τ² = 0 at which the function rises through zero, if any.
std::optional<double> firstRisingRoot(double c, double b, double a, double lo, double hi)
{
  for (const double tau : quadraticRoots(c, b, a, lo, hi))
    if (b + a * tau >= 0.0)
      return tau;
  return std::nullopt;
}
}  // namespace

namespace
{
/// Guard samples of an airborne ball's approach to a nose, over the stretch where its centre is within a radius
/// of the nose line horizontally (a ball at 5 m/s covers a radius in under 6 ms).
constexpr int NOSE_SAMPLES = 32;

/// Samples before the first guard sample after a ball leaves a nose it touches, each half the next: it may come back
/// after any fraction of the flight (the next hit of a Zeno sequence of hops), and 2^-48 of a flight is below the
/// resolution of the events.
constexpr int RETURN_SAMPLES = 48;

/// The ball's motion relative to a nose at an instant, along the contact normal.
struct Approach
{
  double overlap;  ///< m: > 0 inside the nose, 0 touching it
  double speed;    ///< m/s: > 0 approaching
  double rate;     ///< m/s²: how fast the approach grows
};

/// Whether a ball touching a nose meets it: it moves into it (an impact), or it does not move away and its motion
/// presses it in, its approach becoming resolvable within `remaining` seconds (sustained contact begins). One that
/// touches it slower than REST_SPEED and is not pressed in moves along it.
std::optional<NoseContact> contactOf(const Approach& approach, double remaining)
{
  if (approach.speed > REST_SPEED)
    return NoseContact::Impact;
  if (approach.speed >= -REST_SPEED && approach.rate > 0.0 && approach.speed + approach.rate * remaining > REST_SPEED)
    return NoseContact::Pressed;
  return std::nullopt;
}

struct NoseHit
{
  double time;
  NoseContact contact;
};

/// The first rise through zero of `overlap` over [start, end], sampled NOSE_SAMPLES times (after `refinements`
/// samples ever closer to the start, each half the next) and located with TOMS 748, at which `contact_at` finds a
/// contact.
template <class Overlap, class ContactAt>
std::optional<NoseHit> firstSampledContact(Overlap overlap, ContactAt contact_at, double start, double f_start,
                                           double end, int refinements)
{
  if (!(end > start))
    return std::nullopt;
  const double first = (end - start) / NOSE_SAMPLES;
  double lo = start, f_lo = f_start;
  for (int k = 1 - refinements; k <= NOSE_SAMPLES; ++k)
  {
    const double hi = k <= 0 ? start + std::ldexp(first, k - 1) : start + first * k, f_hi = overlap(hi);
    if (f_lo <= 0.0 && f_hi > 0.0)
    {
      const double tau = locateEvent(overlap, lo, hi, f_lo, f_hi);
      if (const auto contact = contact_at(tau))
        return NoseHit{tau, *contact};
      // A rise of round-off, or a touch slower than REST_SPEED that turns away: no contact.
    }
    lo = hi;
    f_lo = f_hi;
  }
  return std::nullopt;
}

/// On the cloth the ball's centre stays at height R, so it touches the nose exactly when its centre reaches the
/// line at `cushionReach` from the edge: a root of a quadratic. A ball touching the nose at the start (to
/// CONTACT_DISTANCE, or inside it) meets it at once if it moves or is pressed into it; the root where a ball that
/// touches it moves away falls through zero and is no contact.
std::optional<NoseHit> onClothContact(const MotionSegment& segment, const Nose& nose, double reach, double horizon)
{
  // g(τ) = outward·x(τ) − (edge − reach), the overlap measured horizontally: rises through zero when the ball
  // reaches the nose moving towards it.
  const double c = nose.outwardPart(segment.start.position) - (nose.edge - reach);
  const double b = nose.outwardPart(segment.start.velocity);
  const double a = nose.outwardPart(segment.acceleration);
  if (c >= -CONTACT_DISTANCE)
    if (const auto contact = contactOf({c, b, a}, horizon))
      return NoseHit{0.0, *contact};
  const auto tau = firstRisingRoot(c, b, a, 0.0, horizon);
  if (!tau)
    return std::nullopt;
  if (const auto contact = contactOf({0.0, b + a * *tau, a}, horizon - *tau))
    return NoseHit{*tau, *contact};
  return std::nullopt;  // its path touches the nose line slower than REST_SPEED and turns away: it moves along it
}

/// In the air: p = (u, w) runs from the nose line to the ball's centre across the rail, u horizontally into the
/// table, w up; the ball touches the nose when |p| = R.
Approach airborneApproach(const MotionSegment& segment, const Nose& nose, const Table& table, double radius, double tau)
{
  const BallState s = segment.at(segment.start_time + tau);
  const Eigen::Vector2d p(nose.edge - nose.outwardPart(s.position), s.position.z() - table.cushion_height);
  const Eigen::Vector2d dp(-nose.outwardPart(s.velocity), s.velocity.z());
  const Eigen::Vector2d ddp(-nose.outwardPart(segment.acceleration), segment.acceleration.z());
  const double d = p.norm();
  const Eigen::Vector2d n = p / d;
  const double separating = n.dot(dp);
  // d|p|/dτ = n·p', d²|p|/dτ² = (|p'|² − (n·p')²)/|p| + n·p'': the motion across the normal carries the centre away
  // from the nose line, gravity pulls a ball above the nose onto it.
  const double across = std::max(dp.squaredNorm() - separating * separating, 0.0);
  return {radius - d, -separating, -(across / d + n.dot(ddp))};
}

/// In the air the ball touches the nose when its centre comes within R of the nose line, which can only happen
/// while the centre is within R of the edge horizontally: the overlap R² − u² − w² is sampled there and its rise
/// located with TOMS 748. A ball touching the nose at the start meets it at once if it moves or is pressed into it;
/// one moving away is followed from the start with samples ever closer to it, so that a quick return is not
/// stepped over. If the centre reaches the nose line without touching the nose, the ball passes over it: its bottom
/// is then above the nose, and it leaves the table.
std::optional<NoseHit> airborneContact(const MotionSegment& segment, const Nose& nose, const Table& table,
                                       double radius, double horizon)
{
  const double c = nose.outwardPart(segment.start.position) - nose.edge;
  const double b = nose.outwardPart(segment.start.velocity);
  const double a = nose.outwardPart(segment.acceleration);
  const auto passes = c >= 0.0 ? std::optional<double>(0.0) : firstRisingRoot(c, b, a, 0.0, horizon);
  const double end = passes ? *passes : horizon;
  auto overlap = [&](double tau)
  {
    const Eigen::Vector3d centre = segment.at(segment.start_time + tau).position;
    const double u = nose.edge - nose.outwardPart(centre), w = centre.z() - table.cushion_height;
    return radius * radius - u * u - w * w;
  };
  auto contact_at = [&](double tau)
  { return contactOf(airborneApproach(segment, nose, table, radius, tau), horizon - tau); };

  double start = 0.0, f_start = 0.0;
  int refinements = 0;
  const Approach initial = airborneApproach(segment, nose, table, radius, 0.0);
  if (initial.overlap >= -CONTACT_DISTANCE)
  {
    if (const auto contact = contactOf(initial, horizon))
      return NoseHit{0.0, *contact};
    refinements = RETURN_SAMPLES;  // leaving it: the overlap falls from zero
  }
  else
  {
    if (c + radius < 0.0)
    {
      const auto near = firstRisingRoot(c + radius, b, a, 0.0, end);
      start = near ? *near : end;
    }
    f_start = overlap(start);
  }
  if (const auto hit = firstSampledContact(overlap, contact_at, start, f_start, end, refinements))
    return hit;
  if (!passes)
    return std::nullopt;
  if (segment.at(segment.start_time + *passes).position.z() - table.cushion_height >= radius - CONTACT_DISTANCE)
    return NoseHit{*passes, NoseContact::Over};
  // The centre reaches the nose line with the ball's bottom below the nose, an overlap no sample resolved: it must
  // not go through, so it meets the nose there.
  const auto contact = contact_at(*passes);
  return NoseHit{*passes, contact ? *contact : NoseContact::Pressed};
}
}  // namespace

namespace
{
/// The ball's motion relative to a round piece at an instant: its centre's horizontal distance ρ from the piece's
/// centre and that distance's first two derivatives.
struct RadialMotion
{
  Eigen::Vector2d direction;  ///< unit, from the piece's centre towards the ball's
  double distance, rate, rate_slope;
};

RadialMotion radialMotion(const MotionSegment& segment, const NosePiece& piece, double tau)
{
  const BallState s = segment.at(segment.start_time + tau);
  const Eigen::Vector2d q = s.position.head<2>() - piece.centre;
  const Eigen::Vector2d dq = s.velocity.head<2>(), ddq = segment.acceleration.head<2>();
  const double rho = q.norm();
  const Eigen::Vector2d direction = q / rho;
  const double rate = direction.dot(dq);
  // ρ'' = (|q'|² − ρ'²)/ρ + q̂·q'': the motion across the radius carries the centre away, the acceleration along it.
  return {direction, rho, rate, (dq.squaredNorm() - rate * rate) / rho + direction.dot(ddq)};
}

/// On the cloth a ball touches a round piece when its centre comes within the piece's radius plus `reach` of the
/// piece's centre: the balls' contact search finds that moment exactly.
std::optional<NoseHit> onClothRoundContact(const MotionSegment& segment, const NosePiece& piece, double reach,
                                           double horizon)
{
  const auto tau = firstApproachWithin(planarMotionFrom(segment, piece.centre), piece.radius + reach, horizon);
  if (!tau)
    return std::nullopt;
  const RadialMotion m = radialMotion(segment, piece, *tau);
  if (const auto contact = contactOf({piece.radius + reach - m.distance, -m.rate, -m.rate_slope}, horizon - *tau))
    return NoseHit{*tau, *contact};
  return std::nullopt;
}

/// In the air: in the vertical plane through the piece's centre and the ball's, p = (ρ − r, z − h) runs from the
/// nose to the ball's centre; the ball touches the nose when |p| = R.
Approach airborneRoundApproach(const MotionSegment& segment, const NosePiece& piece, const Table& table, double radius,
                               double tau)
{
  const RadialMotion m = radialMotion(segment, piece, tau);
  const BallState s = segment.at(segment.start_time + tau);
  const double u = m.distance - piece.radius, w = s.position.z() - table.cushion_height;
  const double dw = s.velocity.z(), ddw = segment.acceleration.z();
  const double d = std::hypot(u, w);
  const double rate = (u * m.rate + w * dw) / d;
  const double slope = (m.rate * m.rate + u * m.rate_slope + dw * dw + w * ddw - rate * rate) / d;
  return {radius - d, -rate, -slope};
}

/// In the air a ball can touch a round piece only once its centre is within the piece's radius plus R of the piece's
/// centre horizontally: from there the overlap R² − (ρ − r)² − (z − h)² is sampled as for a straight nose.
std::optional<NoseHit> airborneRoundContact(const MotionSegment& segment, const NosePiece& piece, const Table& table,
                                            double radius, double horizon)
{
  auto overlap = [&](double tau)
  {
    const Eigen::Vector3d centre = segment.at(segment.start_time + tau).position;
    const double u = (centre.head<2>() - piece.centre).norm() - piece.radius, w = centre.z() - table.cushion_height;
    return radius * radius - u * u - w * w;
  };
  auto contact_at = [&](double tau)
  { return contactOf(airborneRoundApproach(segment, piece, table, radius, tau), horizon - tau); };
  const Approach initial = airborneRoundApproach(segment, piece, table, radius, 0.0);
  if (initial.overlap >= -CONTACT_DISTANCE)
  {
    if (const auto contact = contactOf(initial, horizon))
      return NoseHit{0.0, *contact};
    return firstSampledContact(overlap, contact_at, 0.0, 0.0, horizon, RETURN_SAMPLES);
  }
  double start = 0.0;
  const PlanarMotion planar = planarMotionFrom(segment, piece.centre);
  if (planar.offset.norm() > piece.radius + radius)
  {
    const auto near = firstApproachWithin(planar, piece.radius + radius, horizon);
    if (!near)
      return std::nullopt;
    start = *near;
  }
  // In the air the centre moves uniformly across the cloth: it leaves the circle of r + R at the later root of the
  // quadratic |q + v τ|² = (r + R)², and the samples need not reach further.
  double end = horizon;
  if (segment.acceleration.head<2>().isZero())
  {
    const Eigen::Vector2d q = planar.offset.head<2>(), v = planar.velocity.head<2>();
    const double reach_out = piece.radius + radius;
    const std::vector<double> roots =
        quadraticRoots(q.squaredNorm() - reach_out * reach_out, 2.0 * q.dot(v), 2.0 * v.squaredNorm(),
                       -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
    if (!roots.empty() && roots.back() > start)
      end = std::min(end, roots.back());
  }
  return firstSampledContact(overlap, contact_at, start, overlap(start), end, 0);
}

/// The stretches of [0, horizon] over which a straight piece covers the ball's centre: where the centre's place
/// along the piece, a quadratic in time, lies within its extent. An infinite rail covers it throughout.
std::vector<std::pair<double, double>> coverWindows(const MotionSegment& segment, const NosePiece& piece,
                                                    double horizon)
{
  if (!std::isfinite(piece.from) && !std::isfinite(piece.to))
    return {{0.0, horizon}};
  auto along = [&](const Eigen::Vector3d& v) { return piece.tangent.x() * v.x() + piece.tangent.y() * v.y(); };
  const double c = along(segment.start.position), b = along(segment.start.velocity), a = along(segment.acceleration);
  std::vector<double> points{0.0};
  for (const double end : {piece.from, piece.to})
    for (const double tau : quadraticRoots(c - end, b, a, 0.0, horizon))
      points.push_back(tau);
  points.push_back(horizon);
  std::sort(points.begin(), points.end());
  std::vector<std::pair<double, double>> windows;
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    const double middle = 0.5 * (points[k - 1] + points[k]);
    if (piece.covers(segment.at(segment.start_time + middle).position.head<2>()))
      windows.emplace_back(points[k - 1], points[k]);
  }
  return windows;
}

/// The segment from `offset` after its start on.
MotionSegment laterPart(const MotionSegment& segment, double offset)
{
  if (offset == 0.0)
    return segment;
  MotionSegment part = segment;
  part.start = segment.at(segment.start_time + offset);
  part.start_time = segment.start_time + offset;
  return part;
}

/// A straight piece's first contact: searched stretch by stretch where the piece covers the ball, so that a contact
/// with its line beyond its ends (a ball in a pocket's mouth, on the line of the rail beside it) neither counts nor
/// hides the contact that follows once the ball is alongside it.
std::optional<NoseHit> lineContact(const MotionSegment& segment, const NosePiece& piece, const Table& table,
                                   double radius, double reach, double horizon)
{
  for (const auto& [from, to] : coverWindows(segment, piece, horizon))
  {
    const MotionSegment part = laterPart(segment, from);
    const auto hit = segment.phase == MotionPhase::Airborne
                         ? airborneContact(part, piece.line, table, radius, to - from)
                         : onClothContact(part, piece.line, reach, to - from);
    if (hit)
      return NoseHit{from + hit->time, hit->contact};
  }
  return std::nullopt;
}

std::optional<NoseHit> pieceContact(const MotionSegment& segment, const NosePiece& piece, const Table& table,
                                    double radius, double reach, double horizon)
{
  if (piece.shape == NosePiece::Shape::Line)
    return lineContact(segment, piece, table, radius, reach, horizon);
  return segment.phase == MotionPhase::Airborne ? airborneRoundContact(segment, piece, table, radius, horizon)
                                                : onClothRoundContact(segment, piece, reach, horizon);
}
}  // namespace

Eigen::Vector3d cushionNormal(const NosePiece& piece, const Table& table, const Eigen::Vector3d& centre)
{
  Eigen::Vector3d normal;
  if (piece.shape == NosePiece::Shape::Line)
  {
    // From the nose line, into the table; adding +0 leaves a rail's normal exactly along its axis (no −0 across it).
    normal.head<2>() =
        (piece.line.outwardPart(centre) - piece.line.edge) * piece.line.outward + Eigen::Vector2d::Zero();
  }
  else
  {
    const Eigen::Vector2d from_centre = centre.head<2>() - piece.centre;
    const double rho = from_centre.norm();
    normal.head<2>() = from_centre * ((rho - piece.radius) / rho);
  }
  normal.z() = centre.z() - table.cushion_height;
  return normal.normalized();
}

std::vector<int> touchedNoses(const Eigen::Vector3d& centre, const MotionGeometry& geometry, const Table& table,
                              double radius)
{
  std::vector<int> touched;
  std::vector<Eigen::Vector3d> normals;
  for (std::size_t i = 0; i < geometry.noses.size(); ++i)
  {
    const NosePiece& piece = geometry.noses[i];
    if (!piece.covers(centre.head<2>()) ||
        std::hypot(piece.across(centre.head<2>()), centre.z() - table.cushion_height) > radius + CONTACT_DISTANCE)
      continue;
    // Pieces that join where the ball touches both meet it at one point, along one normal: one contact.
    const Eigen::Vector3d normal = cushionNormal(piece, table, centre);
    if (std::none_of(normals.begin(), normals.end(), [&](const auto& n) { return n.dot(normal) > 1.0 - 1e-12; }))
    {
      touched.push_back(static_cast<int>(i));
      normals.push_back(normal);
    }
  }
  return touched;
}

std::optional<CushionCrossing> firstCushionHit(const MotionSegment& segment, const MotionGeometry& geometry,
                                               const Table& table, double radius, double horizon)
{
  const double reach = cushionReach(table, radius);
  std::optional<CushionCrossing> best;
  for (std::size_t i = 0; i < geometry.noses.size(); ++i)
  {
    const NosePiece& piece = geometry.noses[i];
    const auto hit = pieceContact(segment, piece, table, radius, reach, horizon);
    if (hit && (!best || hit->time < best->time) &&
        piece.covers(segment.at(segment.start_time + hit->time).position.head<2>()))
      best = CushionCrossing{hit->time, static_cast<int>(i), hit->contact};
  }
  return best;
}

std::optional<double> firstCircleEntry(const MotionSegment& segment, const Eigen::Vector2d& centre, double radius,
                                       double horizon)
{
  const PlanarMotion planar = planarMotionFrom(segment, centre);
  if (!(planar.offset.norm() > radius))
    return 0.0;
  // The contact search isolates the roots of the quartic |d|² − radius² exactly.
  return firstApproachWithin(planar, radius, horizon);
}

std::optional<Crossing> firstPocketEntry(const MotionSegment& segment, const MotionGeometry& geometry, double horizon)
{
  std::optional<Crossing> best;
  for (std::size_t i = 0; i < geometry.drops.size(); ++i)
  {
    const DropRegion& drop = geometry.drops[i];
    const auto entry = firstCircleEntry(segment, drop.centre, drop.radius, best ? best->time : horizon);
    if (entry && *entry == 0.0)
      return Crossing{0.0, static_cast<int>(i)};
    if (entry)
      best = Crossing{*entry, static_cast<int>(i)};
  }
  return best;
}

}  // namespace detail
}  // namespace billiard_shot_planner
