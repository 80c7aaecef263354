#pragma once

#include <cstddef>
#include <string>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// Numerical settings of the multiple-impact solver. The defaults give final velocities to about 1e-10
/// relative on the paper's examples.
struct SolverOptions
{
  double relative_tolerance = 1e-12;  ///< integrator tolerance on the normalised state
  double absolute_tolerance = 1e-14;  ///< same, absolute (the normalised state is of order one)
  /// A contact whose compression ends with a stored energy below this fraction of the initial kinetic energy,
  /// after it has already ended compression at least twice, is taken to chatter: the solver finishes with the
  /// limit of the infinite sequence, a rigid link while its force stays compressive (paper Theorem 12).
  double chatter_energy_fraction = 1e-20;
  /// The same limit is taken once the stiffness a contact's restitution would have has grown by this factor
  /// (k/k̄ = e^{-2j} after its j-th end of compression): a restitution that stiff is the rigid limit already.
  double chatter_stiffness_growth = 1e14;
  /// And, in a numerically integrated state, once its deformation at the end of compression (normalised) is below
  /// this multiple of absolute_tolerance: the integrator holds a spring only to that tolerance, so later cycles would
  /// carry no correct digit (closed-form states hold it to round-off). A jammed contact chatters under a large
  /// force, its deformation F/k shrinking as k grows: on random jammed cue strikes, integrating those cycles moved
  /// the final velocities by up to 0.03 (m/s, rad/s) from the converged limit; cut at 100 tolerances, by 6e-4.
  double chatter_resolution = 100.0;
  std::size_t max_events = 200000;  ///< bound on contact events; beyond it the solve fails (never hangs)
  /// Bound on integrator steps; beyond it the solve fails (a step costs 5–25 µs). Every example takes under 1 000
  /// by default and under 10 000 integrated in plain time at 1e-14; the slowest of 20 000 random impacts (a nearly
  /// plastic cushion, a table friction of 0.003) about 200 000.
  std::size_t max_steps = 300000;
  /// Wall-clock bound of one solve, s; beyond it the solve fails (TimeLimitExceeded). Every example and random
  /// collision of the tests takes well under a second in a release build; chains of 25–30 balls with masses over
  /// six decades take up to 150 000 events and 13 s. The library's default leaves room for slow builds (the
  /// sanitizers' are 20–50 times slower); a robot sets what its loop allows (the node's configuration: 1 s).
  double max_seconds = 10.0;
  bool record_samples = false;  ///< keep the impulse curve and energies at every integrator step
  /// Solve states in which no active contact slides (frictionless or sticking contacts: linear spring dynamics) in
  /// closed form, exact to round-off; off, every state is integrated numerically (for cross-checks).
  bool closed_form_linear_phases = true;
  /// Integrate on a clock that slows down as sliding contacts approach separation, where their slip direction has a
  /// weak singularity that costs explicit steps in proportion to the time left (off: plain time, for cross-checks).
  bool separation_clock = true;
  /// A contact that starts sliding from relaxed springs (a landing, the cloth under a cushion hit, a reactivation)
  /// has so short a spring on its friction cone that its slip direction relaxes almost at once: it follows the
  /// slip with its second-order quasi-steady lag while its relaxation time ρ/|v_t| is below (tolerance/10)^¼
  /// (5.6e-4 of the collision's time by default; errors of order its fourth power), and is integrated from then on.
  /// Off, the direction is integrated from the start, a stiff equation that the explicit integrator follows only in
  /// tiny steps and, at small loads, not always stably (for cross-checks).
  bool quasi_steady_slip = true;
};

/// The loosest absolute tolerance accepted: coarser, the cut of chattering contacts (100 absolute tolerances) lets
/// energy rise (bench/NOTES.md, Bounds of work).
constexpr double LOOSEST_ABSOLUTE_TOLERANCE = 1e-8;

/// Checks every field (InvalidArgument naming `field`.name): relative_tolerance in [2.2e-16, 1e-3],
/// absolute_tolerance in [1e-16, 1e-8] (coarser, the chatter cut lets energy rise), chatter_energy_fraction and
/// chatter_resolution finite and >= 0 (0 turns that cut off), chatter_stiffness_growth > 1 (infinity turns it
/// off), max_events and max_steps > 0, max_seconds in (0, 60].
/// solveMultipleImpact refuses options that fail it.
Status validate(const SolverOptions& options, const std::string& field = "options");

}  // namespace billiard_shot_planner
