// The earliest contact of two balls in constant-acceleration phases (src/motion/ball_contact_time.cpp): hand cases
// against closed-form times from the geometry, then 100 000 random cases against a brute force in long double (a
// fine grid, each cell's extremum of the gap located from the sign of d·d', bisection of the first crossing),
// near-tangent and near-double roots included on purpose. The answer must never come at a time at which the gap
// opens.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

#include "../../src/motion/ball_contact_time.hpp"

namespace bsp = billiard_shot_planner;
using bsp::detail::BALL_TOUCHING_TOLERANCE;
using bsp::detail::earliestBallContact;
using Eigen::Vector3d;

namespace
{
const double R = 0.028575, D = 2.0 * R, G = 9.81, TOL = BALL_TOUCHING_TOLERANCE;
const double INF = std::numeric_limits<double>::infinity();
const Vector3d ZERO = Vector3d::Zero();

double gapAt(const Vector3d& dp, const Vector3d& dv, const Vector3d& da, double t)
{
  return bsp::detail::ballGap(dp, dv, da, D, t);
}
}  // namespace

TEST(BallContactTime, HeadOnAtConstantSpeed)
{
  const auto t = earliestBallContact({1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, ZERO, D, 10.0);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, (1.0 - D) / 2.0, 1e-15);
  // Along an oblique direction in space, and with no horizon at all.
  const Vector3d u = Vector3d(0.3, -0.5, 0.2).normalized();
  const auto oblique = earliestBallContact(1.7 * u, -0.35 * u, ZERO, D, INF);
  ASSERT_TRUE(oblique);
  EXPECT_NEAR(*oblique, (1.7 - D) / 0.35, 1e-14);
  EXPECT_LE(gapAt(1.7 * u, -0.35 * u, ZERO, *oblique), 0.0);
}

TEST(BallContactTime, HorizonCutsOff)
{
  const double contact = (1.0 - D) / 2.0;
  EXPECT_FALSE(earliestBallContact({1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, ZERO, D, contact * (1.0 - 1e-6)));
  const double within = contact * (1.0 - 1e-10);  // 9.4e-11 m apart at the horizon, approaching: a contact there
  EXPECT_EQ(earliestBallContact({1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, ZERO, D, within), within);
  EXPECT_FALSE(earliestBallContact({1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, ZERO, D, 0.0));
  const auto t = earliestBallContact({1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, ZERO, D, contact * (1.0 + 1e-12));
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, contact, 1e-15);
  EXPECT_FALSE(earliestBallContact({1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, ZERO, D, -1.0));
  EXPECT_FALSE(earliestBallContact({1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, ZERO, D, NAN));
}

// Ball i rolls towards ball j at rest, decelerating at α: it stops after v²/(2α), at rest = v/α, the phase's end.
TEST(BallContactTime, RollingToRestShortOfOrTouchingAnotherBall)
{
  const double v = 1.2, alpha = 0.2, rest = v / alpha, travel = v * v / (2.0 * alpha);
  auto contact = [&](double gap_at_start) {
    return earliestBallContact({D + gap_at_start, 0.0, 0.0}, {-v, 0.0, 0.0}, {alpha, 0.0, 0.0}, D, rest);
  };
  EXPECT_FALSE(contact(travel + 1e-6));
  EXPECT_FALSE(contact(travel + 2.0 * TOL));  // stops beyond the tolerance: a miss
  const auto graze = contact(travel + 0.5 * TOL);
  ASSERT_TRUE(graze);  // stops within the tolerance: a graze at rest, for the resolver
  EXPECT_EQ(*graze, rest);
  const auto touching = contact(travel);
  ASSERT_TRUE(touching);
  EXPECT_NEAR(*touching, rest, 2e-7);  // the gap is ½α(rest − t)²: a double root, to √(round-off / α)
  const double short_by = 1e-3;        // reaches it still moving: v t − ½α t² = travel − short_by
  const auto hit = contact(travel - short_by);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(*hit, (v - std::sqrt(2.0 * alpha * short_by)) / alpha, 1e-12);
}

TEST(BallContactTime, CutAtAnOffset)
{
  const double b = 0.7 * D, length = 0.8, v = 3.0;  // centres meet at x = √(D² − b²) along the path
  const auto t = earliestBallContact({length, b, 0.0}, {-v, 0.0, 0.0}, ZERO, D, 1.0);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, (length - std::sqrt((D - b) * (D + b))) / v, 1e-15);
}

TEST(BallContactTime, TangentGrazeOnParallelPaths)
{
  const double length = 0.8, v = 3.0;
  auto contact = [&](double offset) {
    return earliestBallContact({length, offset, 0.0}, {-v, 0.0, 0.0}, ZERO, D, 1.0);
  };
  const auto exact = contact(D);  // closest approach exactly D at length/v: a graze or a crossing by round-off
  ASSERT_TRUE(exact);
  EXPECT_NEAR(*exact, length / v, 1e-8);
  EXPECT_LE(gapAt({length, D, 0.0}, {-v, 0.0, 0.0}, ZERO, *exact), 1e-15);
  const auto graze = contact(D + 0.5 * TOL);
  ASSERT_TRUE(graze);
  EXPECT_NEAR(*graze, length / v, 1e-15);
  EXPECT_FALSE(contact(D + 2.0 * TOL));
  // Just inside: the crossing comes 8e-8 m before the closest approach, where the gap closes at only 4e-6 m/s; the
  // round-off of the gap (1e-17 m) makes 3e-12 s.
  const double b = D * (1.0 - 1e-12);
  const auto inside = contact(b);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(*inside, (length - std::sqrt((D - b) * (D + b))) / v, 3e-12);
  EXPECT_LT(*inside, length / v);
}

// Ball i slides at 2 m/s decelerating at 1.5 m/s² towards ball j rolling away at 0.5 m/s decelerating at 0.1 m/s²:
// the relative position is L − 1.5 t + 0.7 t², a quadratic.
TEST(BallContactTime, DeceleratingTowardsABallMovingAway)
{
  auto contact = [](double length, double horizon) {
    return earliestBallContact({length, 0.0, 0.0}, {-1.5, 0.0, 0.0}, {1.4, 0.0, 0.0}, D, horizon);
  };
  const double length = 0.5, c = length - D;  // 0.7 t² − 1.5 t + c = 0, the smaller root, in the stable form
  const double expected = 2.0 * c / (1.5 + std::sqrt(1.5 * 1.5 - 4.0 * 0.7 * c));
  for (const double horizon : {1.2, INF})
  {
    const auto t = contact(length, horizon);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, expected, 1e-15);
  }
  EXPECT_FALSE(contact(1.0, 1.2));  // its closest approach is 0.196 m
  EXPECT_FALSE(contact(1.0, INF));  // (the formula has the balls part again after it)
}

// Ball i jumps from the cloth and comes down onto ball j at rest: placed so that at tc the centres are D apart at
// the elevation θ, ball i above and behind ball j, descending.
TEST(BallContactTime, JumpLandsOntoABall)
{
  const double vx = 2.0, tc = 0.3, theta = 0.7;
  const double vz = (D * std::sin(theta) + 0.5 * G * tc * tc) / tc, x = vx * tc + D * std::cos(theta);
  const Vector3d dp(x, 0.0, 0.0), dv(-vx, 0.0, -vz), da(0.0, 0.0, G);  // ball j relative to ball i
  const double landing = 2.0 * vz / G;
  const auto t = earliestBallContact(dp, dv, da, D, landing);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, tc, 1e-14);
  for (int k = 0; k < 1000; ++k)  // no earlier contact
    EXPECT_GT(gapAt(dp, dv, da, tc * k / 1000.0), 0.0);
}

TEST(BallContactTime, TouchingAtTheStart)
{
  const Vector3d touching(D, 0.0, 0.0);
  EXPECT_EQ(earliestBallContact(touching, {-1.0, 0.0, 0.0}, ZERO, D, 1.0), 0.0);  // approaching
  EXPECT_EQ(earliestBallContact(touching + Vector3d(0.5 * TOL, 0, 0), {-1.0, 0.3, 0.0}, ZERO, D, 1.0), 0.0);
  EXPECT_EQ(earliestBallContact(touching, ZERO, {-1.0, 0.0, 0.0}, D, 1.0), 0.0);  // at rest, pressed together
  EXPECT_FALSE(earliestBallContact(touching, {1.0, 0.0, 0.0}, ZERO, D, 1.0));     // separating
  EXPECT_FALSE(earliestBallContact(touching, ZERO, ZERO, D, 1.0));                // at rest
  EXPECT_FALSE(earliestBallContact(touching, ZERO, {1.0, 0.0, 0.0}, D, 1.0));     // pulled apart
  // Sliding past each other: the inward acceleration decides, |d|² = D² + (1 + D α) t² + ¼α² t⁴ (α = −1 or −100).
  EXPECT_FALSE(earliestBallContact(touching, {0.0, 1.0, 0.0}, {-1.0, 0.0, 0.0}, D, 1.0));
  EXPECT_EQ(earliestBallContact(touching, {0.0, 1.0, 0.0}, {-100.0, 0.0, 0.0}, D, 1.0), 0.0);
  // Sliding past each other at the touch: the normal speed is round-off, the tangential speed separates them.
  const double angle = 0.3;
  const Vector3d normal(std::cos(angle), std::sin(angle), 0.0), tangent(-std::sin(angle), std::cos(angle), 0.0);
  EXPECT_FALSE(earliestBallContact(D * normal, 2.0 * tangent, ZERO, D, 1.0));
  // Separating, then pulled back: D + t − t² is D again at t = 1.
  const auto back = earliestBallContact(touching, {1.0, 0.0, 0.0}, {-2.0, 0.0, 0.0}, D, 2.0);
  ASSERT_TRUE(back);
  EXPECT_NEAR(*back, 1.0, 1e-15);
  // Overlapping (the caller's error): 0 if approaching, else when they begin to approach, here at t = 0.5.
  const Vector3d overlapping(0.9 * D, 0.0, 0.0);
  EXPECT_EQ(earliestBallContact(overlapping, {-1.0, 0.0, 0.0}, ZERO, D, 1.0), 0.0);
  const auto turning = earliestBallContact(overlapping, {0.01, 0.0, 0.0}, {-0.02, 0.0, 0.0}, D, 2.0);
  ASSERT_TRUE(turning);
  EXPECT_NEAR(*turning, 0.5, 1e-15);
}

namespace
{
/// The same relative motion in long double, for the brute force.
struct Exact
{
  long double p[3], v[3], a[3];

  Exact(const Vector3d& dp, const Vector3d& dv, const Vector3d& da)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] = dp[k];
      v[k] = dv[k];
      a[k] = da[k];
    }
  }

  /// The gap at t and the derivatives of ½|d|² there: the rate d·d' and its slope and curvature.
  struct Sample
  {
    long double t, gap, rate, slope, curvature, speed;  ///< speed |d'|
  };

  Sample at(long double t) const
  {
    long double d[3], w[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = p[k] + t * v[k] + 0.5L * t * t * a[k];
      w[k] = v[k] + t * a[k];
    }
    return {t,
            std::sqrt(dot(d, d)) - static_cast<long double>(D),
            dot(d, w),
            dot(w, w) + dot(d, a),
            3.0L * dot(w, a),
            std::sqrt(dot(w, w))};
  }
  long double gap(long double t) const { return at(t).gap; }
  long double rate(long double t) const
  {
    long double r = 0.0L;
    for (int k = 0; k < 3; ++k)
      r += (p[k] + t * v[k] + 0.5L * t * t * a[k]) * (v[k] + t * a[k]);
    return r;
  }
  long double distance(long double t) const { return at(t).gap + static_cast<long double>(D); }

  static long double dot(const long double* x, const long double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
  static long double norm(const long double* x) { return std::sqrt(dot(x, x)); }
  /// The size of the terms that cancel in the gap at t: its round-off in double is some 1e-16 of it.
  long double scale(long double t) const { return norm(p) + t * norm(v) + 0.5L * t * t * norm(a); }
};

struct Reference
{
  std::optional<long double> time;
  bool ambiguous = false;  ///< a decisive gap or derivative within round-off of its threshold
};

bool oppositeSigns(long double x, long double y)
{
  return (x < 0.0L && y > 0.0L) || (x > 0.0L && y < 0.0L);
}

template <class F>
long double bisect(F f, long double lo, long double hi)  // f changes sign on [lo, hi]: the end past the change
{
  const bool rising = f(lo) <= 0.0L;
  for (int i = 0; i < 200; ++i)
  {
    const long double mid = 0.5L * (lo + hi);
    if (mid <= lo || mid >= hi)
      break;
    ((f(mid) > 0.0L) != rising ? lo : hi) = mid;
  }
  return hi;
}

/// The brute force: a grid of `cells` cells on [0, horizon] plus the given times. A cell across which the slope or
/// the curvature of d·d' changes sign may hide two extrema of the gap: it is split into 16, three times over. Each
/// cell is then split where d·d' changes sign (an extremum of the gap, located by bisection), and the definition
/// of contact applied piece by piece in time.
class BruteForce
{
public:
  BruteForce(const Exact& m, double horizon, const std::vector<double>& hints, int cells) : m_(m)
  {
    for (int k = 0; k <= cells; ++k)
      grid_.push_back(static_cast<long double>(horizon) * k / cells);
    for (double t : hints)
      if (t > 0.0 && t < horizon)
        grid_.insert(std::upper_bound(grid_.begin(), grid_.end(), static_cast<long double>(t)), t);
  }

  Reference contact()
  {
    const long double g0 = m_.gap(0.0L);
    touching_ = g0 <= TOL;
    ref_.ambiguous = std::abs(g0 - TOL) <= band(0.0L);
    if (touching_ && approachingAtStart())
    {
      ref_.time = 0.0L;
      return ref_;
    }
    // |d'| is convex in t: at most its larger end value, so the gap needs (gap − tolerance) / that long to come
    // within the tolerance. The cells before decide nothing: skip them.
    const long double top_speed = std::max(m_.at(0.0L).speed, m_.at(grid_.back()).speed);
    Exact::Sample lo = m_.at(grid_.front());
    for (std::size_t i = 1; i < grid_.size(); ++i)
    {
      const long double reachable = lo.t + (lo.gap - TOL - band(grid_.back())) / top_speed;
      if (grid_[i] < reachable && i + 1 < grid_.size())
      {
        while (i + 1 < grid_.size() && grid_[i + 1] < reachable)
          ++i;
        lo = m_.at(grid_[i]);
        was_approaching_ = lo.rate < 0.0L;
        continue;
      }
      const Exact::Sample hi = m_.at(grid_[i]);
      if (cellDecides(lo, hi, 3))
        return ref_;
      lo = hi;
    }
    const long double g_end = lo.gap;
    if (!was_approaching_ && g_end <= TOL + band(lo.t) && uncertain(lo.t, lo.rate))
      ref_.ambiguous = true;  // an approach may begin right at the horizon
    if (was_approaching_ && g_end <= TOL + band(lo.t))
    {
      ref_.ambiguous = ref_.ambiguous || g_end > TOL - band(lo.t);
      if (g_end <= TOL)
        ref_.time = lo.t;
    }
    return ref_;
  }

private:
  /// Round-off of the gap evaluated in double at t.
  long double band(long double t) const { return 1e-15L * m_.scale(t) + 1e-17L; }

  /// Whether the sign of the rate r at t is within the round-off of its evaluation in double.
  bool uncertain(long double t, long double r) const
  {
    return std::abs(r) <= 1e-14L * m_.scale(t) * (Exact::norm(m_.v) + t * Exact::norm(m_.a));
  }

  bool cellDecides(const Exact::Sample& lo, const Exact::Sample& hi, int refinements)
  {
    // |d'| is convex in t, so the gap falls by at most the cell's width times the larger end speed: a cell that
    // stays beyond the tolerance decides nothing (and the approach it ends with is decided by a piece far apart).
    if (std::min(lo.gap, hi.gap) - (hi.t - lo.t) * std::max(lo.speed, hi.speed) > TOL + band(hi.t))
    {
      was_approaching_ = hi.rate < 0.0L;
      return false;
    }
    if (refinements > 0 && (oppositeSigns(lo.slope, hi.slope) || oppositeSigns(lo.curvature, hi.curvature)))
    {
      Exact::Sample sub_lo = lo;
      for (int k = 1; k <= 16; ++k)
      {
        const Exact::Sample sub_hi = k == 16 ? hi : m_.at(lo.t + (hi.t - lo.t) * k / 16);
        if (cellDecides(sub_lo, sub_hi, refinements - 1))
          return true;
        sub_lo = sub_hi;
      }
      return false;
    }
    if (oppositeSigns(lo.rate, hi.rate))
    {
      const Exact::Sample extremum = m_.at(bisect([&](long double t) { return m_.rate(t); }, lo.t, hi.t));
      return decides(lo, extremum) || decides(extremum, hi);
    }
    return decides(lo, hi);
  }

  /// Whether the piece [lo, hi], on which the gap is monotone, decides the contact (then in ref_).
  bool decides(const Exact::Sample& lo_sample, const Exact::Sample& hi_sample)
  {
    const long double lo = lo_sample.t, hi = hi_sample.t, mid = 0.5L * (lo + hi), r = m_.rate(mid);
    const bool approaching = r < 0.0L && !(lo == 0.0L && touching_);
    const bool uncertain = this->uncertain(mid, r);
    const long double g_lo = lo_sample.gap;
    const bool touching = g_lo <= TOL + band(lo);
    // A direction within round-off may fake or hide the start of an approach while touching. After an approach it
    // only moves the end of the graze within the same touch.
    ref_.ambiguous = ref_.ambiguous || (touching && uncertain && !was_approaching_);
    if (approaching != was_approaching_ && touching)  // touching where an approach begins or ends
    {
      ref_.ambiguous = ref_.ambiguous || g_lo > TOL - band(lo);
      if (g_lo <= TOL)
      {
        ref_.time = lo;
        return true;
      }
    }
    if (approaching && hi_sample.gap <= 0.0L)
    {
      ref_.time = bisect([&](long double t) { return m_.gap(t); }, lo, hi);
      return true;
    }
    was_approaching_ = approaching;
    return false;
  }

  bool approachingAtStart()
  {
    const long double derivatives[] = {Exact::dot(m_.p, m_.v), Exact::dot(m_.v, m_.v) + Exact::dot(m_.p, m_.a),
                                       Exact::dot(m_.v, m_.a)};
    const long double pv = Exact::norm(m_.p) * Exact::norm(m_.v), vv = Exact::dot(m_.v, m_.v);
    const long double sizes[] = {pv, vv + Exact::norm(m_.p) * Exact::norm(m_.a), Exact::norm(m_.v) * Exact::norm(m_.a)};
    // The function takes a derivative below 8 ulps of its terms for zero (and may be off by 4 in double).
    const long double ulp = std::numeric_limits<double>::epsilon();
    for (int k = 0; k < 3; ++k)
    {
      ref_.ambiguous =
          ref_.ambiguous || std::abs(std::abs(derivatives[k]) - 8.0L * ulp * sizes[k]) <= 4.0L * ulp * sizes[k];
      if (std::abs(derivatives[k]) > 8.0L * ulp * sizes[k])
        return derivatives[k] < 0.0L;
    }
    return false;
  }

  Exact m_;
  std::vector<long double> grid_;
  Reference ref_;
  bool touching_ = false, was_approaching_ = false;
};

struct Case
{
  Vector3d dp, dv, da;
  double horizon;
  std::vector<double> hints;  ///< times of interest the brute force's grid includes
};

class Generator
{
public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  double sign() { return pick(2) == 0 ? -1.0 : 1.0; }

  Vector3d unit(bool in_space)
  {
    std::normal_distribution<double> normal;
    Vector3d u(normal(rng_), normal(rng_), in_space ? normal(rng_) : 0.0);
    return u.normalized();
  }

  /// One ball's acceleration in a phase: at rest, rolling, sliding (horizontal) or airborne.
  Vector3d ballAcceleration(bool& airborne)
  {
    switch (pick(4))
    {
      case 0:
        return Vector3d::Zero();
      case 1:
        return logUniform(0.05, 0.5) * unit(false);
      case 2:
        return uniform(1.0, 3.0) * unit(false);
      default:
        airborne = true;
        return Vector3d(0.0, 0.0, -G);
    }
  }

  /// The relative acceleration of two balls and whether one of them flies (so the motion is in space).
  Vector3d relativeAcceleration(bool& in_space)
  {
    in_space = false;
    return ballAcceleration(in_space) - ballAcceleration(in_space);
  }

  /// Offsets of a closest approach relative to D: near-double roots on both sides, exact tangency, grazes within
  /// the tolerance and at its edge, and ordinary misses and hits.
  double closestOffset()
  {
    switch (pick(6))
    {
      case 0:
      case 1:
        return sign() * std::pow(10.0, -uniform(6.0, 12.0));
      case 2:
        return 0.0;
      case 3:
        return TOL / D * (pick(2) == 0 ? uniform(0.0, 1.0) : 1.0 + sign() * std::pow(10.0, -uniform(3.0, 6.0)));
      default:
        return uniform(-0.5, 0.5);
    }
  }

  /// Balls somewhere on the table, the relative velocity aimed roughly at each other.
  Case generic()
  {
    bool in_space;
    const Vector3d da = relativeAcceleration(in_space);
    Vector3d dp;
    do
      dp = Vector3d(uniform(-1.0, 1.0), uniform(-1.0, 1.0), in_space ? uniform(-0.3, 0.3) : 0.0);
    while (dp.norm() <= D + TOL);
    const Vector3d aim = (-dp.normalized() + uniform(0.0, 0.1) * unit(in_space)).normalized();
    return {dp, logUniform(0.01, 10.0) * aim, da, logUniform(1e-3, 100.0), {}};
  }

  /// A closest approach D(1 + offset) apart at tc, moving at w ⊥ d there.
  Case nearTangent()
  {
    bool in_space;
    const Vector3d da = relativeAcceleration(in_space);
    const double horizon = logUniform(1e-3, 100.0);
    const double tc = pick(10) == 0 ? horizon : uniform(0.0, 1.0) * horizon;
    const Vector3d n = unit(in_space);
    Vector3d w = unit(in_space);
    w = (w - w.dot(n) * n).normalized() * logUniform(1e-3, 10.0);
    const Vector3d dv = w - da * tc;
    const Vector3d dp = D * (1.0 + closestOffset()) * n - dv * tc - 0.5 * tc * tc * da;
    if (dp.norm() < D - TOL)
      return nearTangent();  // overlapping at the start: the caller's error, tested by hand
    return {dp, dv, da, horizon, {tc}};
  }

  /// Ball i rolls or slides along u and stops at `rest`, its centre then D(1 + offset) from ball j's at rest.
  Case stopNearContact()
  {
    const Vector3d u = unit(false), side = Vector3d(-u.y(), u.x(), 0.0);
    const double alpha = logUniform(0.05, 3.0), rest = logUniform(0.01, 30.0), phi = uniform(-0.3, 0.3);
    const Vector3d dv = -alpha * rest * u, da = alpha * u;
    const Vector3d stop = D * (1.0 + closestOffset()) * (std::cos(phi) * u + std::sin(phi) * side);
    const Vector3d dp = stop - dv * rest - 0.5 * rest * rest * da;
    const double horizon = pick(3) == 0 ? rest * uniform(0.5, 1.5) : rest;
    if (dp.norm() < D - TOL)
      return stopNearContact();
    return {dp, dv, da, horizon, {rest}};
  }

  /// Balls touching at the start (within the tolerance, exactly, or at its edge), approaching slowly, fast or not.
  Case touchingStart()
  {
    bool in_space;
    const Vector3d da = relativeAcceleration(in_space);
    const Vector3d n = unit(in_space);
    const double offsets[] = {0.0, uniform(-TOL, TOL), sign() * TOL * (1.0 - 1e-6)};
    const Vector3d dp = (D + offsets[pick(3)]) * n;
    Vector3d tangent = unit(in_space);
    tangent -= tangent.dot(n) * n;
    const double normal_speeds[] = {0.0, sign() * std::pow(10.0, -uniform(0.0, 12.0)), uniform(-10.0, 10.0)};
    const Vector3d dv = normal_speeds[pick(3)] * n + logUniform(1e-3, 10.0) * tangent;
    return {dp, dv, da, logUniform(1e-3, 10.0), {}};
  }

private:
  std::mt19937_64 rng_;
};

struct Statistics
{
  int cases = 0, contacts = 0, misses = 0;
  int flagged = 0;        ///< cases in which the brute force met a decisive value within round-off of its threshold
  int ambiguous = 0;      ///< disagreements among those
  int flat = 0;           ///< times more than 1e-9 s apart (relative to max(1 s, t)) within the same touch
  double worst_dt = 0.0;  ///< largest time difference (s) of all contacts found by both
  double worst_clean_dt = 0.0;  ///< largest, relative to max(1 s, t), where the gap closes at 1 mm/s or faster
  double worst_opening = 0.0;   ///< largest d·d'/|d| (m/s) at a returned time
};

/// Whether the gap stays touching (within its round-off of [0, tolerance]) from a to b: the same touch.
bool sameTouch(const Exact& m, long double a, long double b)
{
  for (int k = 0; k <= 100; ++k)
  {
    const long double t = a + (b - a) * k / 100, band = 1e-15L * m.scale(t) + 1e-17L, g = m.gap(t);
    if (g < -band || g > TOL + band)
      return false;
  }
  return true;
}

/// One case against the brute force: the same decision, and the time to 1e-9 s relative to max(1 s, t), or, where
/// the gap is too flat to resolve the time (a near-double root), both times in the same touch. Disagreements are
/// allowed only where the brute force met a decisive value within round-off of its threshold.
void check(const Case& c, Statistics& stats, int cells)
{
  const Exact exact(c.dp, c.dv, c.da);
  const Reference ref = BruteForce(exact, c.horizon, c.hints, cells).contact();
  const auto t = earliestBallContact(c.dp, c.dv, c.da, D, c.horizon);
  ++stats.cases;
  stats.flagged += ref.ambiguous;
  auto what = [&]
  {
    std::ostringstream out;
    out.precision(17);
    out << "dp " << c.dp.transpose() << " dv " << c.dv.transpose() << " da " << c.da.transpose() << " horizon "
        << c.horizon << " code " << (t ? *t : -1.0) << " brute " << (ref.time ? double(*ref.time) : -1.0);
    return out.str();
  };
  if (t)
  {
    ASSERT_GE(*t, 0.0) << what();
    ASSERT_LE(*t, c.horizon) << what();
    ASSERT_LE(exact.gap(*t), TOL + 1e-15L * exact.scale(*t)) << what();
    // d·d' to its round-off in double (of terms of size scale × |d'|): the gap does not open.
    const double speed = c.dv.norm() + *t * c.da.norm();
    const double opening = double(exact.rate(*t) / exact.distance(*t));
    stats.worst_opening = std::max(stats.worst_opening, opening);
    ASSERT_LE(opening, 1e-14 * double(exact.scale(*t)) * speed / D) << what();
  }
  if (t.has_value() != ref.time.has_value())
  {
    ASSERT_TRUE(ref.ambiguous) << what();
    ++stats.ambiguous;
    return;
  }
  if (!t)
  {
    ++stats.misses;
    return;
  }
  ++stats.contacts;
  const double dt = std::abs(*t - double(*ref.time)), relative = dt / std::max(1.0, *t);
  if (relative > 1e-9 && !sameTouch(exact, *t, *ref.time))
  {
    ASSERT_TRUE(ref.ambiguous) << what();
    ++stats.ambiguous;
    return;
  }
  stats.worst_dt = std::max(stats.worst_dt, dt);
  stats.flat += relative > 1e-9;
  if (std::abs(exact.rate(*ref.time)) >= 1e-3L * exact.distance(*ref.time))
    stats.worst_clean_dt = std::max(stats.worst_clean_dt, relative);
}

void report(const char* family, const Statistics& s)
{
  std::printf(
      "%-15s %6d cases: %5d contacts, %5d misses; %4d within round-off of a threshold, %3d of them disagree; "
      "%4d flat; worst dt %.2g s, closing at >= 1 mm/s %.2g relative to max(1 s, t); opening %.2g m/s\n",
      family, s.cases, s.contacts, s.misses, s.flagged, s.ambiguous, s.flat, s.worst_dt, s.worst_clean_dt,
      s.worst_opening);
}

template <class Make>
Statistics runFamily(const char* family, Make make, int count, int cells)
{
  Statistics stats;
  for (int i = 0; i < count; ++i)
  {
    check(make(), stats, cells);
    if (::testing::Test::HasFatalFailure())
      break;
  }
  report(family, stats);
  return stats;
}
}  // namespace

TEST(BallContactTime, AgreesWithBruteForceOnRandomCases)
{
  Generator gen(20240611);
  const int cells = 1000;  // 4000 give the same statistics
  const Statistics generic = runFamily(
      "generic", [&] { return gen.generic(); }, 30000, cells);
  const Statistics tangent = runFamily(
      "near-tangent", [&] { return gen.nearTangent(); }, 40000, cells);
  const Statistics stop = runFamily(
      "stop near ball", [&] { return gen.stopNearContact(); }, 15000, cells);
  const Statistics touching = runFamily(
      "touching start", [&] { return gen.touchingStart(); }, 15000, cells);
  for (const Statistics* s : {&generic, &tangent, &stop, &touching})
  {
    EXPECT_GT(s->contacts, s->cases / 10);
    EXPECT_LT(s->ambiguous, s->cases / 100);
  }
}
