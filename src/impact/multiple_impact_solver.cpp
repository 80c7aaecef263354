#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"

#include <chrono>

#include "billiard_shot_planner/core/validation.hpp"

#include "dense_stepper.hpp"  // first: its Boost 1.74 workaround must come before any Boost.Math header

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "affine_crossing_search.hpp"
#include "contact_dynamics.hpp"
#include "contact_space.hpp"
#include "linear_phase.hpp"
#include "quasi_steady_slip.hpp"
#include "sampled_crossing_search.hpp"
#include "separation_clock.hpp"
#include "state_transitions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Closed-form steps, in radians of the fastest mode: the guards are sums of sines of at most that frequency, so
/// with SampledCrossingSearch::SAMPLES_PER_STEP samples a step sees any crossing pair more than a quarter radian apart
/// by their signs, and firstRise looks between the samples for closer ones. Finer when the impulse curve is recorded
/// for plots. docs/engine.md, "Closed form of linear phases".
constexpr double RADIANS_PER_CLOSED_FORM_STEP = 1.0;
constexpr double RADIANS_PER_RECORDED_STEP = 0.125;

/// Normal speeds (dimensionless) below this many absolute tolerances are not resolved by the integrator.
constexpr double UNRESOLVED_SPEED = 100.0;

/// Zero-time transitions one contact may make at one instant (see ImpactSolver::settle).
constexpr int MAX_SWITCHES_PER_INSTANT = 6;

/// Integrates the spring dynamics from event to event and runs the state transition diagram (docs/engine.md,
/// "Formulation"). Which slip directions follow their slip is QuasiSteadySlip's to decide, where a numerically
/// integrated state's next transition lies SampledCrossingSearch's to find.
class ImpactSolver
{
public:
  ImpactSolver(const ImpactProblem& problem, const SolverOptions& options)
      : problem_(problem),
        options_(options),
        space_(buildContactSpace(problem)),
        contacts_(initialContactStates(problem, space_)),
        dynamics_(space_, contacts_, QuasiSteadySlip::relaxationLimit(options)),
        springs_(dynamics_),
        slip_(options, space_, contacts_, dynamics_),
        sampled_search_(space_, contacts_, dynamics_, static_cast<std::size_t>(2 * space_.size)),
        y_(static_cast<std::size_t>(2 * space_.size), 0.0),
        recorded_state_(y_.size())
  {
    result_.initial_kinetic_energy = kineticEnergy(problem.velocity);
    chatter_.energy = options.chatter_energy_fraction * result_.initial_kinetic_energy / space_.energy_scale;
    chatter_.stiffness_growth = options.chatter_stiffness_growth;
  }

  Expected<ImpactResult> run()
  {
    chooseRestingModes(dynamics_, y_, contacts_, space_);
    for (const ContactState& contact : contacts_)
      result_.initially_slipping.push_back(contact.sliding());
    if (auto status = settle(); !status)
      return status.error();
    while (anyActive())
    {
      auto advanced = advanceToNextEvent();
      if (!advanced)
        return advanced.error();
      if (auto status = settle(); !status)
        return status.error();
    }
    return finish();
  }

private:
  double kineticEnergy(const Eigen::VectorXd& u)
  {
    // Coefficient-wise products (lazyProduct) here and in snapshot: on a few balls' sizes Eigen's general
    // matrix–vector kernel spends more on dispatch than on arithmetic.
    momentum_.noalias() = problem_.mass_matrix.lazyProduct(u);
    return 0.5 * u.dot(momentum_);
  }

  bool anyActive() const
  {
    for (const ContactState& contact : contacts_)
      if (contact.active())
        return true;
    return false;
  }

  ImpactSnapshot snapshot(const double* y, double t)
  {
    ImpactSnapshot snap;
    snap.time = t * space_.time_scale;
    snap.velocity = problem_.velocity;
    snap.velocity.noalias() +=
        space_.impulse_scale * space_.response.lazyProduct(Eigen::Map<const Eigen::VectorXd>(y, space_.size));
    snap.kinetic_energy = kineticEnergy(snap.velocity);
    const auto n = static_cast<Eigen::Index>(contacts_.size());
    snap.normal_impulses.resize(n);
    snap.strain_energies.resize(n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
      snap.normal_impulses(i) = y[space_.offset[i]] * space_.impulse_scale;
      snap.strain_energies(i) = dynamics_.strainEnergy(i, y, energy_scratch_) * space_.energy_scale;
    }
    return snap;
  }

  /// Whether `set` lists exactly the active contacts (without building the list: called after every event).
  bool isActiveSet(const std::vector<std::size_t>& set) const
  {
    std::size_t k = 0;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (contacts_[i].active() && (k >= set.size() || set[k++] != i))
        return false;
    return k == set.size();
  }

  std::vector<std::size_t> activeSet() const
  {
    std::vector<std::size_t> active;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (contacts_[i].active())
        active.push_back(i);
    return active;
  }

  Status countEvent()
  {
    if (++event_count_ > options_.max_events)
      return Error{ErrorKind::EventLimitExceeded, "",
                   "the state sequence did not end within " + std::to_string(options_.max_events) + " events"};
    return checkClock();
  }

  /// The wall-clock bound of one solve (SolverOptions::max_seconds), read at every event and integrator step
  /// (docs/engine.md, "Bounds and errors").
  Status checkClock() const
  {
    if (std::chrono::steady_clock::now() <= deadline_)
      return {};
    return Error{ErrorKind::TimeLimitExceeded, "",
                 "the impact did not end within " + formatNumber(options_.max_seconds) + " s (" +
                     std::to_string(event_count_) + " events, " + std::to_string(step_count_) + " integrator steps)"};
  }

  Status fire(const Guard& guard)
  {
    if (guard.releases_direction)
    {
      slip_.release(guard.contact, y_);
      return {};
    }
    if (auto status = countEvent(); !status)
      return status;
    evaluateKinematics(dynamics_, y_.data(), event_kinematics_);
    for (ContactEventType type : applyTransition(guard, event_kinematics_, y_.data(), contacts_, space_, chatter_))
    {
      dynamics_.refresh();
      result_.events.push_back({type, guard.contact, snapshot(y_.data(), t_)});
    }
    return {};
  }

  /// Fires every transition due at the current instant, then records the state if the active set changed.
  Status settle()
  {
    slip_.integrateEverySlipWhenOff(y_);
    dynamics_.refresh();
    // A contact whose rigid-link force and grazing acceleration disagree in sign (friction coupling, as in
    // Painlevé's paradox) could switch forever at one instant: after a few switches it is left as it is, and its
    // guards decide from then on (docs/impact_model.md, "Chatter limits and rigid links").
    switches_.assign(contacts_.size(), 0);
    settled_.assign(contacts_.size(), false);
    while (true)
    {
      evaluateKinematics(dynamics_, y_.data(), event_kinematics_);
      std::optional<Guard> guard;
      if (std::any_of(contacts_.begin(), contacts_.end(),
                      [](const ContactState& c) { return c.phase == NormalPhase::RigidLink && c.tangential.slipping; }))
        guard = jammedLink(dynamics_, event_kinematics_, contacts_, space_, settled_);
      if (!guard)
        guard = immediateTransition(event_kinematics_, contacts_, space_, settled_);
      if (!guard)
        break;
      if (auto status = fire(*guard); !status)
        return status;
      settled_[guard->contact] = ++switches_[guard->contact] >= MAX_SWITCHES_PER_INSTANT;
    }
    slip_.integrateEverySlipWhenOff(y_);
    if (result_.states.empty() || !isActiveSet(result_.states.back().active))
      result_.states.push_back({activeSet(), snapshot(y_.data(), t_)});
    return {};
  }

  /// Angular frequency bound of the active springs: the largest eigenvalue of W K is at most its trace, K the springs'
  /// tangent stiffnesses at the present deformations.
  double fastestFrequency() const
  {
    double trace = 0.0;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
    {
      if (!contacts_[i].active())
        continue;
      const int row = space_.offset[i];
      if (contacts_[i].compliant())
        trace += space_.delassus(row, row) * contacts_[i].normal.stiffnessAt(y_.data()[space_.size + row]);
      if (space_.dim[i] == 3)
        trace +=
            (space_.delassus(row + 1, row + 1) + space_.delassus(row + 2, row + 2)) * contacts_[i].tangential.kappa;
    }
    return std::sqrt(std::max(trace, std::numeric_limits<double>::min()));
  }

  /// The closed form holds slip directions fixed. A contact following its slip joins it only when its direction
  /// cannot turn, and then releasing it is exact; otherwise it keeps following. Builds closed_form_; false when the
  /// state is not linear.
  bool tryClosedForm()
  {
    slip_.releaseAll(y_);
    const bool linear =
        closed_form_.build(space_, contacts_, dynamics_, y_, t_,
                           options_.record_samples ? RADIANS_PER_RECORDED_STEP : RADIANS_PER_CLOSED_FORM_STEP);
    if (!linear)
      slip_.followReleasedAgain();
    return linear;
  }

  /// Integrates to the next transition: in closed form where the dynamics is linear (no sliding direction can
  /// turn), otherwise with Bulirsch–Stoer, on the separation clock while a sliding contact may separate.
  Expected<bool> advanceToNextEvent()
  {
    const bool closed_form = options_.closed_form_linear_phases && tryClosedForm();
    // A chatter is cut where the method stops resolving it (SolverOptions::chatter_resolution): the integrator
    // holds springs to its absolute tolerance, the closed form to round-off. Cut at the integrator's resolution in a
    // closed form, a contact that merely touches lightly three times would become a rigid link (docs/engine.md,
    // "Chatter and rigid links").
    chatter_.deformation = closed_form ? 0.0 : options_.chatter_resolution * options_.absolute_tolerance;
    if (closed_form)
      return advanceAffine();
    // Likewise a normal velocity: the integrator holds it to about its absolute tolerance. A contact at rest at the
    // far end of a chain has that noise for its velocity until the collision reaches it: without the floor it would
    // end its compression at t = 0 on the noise, separate and come back.
    const double separation_floor = std::max(VELOCITY_TOLERANCE, UNRESOLVED_SPEED * options_.absolute_tolerance);
    slip_.startIntegratedState(y_);
    const std::vector<Guard>& guards = armedGuards(contacts_, space_, guards_);
    const double omega = fastestFrequency();
    // 0.1 rad of the fastest mode, near the steps the tolerance allows: Bulirsch–Stoer grows a step at most fourfold
    // per step, so a smaller start costs steps at every state.
    const double first_step = 0.1 / omega;
    if (options_.separation_clock &&
        std::any_of(contacts_.begin(), contacts_.end(), [](const ContactState& c) { return c.slidingInRestitution(); }))
    {
      if (!clock_stepper_)
        clock_stepper_.emplace(dynamics_, options_.absolute_tolerance, options_.relative_tolerance);
      clock_stepper_->restart(y_, t_, first_step);
      return advanceWith(*clock_stepper_, guards, separation_floor, omega);
    }
    if (!plain_stepper_)
      plain_stepper_.emplace(options_.absolute_tolerance, options_.relative_tolerance);
    plain_stepper_->restart(y_, t_, 0.5 / omega, first_step);
    return advanceWith(*plain_stepper_, guards, separation_floor, omega);
  }

  /// A closed-form state whose guards are all affine is searched with bounds (AffineCrossingSearch); otherwise (a
  /// guard not affine, one above zero at the start, or the impulse curve recorded) with samples.
  Expected<bool> advanceAffine()
  {
    const std::vector<Guard>& guards = armedGuards(contacts_, space_, guards_);
    affine_guards_.clear();
    for (const Guard& guard : guards)
      affine_guards_.push_back(affineForm(guard, contacts_, space_));
    const bool all_affine = std::all_of(affine_guards_.begin(), affine_guards_.end(),
                                        [](const std::optional<AffineGuard>& form) { return form.has_value(); });
    if (!all_affine || options_.record_samples || !affine_search_.start(closed_form_, affine_guards_, t_))
      return advanceWith(closed_form_, guards, /*separation_floor=*/0.0, /*omega: the closed form's own=*/0.0);
    affine_search_.setDeadline(deadline_);
    while (true)
    {
      if (++step_count_ > options_.max_steps)
        return stepLimitError();
      if (auto status = checkClock(); !status)
        return status.error();
      const PerGuard<GuardZero>& zeros = affine_search_.nextStep();
      if (zeros.empty())
        continue;
      affine_crossings_.clear();
      for (const GuardZero& zero : zeros)
        affine_crossings_.push_back({guards[zero.guard], zero.time});
      const std::vector<FiredGuard>& fired =
          earliestCrossings(affine_crossings_, affine_search_.stepLength(), affine_fired_);
      if (auto status = fireAll(closed_form_, fired); !status)
        return status.error();
      return true;
    }
  }

  /// Moves to the instant of `fired` (not empty) and fires its transitions.
  template <class Stepper>
  Status fireAll(const Stepper& stepper, const std::vector<FiredGuard>& fired)
  {
    stepper.calc_state(fired.front().time, y_);
    t_ = physicalTime(stepper, fired.front().time);
    for (const FiredGuard& f : fired)
      if (auto status = fire(f.guard); !status)
        return status;
    return {};
  }

  Error stepLimitError() const
  {
    return Error{ErrorKind::StepLimitExceeded, "",
                 "the impact did not end within " + std::to_string(options_.max_steps) + " integrator steps"};
  }

  /// Steps through the state to its next transition, sampling `guards` (SampledCrossingSearch::start).
  template <class Stepper>
  Expected<bool> advanceWith(Stepper& stepper, const std::vector<Guard>& guards, double separation_floor, double omega)
  {
    slip_.restartChecks();
    sampled_search_.start(stepper, guards, y_.data(), separation_floor, omega);
    while (true)
    {
      if (++step_count_ > options_.max_steps)
        return stepLimitError();
      if (auto status = checkClock(); !status)
        return status.error();
      const auto [t0, t1] = stepper.do_step(std::ref(springs_));
      sampled_search_.sampleStep(stepper, t0, t1);
      const bool slip_may_follow = slipMayFollow(stepper);
      const std::vector<FiredGuard>& fired = sampled_search_.firedGuards(stepper, t0, t1);
      if (fired.empty())
      {
        recordSamples(stepper, t0, t1);
        if (aSlipHasRelaxed(stepper, t1, slip_may_follow))
        {
          stepper.calc_state(t1, y_);
          t_ = physicalTime(stepper, t1);
          return true;
        }
        sampled_search_.startNextStep(t0, t1);
        continue;
      }
      recordSamples(stepper, t0, fired.front().time);
      if (auto status = fireAll(stepper, fired); !status)
        return status.error();
      if (options_.record_samples)
        result_.samples.push_back(snapshot(y_.data(), t_));  // after the jump (e.g. the energy loss at A → A')
      return true;
    }
  }

  /// Whether some integrated slip could be handed to the quasi-steady lag mid-state, from the kinematics at the end
  /// of the step just sampled.
  template <class Stepper>
  bool slipMayFollow(const Stepper& /*stepper*/) const
  {
    return slip_.anIntegratedSlipRelaxesFast(sampled_search_.sampledEnd());
  }

  /// The closed form holds its slips fixed.
  bool slipMayFollow(const LinearPhaseStepper& /*stepper*/) const { return false; }

  /// Whether at the end t1 of a step some integrated slip direction has relaxed onto its quasi-steady one, so that
  /// the state ends there for QuasiSteadySlip::startIntegratedState to take it.
  template <class Stepper>
  bool aSlipHasRelaxed(const Stepper& stepper, double t1, bool slip_may_follow)
  {
    if (!slip_may_follow || !slip_.checkDue(step_count_))
      return false;
    // Evaluated again: the crossing search may have evaluated other instants since the samples.
    return slip_.anIntegratedSlipHasRelaxed(sampled_search_.evaluateAt(stepper, t1), step_count_);
  }

  /// Points of the impulse curve in (t0, t1], at the instants of the step's guard samples, for plots.
  template <class Stepper>
  void recordSamples(const Stepper& stepper, double t0, double t1)
  {
    if (!options_.record_samples)
      return;
    for (int k = 1; k <= sampled_search_.samplesPerStep(); ++k)
    {
      const double t = sampled_search_.sampleTime(t0, t1, k);
      stepper.calc_state(t, recorded_state_);
      result_.samples.push_back(snapshot(recorded_state_.data(), physicalTime(stepper, t)));
    }
  }

  Expected<ImpactResult> finish()
  {
    const ImpactSnapshot last = snapshot(y_.data(), t_);
    result_.velocity = last.velocity;
    result_.final_kinetic_energy = last.kinetic_energy;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
    {
      const int row = space_.offset[i];
      ContactImpulse impulse;
      impulse.normal = y_[row] * space_.impulse_scale;
      if (space_.dim[i] == 3)
        impulse.tangential = Eigen::Vector2d(y_[row + 1], y_[row + 2]) * space_.impulse_scale;
      result_.impulses.push_back(impulse);
      result_.ends_of_compression.push_back(contacts_[i].ends_of_compression);
      result_.converged = result_.converged || contacts_[i].chattered;
    }
    return std::move(result_);
  }

  const ImpactProblem& problem_;
  const SolverOptions& options_;
  ContactSpace space_;
  std::vector<ContactState> contacts_;
  ContactDynamics dynamics_;
  SpringSystem springs_;  ///< the dynamics as the integrator's system
  QuasiSteadySlip slip_;
  LinearPhaseStepper closed_form_;  ///< rebuilt at every linear state (its storage kept)
  /// Numerical steppers, made at their first use and restarted at every state (their storage kept).
  std::optional<DenseStepper> plain_stepper_;
  std::optional<SeparationClockStepper> clock_stepper_;
  SampledCrossingSearch sampled_search_;
  ChatterLimit chatter_{};
  OdeState y_;
  OdeState recorded_state_;         ///< a point of the impulse curve (recordSamples)
  Kinematics event_kinematics_{};   ///< at the current instant, for transitions
  ForceEvaluation energy_scratch_;  ///< of strainEnergy
  Eigen::VectorXd momentum_;        ///< scratch of kineticEnergy
  // Storage kept across the solve (a short impact is a few states, and allocating per event would be a large part
  // of its cost).
  std::vector<Guard> guards_;
  PerGuard<std::optional<AffineGuard>> affine_guards_;  ///< of guards_
  AffineCrossingSearch affine_search_;
  std::vector<FiredGuard> affine_crossings_, affine_fired_;
  std::vector<int> switches_;
  std::vector<bool> settled_;
  double t_ = 0.0;
  std::size_t event_count_ = 0;
  std::size_t step_count_ = 0;
  std::chrono::steady_clock::time_point deadline_ =
      std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(options_.max_seconds));
  ImpactResult result_;
};
}  // namespace
}  // namespace detail

Expected<ImpactResult> solveMultipleImpact(const ImpactProblem& problem, const SolverOptions& options)
{
  if (Status status = validate(problem); !status)
    return status.error();
  if (Status status = validate(options); !status)
    return status.error();
  try
  {
    auto result = detail::ImpactSolver(problem, options).run();
    // An answer never carries NaN or infinity: a failure the checks above did not foresee is reported as one.
    if (result && !(result.value().velocity.allFinite() && std::isfinite(result.value().final_kinetic_energy)))
      return Error{ErrorKind::NumericalFailure, "", "numerical failure: the final velocities are not finite"};
    return result;
  }
  catch (const std::exception& e)
  {
    // Odeint signals a step size collapse, and Boost.Math a failed bracket, by exceptions.
    return Error{ErrorKind::NumericalFailure, "", std::string("numerical failure: ") + e.what()};
  }
}

}  // namespace billiard_shot_planner
