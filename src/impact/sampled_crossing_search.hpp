#pragma once

#include "dense_stepper.hpp"  // first: its Boost 1.74 workaround must come before any Boost.Math header

#include <Eigen/Core>
#include <boost/container/small_vector.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "affine_crossing_search.hpp"
#include "contact_dynamics.hpp"
#include "contact_space.hpp"
#include "contact_state.hpp"
#include "linear_phase.hpp"
#include "sampled_rise_search.hpp"
#include "separation_clock.hpp"
#include "state_transitions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// A guard that fires, at an instant of its stepper's clock.
struct FiredGuard
{
  Guard guard;
  double time;
};

/// The earliest of `crossings` with every other within round-off of it (of a step `width`), all at the earliest
/// instant, into `fired` (returned).
const std::vector<FiredGuard>& earliestCrossings(const std::vector<FiredGuard>& crossings, double width,
                                                 std::vector<FiredGuard>& fired);

/// The crossings of a state's guards found from samples along the steps of its stepper: the numerically integrated
/// states, and the closed-form ones that AffineCrossingSearch does not take. Each step samples every guard at evenly
/// spaced instants, looks for its first rise through zero among them (firstRise, which samples finer where a rise
/// may hide between two samples) and locates its zero with TOMS 748 (docs/engine.md, "Event location").
///
/// Steppers: DenseStepper, SeparationClockStepper (in its clock u) and LinearPhaseStepper. Holds references to the
/// solver's contact space, contact states and dynamics; evaluates states into storage of its own.
class SampledCrossingSearch
{
public:
  /// Guard samples per integrator step: with steps bounded by a fraction of the fastest contact period this
  /// catches transitions that fire and reset within one step.
  static constexpr int SAMPLES_PER_STEP = 4;

  /// `state_size`: the length of the ODE state.
  SampledCrossingSearch(const ContactSpace& space, const std::vector<ContactState>& contacts,
                        const ContactDynamics& dynamics, std::size_t state_size);

  /// Starts a state at y with its armed `guards` (kept by reference until the next start): an end of compression
  /// is due once its contact separates faster than `separation_floor`, and `omega` bounds the state's angular
  /// frequencies.
  template <class Stepper>
  void start(const Stepper& stepper, const std::vector<Guard>& guards, const double* y, double separation_floor,
             double omega)
  {
    guards_ = &guards;
    separation_floor_ = separation_floor;
    omega_ = omega;
    guard_values_.resize(SAMPLES_PER_STEP + 1, static_cast<Eigen::Index>(guards.size()));
    samples_ = SAMPLES_PER_STEP;
    first_row_known_ = sampleStart(stepper, y);  // later, a step's first sample is the previous step's last
    previous_row_known_ = false;
  }

  /// Samples every guard along the step [t0, t1] that the stepper has just taken.
  template <class Stepper>
  void sampleStep(const Stepper& stepper, double t0, double t1)
  {
    samples_ = guardSamples(stepper, t0, t1);
    guard_values_.conservativeResize(samples_ + 1, Eigen::NoChange);
    for (int k = first_row_known_ ? 1 : 0; k <= samples_; ++k)
    {
      evaluateAt(stepper, sampleTime(t0, t1, k));
      storeGuardRow(k);
    }
  }

  /// The kinematics at the end of the step sampled last, until the next evaluation (firedGuards evaluates).
  const Kinematics& sampledEnd() const { return kinematics_; }

  /// The earliest guard to rise through zero in the step [t0, t1] (from its samples, refined where two may straddle
  /// a positive bump), with every other one within round-off of it; empty when none does.
  template <class Stepper>
  const std::vector<FiredGuard>& firedGuards(const Stepper& stepper, double t0, double t1)
  {
    crossings_.clear();
    for (std::size_t g = 0; g < guards_->size(); ++g)
      if (const auto rise = firstRiseOf(stepper, g, t0, t1))
        crossings_.push_back(
            {(*guards_)[g], locateRoot(stepper, g, rise->below.t, rise->above.t, rise->below.g, rise->above.g)});
    return earliestCrossings(crossings_, t1 - t0, fired_);
  }

  /// The next step starts where the step [t0, t1] ended: its first sample is this step's last, the one before that
  /// is kept as its neighbour (for firstRise).
  void startNextStep(double t0, double t1);

  /// The state at t of the current step and its kinematics (into the search's own storage).
  template <class Stepper>
  const Kinematics& evaluateAt(const Stepper& stepper, double t)
  {
    stepper.calc_state(t, state_);
    evaluateKinematics(dynamics_, state_.data(), kinematics_);
    return kinematics_;
  }

  const Kinematics& evaluateAt(const LinearPhaseStepper& stepper, double t)
  {
    stepper.calc_kinematics(t, state_, kinematics_);
    return kinematics_;
  }

  /// Guard samples of the current step.
  int samplesPerStep() const { return samples_; }
  /// Instant of sample k of the step [t0, t1].
  double sampleTime(double t0, double t1, int k) const { return k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_; }

private:
  /// Bound on how many times a step's guard sampling is refined (a step of the separation clock spanning many
  /// periods; it only happens where the clock runs at nearly physical speed).
  static constexpr double MAX_STEP_SUBDIVISION = 64.0;
  /// Evaluations allowed to TOMS 748 for one guard's zero (it converges in about ten).
  static constexpr int MAX_ROOT_ITERATIONS = 100;

  /// Guard values at the start of a numerically integrated state, from the state y itself into the first row of
  /// guard_values_. Odeint's interpolant reproduces the state there only to round-off, and a guard that starts at
  /// zero — a contact with v_n = 0 about to separate — could come out at +1e-18 and its crossing be missed: the
  /// contact would then stay in compression while pulled apart (the cloth under a cushion nose below the ball's
  /// centre). Returns whether the row is known.
  template <class Stepper>
  bool sampleStart(const Stepper& /*stepper*/, const double* y)
  {
    evaluateKinematics(dynamics_, y, kinematics_);
    storeGuardRow(0);
    return true;
  }

  /// The closed form is exact at its start, and its samples take their forces from its modes throughout.
  bool sampleStart(const LinearPhaseStepper& /*stepper*/, const double* /*y*/) { return false; }

  /// Guard samples for a step: SAMPLES_PER_STEP per half radian of the fastest mode in physical time. Only the
  /// separation clock's steps can be longer (their length in u is not bounded in t).
  template <class Stepper>
  int guardSamples(const Stepper& /*stepper*/, double /*t0*/, double /*t1*/) const
  {
    return SAMPLES_PER_STEP;
  }

  int guardSamples(const SeparationClockStepper& stepper, double u0, double u1) const;

  /// A guard's value as the current state's method resolves it: an end of compression is due once the contact
  /// separates faster than separation_floor_, not at the first positive noise of its normal velocity.
  double resolvedGuard(const Guard& guard, const Kinematics& kinematics) const;

  /// Every guard's value at kinematics_ into row k of guard_values_.
  void storeGuardRow(int k);

  template <class Stepper>
  double guardAt(const Stepper& stepper, std::size_t g, double t)
  {
    return resolvedGuard((*guards_)[g], evaluateAt(stepper, t));
  }

  /// The first rise through zero of guard g among its samples of the step [t0, t1].
  template <class Stepper>
  std::optional<RiseBracket> firstRiseOf(const Stepper& stepper, std::size_t g, double t0, double t1)
  {
    const auto column = static_cast<Eigen::Index>(g);
    samples_of_guard_.clear();
    for (int k = 0; k <= samples_; ++k)
      samples_of_guard_.push_back({sampleTime(t0, t1, k), guard_values_(k, column)});
    const GuardSample before{previous_time_, previous_row_known_ ? previous_row_(column) : 0.0};
    // Without a previous step this is the state's first, and its first sample the state's start.
    const bool starts_at_zero = !previous_row_known_ && std::abs(samples_of_guard_.front().g) <= START_ROUND_OFF;
    auto evaluate = [&](double t) { return guardAt(stepper, g, t); };
    return firstRise(samples_of_guard_.data(), samples_of_guard_.size(), previous_row_known_ ? &before : nullptr,
                     nullptr, evaluate, starts_at_zero);
  }

  /// The instant just after the guard's zero (so that the transition has numerically happened).
  template <class Stepper>
  double locateRoot(const Stepper& stepper, std::size_t g, double a, double b, double ga, double gb)
  {
    if (ga == 0.0)
      return a;
    const double width = b - a;
    auto close_enough = [width](double lo, double hi) { return hi - lo <= rootTolerance(width, lo); };
    std::uintmax_t iterations = MAX_ROOT_ITERATIONS;
    const auto bracket = boost::math::tools::toms748_solve([&](double t) { return guardAt(stepper, g, t); }, a, b, ga,
                                                           gb, close_enough, iterations);
    return bracket.second;
  }

  const ContactSpace& space_;
  const std::vector<ContactState>& contacts_;
  const ContactDynamics& dynamics_;
  const std::vector<Guard>* guards_ = nullptr;  ///< of the current state
  double separation_floor_ = 0.0;               ///< normal speed an end of compression must reach in the current state
  double omega_ = 1.0;                          ///< fastest angular frequency of the current state
  OdeState state_;                              ///< at the instant evaluated last
  Kinematics kinematics_{};                     ///< of state_ (or of the state's start, after start)
  Eigen::MatrixXd guard_values_;                ///< guard samples of the current step: instants × guards
  int samples_ = SAMPLES_PER_STEP;              ///< guard samples of the current step
  bool first_row_known_ = false;                ///< the current step's first sample is known before it is sampled
  Eigen::VectorXd previous_row_;  ///< the guards at the previous step's last sample but one, at previous_time_
  double previous_time_ = 0.0;
  bool previous_row_known_ = false;  ///< false in a state's first step
  boost::container::small_vector<GuardSample, SAMPLES_PER_STEP + 1> samples_of_guard_;  ///< scratch of firstRiseOf
  std::vector<FiredGuard> crossings_, fired_;
};

}  // namespace detail
}  // namespace billiard_shot_planner
