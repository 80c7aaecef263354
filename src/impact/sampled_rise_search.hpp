#pragma once

#include <array>
#include <cstddef>
#include <optional>

namespace billiard_shot_planner
{
namespace detail
{
/// A guard's value at one instant of a stepper's clock.
struct GuardSample
{
  double t;
  double g;
};

/// Two samples between which a guard rises through zero.
struct RiseBracket
{
  GuardSample below;
  GuardSample above;
};

/// Parts an interval is split into when its two negative samples may straddle a positive bump, and how many times
/// that may be repeated inside it: the samples end 4³ = 64 times closer, a sixteenth of a radian of the fastest mode
/// becomes a thousandth.
constexpr int BUMP_SPLIT = 4;
constexpr int MAX_BUMP_REFINEMENTS = 3;

/// Curvature term (|g''|h²/2, dimensionless like the state) below which a guard's wiggle between samples is taken
/// for round-off: the guards of contacts at rest, sums of cancelling terms, would otherwise be refined until one
/// sample came out above zero (a random chain touching at rest: two spurious events).
constexpr double BUMP_NOISE = 1e-12;

/// Whether the parabola through p, q, r (increasing instants) has its maximum inside (from, to) and less than
/// |g''|h²/2 below zero, h = to − from: four times what such a parabola rises between samples h apart, a margin for
/// the terms of higher order that it leaves out.
inline bool peaksNearZeroWithin(const GuardSample& p, const GuardSample& q, const GuardSample& r, double from,
                                double to)
{
  const double d1 = (q.g - p.g) / (q.t - p.t);
  const double d2 = (r.g - q.g) / (r.t - q.t);
  const double c = (d2 - d1) / (r.t - p.t);  // half the second derivative
  if (!(c < 0.0))
    return false;
  const double vertex = 0.5 * (p.t + q.t) - d1 / (2.0 * c);
  if (!(vertex > from && vertex < to))
    return false;
  const double peak = p.g + d1 * (vertex - p.t) + c * (vertex - p.t) * (vertex - q.t);
  const double h = to - from;
  const double margin = -c * h * h;
  return margin > BUMP_NOISE && peak > -margin;
}

/// Whether a guard negative at both a and b may rise above zero between them: a parabola through them and a
/// neighbour (before a, or after b) peaks inside and near zero.
inline bool mayHideBump(const GuardSample* before, const GuardSample& a, const GuardSample& b, const GuardSample* after)
{
  return (before != nullptr && peaksNearZeroWithin(*before, a, b, a.t, b.t)) ||
         (after != nullptr && peaksNearZeroWithin(a, b, *after, a.t, b.t));
}

/// Values of a guard at BUMP_SPLIT + 1 evenly spaced instants from a to b (both ends known).
template <class Evaluate>
std::array<GuardSample, BUMP_SPLIT + 1> sampleFiner(const GuardSample& a, const GuardSample& b, Evaluate& evaluate)
{
  std::array<GuardSample, BUMP_SPLIT + 1> finer;
  finer.front() = a;
  finer.back() = b;
  for (int j = 1; j < BUMP_SPLIT; ++j)
  {
    const double t = a.t + (b.t - a.t) * j / BUMP_SPLIT;
    finer[static_cast<std::size_t>(j)] = {t, evaluate(t)};
  }
  return finer;
}

/// The first rise through zero of a guard sampled at increasing instants samples[0 .. count).
///
/// Why more than a sign change between samples:
/// - a guard can rise above zero and fall back between two samples: a contact's tangential force grazing its
///   friction cone for less than a quarter radian of the fastest mode, between samples a quarter radian apart. The
///   transition it makes (stick to slip) changes the rest of the collision. Where the parabola through an interval's
///   samples and a neighbour peaks inside it and close to zero, the interval is sampled finer, and so on up to
///   MAX_BUMP_REFINEMENTS times;
/// - the guard of a contact that has just switched starts at zero (`starts_at_zero`: samples[0].g within
///   START_ROUND_OFF of it), dips below and may rise through zero again before the next sample: with a start of
///   +1e-17 both samples lie above zero. A random cushion hit on the cloth missed such a stick to slip (it came out
///   20 % slower). A first interval rising from the zero start is sampled finer for the dip; where none shows even
///   MAX_BUMP_REFINEMENTS times finer, the start's own sign decides, as a sign change would.
/// `before` and `after` are neighbours outside the range (or null); `evaluate(t)` gives the guard within it.
template <class Evaluate>
std::optional<RiseBracket> firstRise(const GuardSample* samples, std::size_t count, const GuardSample* before,
                                     const GuardSample* after, Evaluate& evaluate, bool starts_at_zero = false,
                                     int refinements = MAX_BUMP_REFINEMENTS)
{
  for (std::size_t k = 0; k + 1 < count; ++k)
  {
    const GuardSample& a = samples[k];
    const GuardSample& b = samples[k + 1];
    const GuardSample* previous = k > 0 ? &samples[k - 1] : before;
    const GuardSample* next = k + 2 < count ? &samples[k + 2] : after;
    const bool from_zero_start = k == 0 && starts_at_zero && b.g > 0.0;
    const bool may_hide_bump = a.g <= 0.0 && b.g <= 0.0 && mayHideBump(previous, a, b, next);
    if (refinements > 0 && (from_zero_start || may_hide_bump))
    {
      const auto finer = sampleFiner(a, b, evaluate);
      if (auto rise = firstRise(finer.data(), finer.size(), previous, next, evaluate, from_zero_start, refinements - 1))
        return rise;
      continue;
    }
    if (a.g <= 0.0 && b.g > 0.0)
      return RiseBracket{a, b};
  }
  return std::nullopt;
}

}  // namespace detail
}  // namespace billiard_shot_planner
