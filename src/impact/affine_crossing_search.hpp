#pragma once

#include <array>
#include <boost/container/small_vector.hpp>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

#include "linear_phase.hpp"
#include "state_transitions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Crossings this close (as a fraction of the step) fire together, at the earliest.
constexpr double SIMULTANEOUS = 1e-12;

/// Width to which a guard's zero is bracketed, in an interval of `width` starting at `start`.
inline double rootTolerance(double width, double start)
{
  return 1e-15 * width + 4.0 * std::numeric_limits<double>::epsilon() * std::abs(start);
}

/// Storage of the affine search, one entry per guard: inline for the guards of a few contacts, so that a short
/// frictionless collision does not allocate for it.
template <class T>
using PerGuard = boost::container::small_vector<T, 8>;

/// A guard that fires, and the instant just after its zero (so that the transition has numerically happened).
struct GuardZero
{
  std::size_t guard;  ///< index among the state's guards
  double time;
};

/// The crossings of a closed-form state's guards when every one is affine (every frictionless state, rigid links
/// included), found with bounds instead of samples.
///
/// Each guard is one kinematic quantity, a sum of the modes' sines: the closed form gives its value and first two
/// derivatives, and bounds M, J on its second and third derivatives over the state (from the modes' amplitudes).
/// Taylor's bound from each end of an interval, g(a + u) ≤ g(a) + ġ(a)u + Mu²/2 or, to third order,
/// g(a) + ġ(a)u + g̈(a)u²/2 + Ju³/6 (which decides a guard that starts at a double zero, a contact touching at rest:
/// the second-order bound cannot), or the chord's, g ≤ max(g(a), g(b)) + Mh²/8 over a width h, then proves the
/// interval free of crossings, or it is halved for all undecided guards at once, until the chord's bound is within
/// the guard's round-off (MAX_REFINEMENTS): a guard that touches zero nearly tangentially (a light ball between a
/// heavy one and the table, its velocity back to zero every fast period) is decided, never dropped. Zeros are found
/// by Newton's method kept inside their bracket. So a step costs one evaluation of the modes, at its end, where the
/// sampled search took four, and it sees the crossing pairs those samples could step over.
class AffineCrossingSearch
{
public:
  /// Starts at t with the state's guards `forms` (each affine). False when a guard is above zero there (it must
  /// fall to zero before it can rise through it): the sampled search takes such a state.
  bool start(const LinearPhaseStepper& stepper, const PerGuard<std::optional<AffineGuard>>& forms, double t);

  /// Searches the next step: the guards that cross in it, each with the instant just after its zero, less those
  /// found to cross after another (the earliest fires, with any within SIMULTANEOUS of it). Empty when none
  /// crosses; the next call searches the step after.
  const PerGuard<GuardZero>& nextStep();

  /// Length of the steps.
  double stepLength() const { return stepper_->step(); }

  /// The solve's wall-clock bound: a step whose halvings run past it ends its search there (its zeros are then
  /// incomplete, and the solver's own check of the bound, before the next step, fails the solve). Without it, a
  /// step whose guards stay undecided halves every interval down to the last refinement, which took 15 s for one
  /// fuzzed problem under the sanitizers.
  void setDeadline(std::chrono::steady_clock::time_point deadline) { deadline_ = deadline; }

private:
  /// An affine guard's value and its first two time derivatives at one instant.
  struct Sample
  {
    double value;
    double rate;
    double acceleration;
  };

  /// An interval at whose ends a guard is ≤ level and > level (ga, gb: its values less the level).
  struct Bracket
  {
    std::size_t guard;
    double a, b;
    double ga, gb;
    double level = 0.0;
  };

  /// What the samples at the ends of an interval tell of one guard.
  enum class Crossing
  {
    Bracketed,  ///< ≤ 0 at the start and > 0 at the end
    Excluded,   ///< proven ≤ 0 throughout
    Undecided,
  };

  /// Halvings of a step: after D of them the chord's bound Mh²/8 is step²M/2^(2D+3), below the guard's round-off
  /// (NOISE · M · step², affine_crossing_search.cpp) from D = 19 on. An interval still undecided there has ends
  /// within round-off of zero or above it: the guard either stays within twice its round-off of zero (no crossing
  /// it could resolve) or rises out of its round-off (a crossing, bracketed). Stopped after 4 halvings, the search
  /// drops a light ball's velocity that touches zero by 8e-6 between two samples at −4e-5, and takes its end of
  /// compression a fast period late (project issue 23).
  static constexpr int MAX_REFINEMENTS = 19;
  /// From this halving on, an undecided guard is also tried by taylorExcludes: there the remainder of its expansion
  /// is below its round-off (h¹⁰M₁₀/10! ≤ M·step²·4⁻¹⁰/10!, 3e-13 of the modal terms). A guard that leaves zero at a
  /// zero of high order (the far end of a chain, which the collision reaches through the balls between) is decided
  /// there, where the bounds on its second and third derivatives, set by the whole state's modes, need halving after
  /// halving (a 10-ball chain: 10 times the instructions).
  static constexpr int TAYLOR_DEPTH = 2;

  /// Every guard's value and rate at t into `samples`.
  void sampleAll(double t, PerGuard<Sample>& samples) const;
  Sample sample(std::size_t g) const;
  /// The guard's value and rate alone (root finding).
  Sample sampleValue(std::size_t g) const;
  /// `last`: no halving follows (see MAX_REFINEMENTS).
  Crossing classify(std::size_t g, double a, Sample ga, double b, Sample gb, bool last) const;
  /// Whether Taylor's expansion of the guard to order TAYLOR_ORDER from an end of [a, b], its terms that can only
  /// lower it left out and its remainder bounded, proves it within `noise` of zero or below over the interval.
  bool taylorExcludes(std::size_t g, double a, Sample ga, double b, Sample gb) const;
  /// The first brackets of the guards in pending_[depth] within [a, b] into brackets_; whether one was found.
  bool isolate(double a, const PerGuard<Sample>& at_a, double b, const PerGuard<Sample>& at_b, int depth);
  /// A guard at zero (to round-off) at a and above zero at b, the ends of the finest interval, that classify left
  /// undecided (it brackets a zero start only where the guard rises at first order): the guard rises through zero in
  /// between, by its curvature, after a dip where it falls first. Brackets that rise into brackets_; whether it did.
  /// Dropped as undecided instead, the guard was above zero at the start of every later interval, where nothing is
  /// bracketed: a chain's contact approached at the reactivation threshold when the state started never
  /// reactivated, and its balls went through each other until the next event.
  bool bracketRiseFromZero(std::size_t g, double a, double b, double gb);
  /// Narrows the bracket to end by `limit` (the earliest zero found so far); false when the guard is still ≤ 0
  /// there, so that its zero comes later and cannot fire.
  bool endBy(double limit, Bracket& bracket) const;
  /// The instant just after the bracketed zero.
  double risingZero(Bracket bracket) const;

  const LinearPhaseStepper* stepper_ = nullptr;
  PerGuard<AffineGuard> guards_;
  PerGuard<LinearPhaseStepper::GuardBounds> bounds_;  ///< on the guards' second and third derivatives
  PerGuard<double> noise_;                            ///< round-off of the guards' values
  double t_ = 0.0;                                    ///< start of the next step
  std::chrono::steady_clock::time_point deadline_ = std::chrono::steady_clock::time_point::max();
  /// The guards at the ends of the step, the start's at ends_[start_]: the next step starts where this one ended.
  std::array<PerGuard<Sample>, 2> ends_;
  std::size_t start_ = 0;
  PerGuard<Bracket> brackets_;
  PerGuard<GuardZero> zeros_;
  /// Guards still undecided at each depth of a step's halving, and their samples at each depth's middle.
  std::array<PerGuard<std::size_t>, MAX_REFINEMENTS + 2> pending_;
  std::array<PerGuard<Sample>, MAX_REFINEMENTS + 1> at_middle_;
};

}  // namespace detail
}  // namespace billiard_shot_planner
