#pragma once

// An independent reference for the frictionless ball–ball–table collision: the same compliant model as the engine
// (a linear spring per contact; at each end of compression k ← k/e² and the energy ← e² times it; a contact
// separates when its spring is relaxed in restitution and is re-made when its bodies approach again), solved by
// another method in extended precision (long double), using nothing of the engine.
//
// The state is scaled so that the equations of motion are skew-symmetric: y_i = √k_i·δ_i (δ_i the spring's
// compression) and w_j = √m_j·v_j, so that ½|z|² is the energy and every entry of the matrix is a frequency. Within
// a phase (a fixed set of active contacts) the motion is z(t) = exp(A t) z(0), summed as its Taylor series on steps of
// a fifth of the inverse norm of A (30 terms: truncation far below the precision). Events are found on every step by
// a sign change of their function, or of its derivative followed by a look at the extremum (a near-tangential touch
// of zero is decided, not stepped over), and located by bisection to the precision of long double. A chatter is
// followed cycle by cycle until its contact's peak energy falls below 1e-22 of the start (what its remaining cycles
// could still lose); its bodies then move as one (the rigid-link limit), and the other contact, if still active,
// finishes alone on them.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace reference
{
using Real = long double;

struct BallBallTableCollision
{
  Real m1 = 1, m2 = 1, stiffness_ratio = 1;  ///< k2/k1, ball–table over ball–ball
  Real e1 = 1, e2 = 1, v0 = -1;              ///< ball–ball and ball–table restitution; ball 1's velocity, upwards +
};

struct BallBallTableOutcome
{
  Real v1 = 0, v2 = 0;
  std::vector<std::string> states;  ///< the paper's names of the active sets: S1 both, S2 table, S3 ball–ball, S4
  bool chatter_limit = false;       ///< ended as the limit of a chatter (the energy left below the threshold)
  bool finished = false;            ///< false only when the phase limit was reached
};

namespace detail
{
using State = std::array<Real, 4>;  // y1, y2, w1, w2

struct Contact
{
  Real s = 1;  ///< √k
  Real e = 1;
  bool active = true;
  bool compressing = true;
};

struct Phase
{
  Real sm1 = 1, sm2 = 1;  ///< √m1, √m2
  std::array<Contact, 2> contacts;

  /// dz/dt = A z.
  State rate(const State& z) const
  {
    const Real s1 = contacts[0].active ? contacts[0].s : 0, s2 = contacts[1].active ? contacts[1].s : 0;
    return {s1 * (z[3] / sm2 - z[2] / sm1), -s2 * z[3] / sm2, s1 * z[0] / sm1, (s2 * z[1] - s1 * z[0]) / sm2};
  }
  /// A bound on the norm of A (its Frobenius norm).
  Real norm() const
  {
    const Real s1 = contacts[0].active ? contacts[0].s : 0, s2 = contacts[1].active ? contacts[1].s : 0;
    return std::sqrt(2 * (s1 * s1 / (sm1 * sm1) + s1 * s1 / (sm2 * sm2) + s2 * s2 / (sm2 * sm2)));
  }
  /// z(τ) from z(0) by the Taylor series of exp(A τ).
  State advance(const State& z, Real tau) const
  {
    State sum = z, term = z;
    for (int n = 1; n <= 30; ++n)
    {
      term = rate(term);
      for (Real& x : term)
        x *= tau / n;
      for (std::size_t i = 0; i < 4; ++i)
        sum[i] += term[i];
    }
    return sum;
  }
  /// The approach speed of contact `i` (positive: its bodies approach).
  Real approach(const State& z, int i) const { return i == 0 ? z[3] / sm2 - z[2] / sm1 : -z[3] / sm2; }
};

enum class Watch
{
  EndOfCompression,  ///< active, compressing: the approach speed falls to 0
  Separation,        ///< active, restituting: the spring relaxes
  Restart,           ///< active, restituting: the bodies approach again
  Reactivation,      ///< inactive: the bodies approach again
};

/// The event function of `watch` for contact `i` (the event happens where it becomes ≤ 0).
inline Real guard(const Phase& p, const State& z, int i, Watch watch)
{
  switch (watch)
  {
    case Watch::EndOfCompression:
      return p.approach(z, i);
    case Watch::Separation:
      return z[static_cast<std::size_t>(i)];
    case Watch::Restart:
    case Watch::Reactivation:
      break;
  }
  return -p.approach(z, i);
}

/// Its rate: every guard is linear in the state, so its rate is the guard of the state's rate.
inline Real guardRate(const Phase& p, const State& z, int i, Watch watch)
{
  return guard(p, p.rate(z), i, watch);
}

inline std::vector<Watch> watches(const Contact& c)
{
  if (!c.active)
    return {Watch::Reactivation};
  if (c.compressing)
    return {Watch::EndOfCompression};
  return {Watch::Separation, Watch::Restart};
}

/// The end of [lo, hi] where `holds` turns false, by bisection to the precision of Real (`holds` is true at lo
/// and false at hi).
template <typename Holds>
Real bisect(Real lo, Real hi, Holds holds)
{
  for (int k = 0; k < 200; ++k)
  {
    const Real mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi)
      break;
    (holds(mid) ? lo : hi) = mid;
  }
  return hi;
}

/// The first τ in (0, h] where the guard is ≤ 0, if any: a sign change over the step, or an extremum inside it
/// that reaches 0. Located by bisection; the τ returned lies just past the crossing.
inline bool firstCrossing(const Phase& p, const State& z0, Real h, int i, Watch watch, Real& tau)
{
  const auto guard_at = [&](Real t) { return guard(p, p.advance(z0, t), i, watch); };
  Real hit = h;
  if (guard_at(h) > 0)
  {
    if (!(guardRate(p, z0, i, watch) < 0 && guardRate(p, p.advance(z0, h), i, watch) > 0))
      return false;
    // The minimum: where the rate turns positive.
    hit = bisect(0, h, [&](Real t) { return guardRate(p, p.advance(z0, t), i, watch) < 0; });
    if (guard_at(hit) > 0)
      return false;
  }
  tau = bisect(0, hit, [&](Real t) { return guard_at(t) > 0; });
  return true;
}

inline std::string stateName(const std::array<Contact, 2>& c)
{
  if (c[0].active && c[1].active)
    return "S1";
  if (c[1].active)
    return "S2";
  if (c[0].active)
    return "S3";
  return "S4";
}

inline void apply(Contact& c, Real& y, Watch watch)
{
  switch (watch)
  {
    case Watch::EndOfCompression:
      y *= c.e;  // E ← e²E with the force continuous: k ← k/e², δ ← e²δ
      c.s /= c.e;
      c.compressing = false;
      return;
    case Watch::Separation:
      y = 0;
      c.active = false;
      return;
    case Watch::Restart:
      c.compressing = true;
      return;
    case Watch::Reactivation:
      y = 0;
      c.active = c.compressing = true;
      return;
  }
}

/// After a chatter of contact `linked` has converged (its bodies move as one), the other contact, still active,
/// finishes alone on the linked bodies: the link is compressive throughout (the other contact pushes the pair, or
/// the ball against the table), so its end follows from the energy, with one end of compression when it is still
/// compressing. Returns the velocities (v1, v2).
inline std::array<Real, 2> finishOnTheLink(const Phase& p, const State& z, int linked, const BallBallTableCollision& c)
{
  const Contact& other = p.contacts[static_cast<std::size_t>(1 - linked)];
  const Real y = z[static_cast<std::size_t>(1 - linked)];
  const Real v1 = z[2] / p.sm1, v2 = z[3] / p.sm2;
  if (linked == 0)  // the balls as one on the table's spring
  {
    const Real mass = c.m1 + c.m2, v = (c.m1 * v1 + c.m2 * v2) / mass;
    const Real out = std::sqrt(v * v + y * y / mass) * (other.compressing ? other.e : 1);
    return {out, out};
  }
  // Ball 2 held on the table, ball 1 on the balls' spring
  const Real out = std::sqrt(v1 * v1 + y * y / c.m1) * (other.compressing ? other.e : 1);
  return {out, 0};
}
}  // namespace detail

/// Solves the collision; `max_phases` bounds the work (a chatter at e near 1 takes hundreds of cycles).
inline BallBallTableOutcome solve(const BallBallTableCollision& c, int max_phases = 100000)
{
  using namespace detail;
  Phase p;
  p.sm1 = std::sqrt(c.m1);
  p.sm2 = std::sqrt(c.m2);
  p.contacts[0] = {1, c.e1, true, true};
  p.contacts[1] = {std::sqrt(c.stiffness_ratio), c.e2, true, true};
  std::array<int, 2> ends{0, 0};
  std::array<Real, 2> last_peak{0, 0};  // each contact's spring energy at its last end of compression
  State z{0, 0, p.sm1 * c.v0, 0};
  // A chatter has converged when its contact's peak energy is below this: the rest of its cycles would lose less
  // (their peaks fall geometrically, as k grows by 1/e² a cycle).
  const Real threshold = 1e-22L * z[2] * z[2] / 2;
  constexpr int CHATTER_ENDS = 5;
  BallBallTableOutcome out;
  out.states.push_back(stateName(p.contacts));
  const auto take_velocities = [&]
  {
    out.v1 = z[2] / p.sm1;
    out.v2 = z[3] / p.sm2;
  };
  for (int phase = 0; phase < max_phases; ++phase)
  {
    const bool none = !p.contacts[0].active && !p.contacts[1].active;
    if (none && p.approach(z, 0) <= 0 && p.approach(z, 1) <= 0)
    {
      out.finished = true;
      break;
    }
    for (int i = 0; i < 2 && !out.finished; ++i)
    {
      const int j = 1 - i;
      const auto k = static_cast<std::size_t>(i);
      if (ends[k] < CHATTER_ENDS || last_peak[k] >= threshold || p.approach(z, i) > 0)
        continue;
      if (p.contacts[static_cast<std::size_t>(j)].active)
      {
        const auto v = finishOnTheLink(p, z, i, c);
        out.v1 = v[0];
        out.v2 = v[1];
        out.finished = out.chatter_limit = true;
      }
      else if (p.approach(z, j) <= 0)
      {
        take_velocities();
        out.finished = out.chatter_limit = true;
      }
    }
    if (out.finished)
      return out;
    const Real h = p.norm() > 0 ? Real(0.2) / p.norm() : 1;  // none active: the velocities are constant
    bool found = false;
    for (int step = 0; step < 1000000 && !found; ++step)
    {
      Real first = h + 1;
      int which = -1;
      Watch what = Watch::EndOfCompression;
      for (int i = 0; i < 2; ++i)
        for (Watch watch : watches(p.contacts[static_cast<std::size_t>(i)]))
        {
          Real tau = 0;
          if (firstCrossing(p, z, h, i, watch, tau) && tau < first)
          {
            first = tau;
            which = i;
            what = watch;
          }
        }
      if (which < 0)
      {
        z = p.advance(z, h);
        continue;
      }
      z = p.advance(z, first);
      if (what == Watch::EndOfCompression)
      {
        ++ends[static_cast<std::size_t>(which)];
        last_peak[static_cast<std::size_t>(which)] =
            z[static_cast<std::size_t>(which)] * z[static_cast<std::size_t>(which)] / 2;
      }
      apply(p.contacts[static_cast<std::size_t>(which)], z[static_cast<std::size_t>(which)], what);
      found = true;
    }
    if (!found)
      break;
    const std::string name = stateName(p.contacts);
    if (name != out.states.back())
      out.states.push_back(name);
  }
  take_velocities();
  return out;
}

}  // namespace reference
