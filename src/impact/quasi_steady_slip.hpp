#pragma once

#include <cstddef>
#include <vector>

#include "billiard_shot_planner/impact/solver_options.hpp"
#include "contact_dynamics.hpp"
#include "contact_space.hpp"
#include "contact_state.hpp"
#include "state_transitions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Which sliding contacts have their slip direction follow the slip quasi-steadily (TangentialSpring::quasi_steady)
/// instead of integrating it, and the switches between the two (SolverOptions::quasi_steady_slip; docs/engine.md,
/// "Quasi-steady slip").
///
/// A slip direction relaxes onto the slip in the time ε = ρ/|v_t|, ρ = μF_n/κ its spring on the friction cone: a
/// stiff equation for the explicit integrator where ε is short. There the direction follows the slip with its
/// second-order lag (ContactDynamics), and it is integrated again once ε reaches the quasi-steady limit
/// (relaxationLimit). Changes the contacts' modes and their carriers in the ODE state, and refreshes the dynamics.
class QuasiSteadySlip
{
public:
  QuasiSteadySlip(const SolverOptions& options, const ContactSpace& space, std::vector<ContactState>& contacts,
                  ContactDynamics& dynamics);

  /// The longest relaxation time ε = ρ/|v_t| (in units of the collision's time) of a slip direction that follows
  /// its slip quasi-steadily.
  static double relaxationLimit(const SolverOptions& options);

  /// The contact's slip direction is integrated from now on, starting where it was following the slip: its carrier
  /// in y is set to that direction.
  void release(std::size_t contact, OdeState& y);
  /// With SolverOptions::quasi_steady_slip off, releases every slip direction that follows its slip.
  void integrateEverySlipWhenOff(OdeState& y);
  /// Releases every slip direction that follows its slip, for a closed form (which holds the directions fixed).
  void releaseAll(OdeState& y);
  /// The directions releaseAll released follow their slip again (the state had no closed form after all).
  void followReleasedAgain();
  /// At the start of a numerically integrated state at y: releases the followed directions that relax too slowly,
  /// and lets the integrated ones that relax fast and have relaxed onto their slip follow it.
  void startIntegratedState(OdeState& y);

  /// Whether some contact could be handed to the quasi-steady lag mid-state, from the kinematics `at` the end of a
  /// step: its integrated slip relaxes fast and it is not on its way to separation with a fast-shrinking cone.
  bool anIntegratedSlipRelaxesFast(const Kinematics& at) const;
  /// Restarts the checks of anIntegratedSlipHasRelaxed (at the start of a state).
  void restartChecks();
  /// Whether anIntegratedSlipHasRelaxed checks at integrator step `step`.
  bool checkDue(std::size_t step) const { return step >= next_check_; }
  /// Whether some integrated slip direction has relaxed onto its quasi-steady one at `at`, the end of integrator
  /// step `step`, so that the state ends there for startIntegratedState to take it. When none has, the next check
  /// is put off twice as many steps as the last.
  bool anIntegratedSlipHasRelaxed(const Kinematics& at, std::size_t step);

private:
  /// Releases the followed directions whose relaxation time has reached the limit at y.
  void releaseSlowRelaxations(OdeState& y);
  /// Lets the integrated directions that relax fast and have relaxed onto their slip at y follow it.
  void followShortSlips(const OdeState& y);
  /// Whether contact i slides on an integrated direction whose relaxation time is below the quasi-steady limit.
  bool relaxesFast(std::size_t i, const Kinematics& at) const;
  /// Whether contact i slides toward its separation with a cone that shrinks fast against its slip.
  bool shrinksToSeparation(std::size_t i, const Kinematics& at) const;
  /// Whether contact i relaxes fast (relaxesFast) and its integrated direction agrees with the one following its
  /// slip would give at `at`; `scratch` takes that evaluation.
  bool hasRelaxedOntoItsSlip(std::size_t i, const Kinematics& at, ForceEvaluation& scratch) const;

  bool enabled_;
  const ContactSpace& space_;
  std::vector<ContactState>& contacts_;
  ContactDynamics& dynamics_;
  Kinematics kinematics_{};            ///< at a state's start
  ForceEvaluation scratch_;            ///< of the evaluations that only a slip direction is read from
  std::vector<std::size_t> released_;  ///< by releaseAll
  std::size_t next_check_ = 0;         ///< first integrator step at which anIntegratedSlipHasRelaxed checks
  std::size_t check_interval_ = 1;     ///< steps between its last two checks
};

}  // namespace detail
}  // namespace billiard_shot_planner
