#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"

#include <chrono>

#include "billiard_shot_planner/core/validation.hpp"

#include "dense_stepper.hpp"  // first: its Boost 1.74 workaround must come before any Boost.Math header

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "affine_crossing_search.hpp"
#include "contact_dynamics.hpp"
#include "contact_space.hpp"
#include "linear_phase.hpp"
#include "sampled_rise_search.hpp"
#include "separation_clock.hpp"
#include "state_transitions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Guard samples per integrator step: with steps bounded by a fraction of the fastest contact period this
/// catches transitions that fire and reset within one step.
constexpr int SAMPLES_PER_STEP = 4;
/// Bound on how many times a step's guard sampling is refined (a step of the separation clock spanning many
/// periods; it only happens where the clock runs at nearly physical speed).
constexpr double MAX_STEP_SUBDIVISION = 64.0;

/// Closed-form steps, in radians of the fastest mode: the guards are sums of sines of at most that frequency, so
/// with SAMPLES_PER_STEP samples a step sees any crossing pair more than a quarter radian apart by their signs, and
/// firstRise looks between the samples for closer ones. Finer when the impulse curve is recorded for plots.
constexpr double RADIANS_PER_CLOSED_FORM_STEP = 1.0;
constexpr double RADIANS_PER_RECORDED_STEP = 0.125;

/// How closely an integrated slip direction must agree with the quasi-steady one for a sliding contact with a short
/// cone to follow its slip from then on (see ImpactSolver::followShortSlips): the jump it makes is at most this.
constexpr double DIRECTION_AGREEMENT = 1e-6;

/// A slip on its way to separation is handed to the quasi-steady lag mid-state only while its cone shrinks slower
/// than this fraction of its slip speed (see ImpactSolver::shrinksToSeparation).
constexpr double SEPARATION_RATE_FOLLOW = 0.01;

/// Normal speeds (dimensionless) below this many absolute tolerances are not resolved by the integrator.
constexpr double UNRESOLVED_SPEED = 100.0;

/// Zero-time transitions one contact may make at one instant (see ImpactSolver::settle).
constexpr int MAX_SWITCHES_PER_INSTANT = 6;

/// Evaluations allowed to TOMS 748 for one guard's zero (it converges in about ten).
constexpr int MAX_ROOT_ITERATIONS = 100;

/// The longest relaxation time ε = ρ/|v_t| (in units of the collision's time) of a slip direction that follows its
/// slip quasi-steadily. The second-order lag leaves errors of order ε⁴ in the friction (a cushion hit on the cloth:
/// 1.1e-12 at 5e-4, 1.1e-11 at 1e-3, 1.7e-10 at 2e-3, against integration from the start), so the limit is
/// (tolerance/10)^¼: 5.6e-4 at the default tolerance. At most 1e-2, where the expansion's terms no longer shrink.
double quasiSteadyRelaxation(const SolverOptions& options)
{
  return std::min(std::pow(0.1 * options.relative_tolerance, 0.25), 1e-2);
}

struct FiredGuard
{
  Guard guard;
  double time;
};

/// Integrates the spring dynamics from event to event and runs the state transition diagram.
class ImpactSolver
{
public:
  ImpactSolver(const ImpactProblem& problem, const SolverOptions& options)
      : problem_(problem),
        options_(options),
        space_(buildContactSpace(problem)),
        contacts_(initialContactStates(problem, space_)),
        dynamics_(space_, contacts_, quasiSteadyRelaxation(options)),
        springs_(dynamics_),
        y_(static_cast<std::size_t>(2 * space_.size), 0.0),
        buffer_(y_.size())
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
  double kineticEnergy(const Eigen::VectorXd& u) const
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
      snap.strain_energies(i) = dynamics_.strainEnergy(i, y, scratch_) * space_.energy_scale;
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
      return Error{ErrorCode::EventLimitExceeded, "",
                   "the state sequence did not end within " + std::to_string(options_.max_events) + " events"};
    return checkClock();
  }

  /// The wall-clock bound of one solve (SolverOptions::max_seconds), read at every event and integrator step.
  Status checkClock() const
  {
    if (std::chrono::steady_clock::now() <= deadline_)
      return {};
    return Error{ErrorCode::TimeLimitExceeded, "",
                 "the impact did not end within " + formatNumber(options_.max_seconds) + " s (" +
                     std::to_string(event_count_) + " events, " + std::to_string(step_count_) + " integrator steps)"};
  }

  /// The contact's slip direction is integrated from now on, starting where it was following the slip.
  void releaseDirection(std::size_t contact)
  {
    const Eigen::Vector2d direction = dynamics_.slipDirection(contact, y_.data(), scratch_);
    contacts_[contact].quasi_steady = false;
    double* carrier = y_.data() + space_.size + space_.offset[contact] + 1;
    carrier[0] = direction.x();
    carrier[1] = direction.y();
    dynamics_.refresh();
  }

  Status fire(const Guard& guard)
  {
    if (guard.releases_direction)
    {
      releaseDirection(guard.contact);
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

  /// With SolverOptions::quasi_steady_slip off, every slip direction is integrated from its start.
  void integrateEverySlipDirection()
  {
    if (options_.quasi_steady_slip)
      return;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (contacts_[i].followsSlip())
        releaseDirection(i);
  }

  /// Fires every transition due at the current instant, then records the state if the active set changed.
  Status settle()
  {
    integrateEverySlipDirection();
    dynamics_.refresh();
    // A contact whose rigid-link force and grazing acceleration disagree in sign (friction coupling, as in
    // Painlevé's paradox) could switch forever at one instant: after a few switches it is left as it is, and its
    // guards decide from then on.
    switches_.assign(contacts_.size(), 0);
    settled_.assign(contacts_.size(), false);
    while (true)
    {
      evaluateKinematics(dynamics_, y_.data(), event_kinematics_);
      std::optional<Guard> guard;
      if (std::any_of(contacts_.begin(), contacts_.end(),
                      [](const ContactState& c) { return c.phase == NormalPhase::RigidLink && c.slipping; }))
        guard = jammedLink(dynamics_, event_kinematics_, contacts_, space_, settled_);
      if (!guard)
        guard = immediateTransition(event_kinematics_, contacts_, space_, settled_);
      if (!guard)
        break;
      if (auto status = fire(*guard); !status)
        return status;
      settled_[guard->contact] = ++switches_[guard->contact] >= MAX_SWITCHES_PER_INSTANT;
    }
    integrateEverySlipDirection();
    if (result_.states.empty() || !isActiveSet(result_.states.back().active))
      result_.states.push_back({activeSet(), snapshot(y_.data(), t_)});
    return {};
  }

  /// Angular frequency bound of the active springs: the largest eigenvalue of W K is at most its trace.
  double fastestFrequency() const
  {
    double trace = 0.0;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
    {
      if (!contacts_[i].active())
        continue;
      const int row = space_.offset[i];
      if (contacts_[i].compliant())
        trace += space_.delassus(row, row) * contacts_[i].stiffness;
      if (space_.dim[i] == 3)
        trace += (space_.delassus(row + 1, row + 1) + space_.delassus(row + 2, row + 2)) * contacts_[i].kappa;
    }
    return std::sqrt(std::max(trace, std::numeric_limits<double>::min()));
  }

  /// The closed form holds slip directions fixed. A contact following its slip joins it only when its direction
  /// cannot turn, and then releasing it is exact; otherwise it keeps following. Builds closed_form_; false when the
  /// state is not linear.
  bool tryClosedForm()
  {
    std::vector<std::size_t> following;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (contacts_[i].followsSlip())
        following.push_back(i);
    for (std::size_t i : following)
      releaseDirection(i);
    const bool linear =
        closed_form_.build(space_, contacts_, dynamics_, y_, t_,
                           options_.record_samples ? RADIANS_PER_RECORDED_STEP : RADIANS_PER_CLOSED_FORM_STEP);
    if (!linear && !following.empty())
    {
      for (std::size_t i : following)
        contacts_[i].quasi_steady = true;
      dynamics_.refresh();
    }
    return linear;
  }

  /// A contact that follows its slip is released once its relaxation time reaches the quasi-steady limit, by a
  /// guard that rises through it. One that starts a state beyond it is released at once: a rigid link reactivated
  /// sliding (a plastic tip touching again) carries a finite force from its first instant, its guard started above
  /// zero and never rose, and the lag stayed in use at 25 times the limit (a random strike, which then ran to the
  /// step bound).
  void releaseSlowRelaxations()
  {
    if (!std::any_of(contacts_.begin(), contacts_.end(), [](const ContactState& c) { return c.followsSlip(); }))
      return;
    evaluateKinematics(dynamics_, y_.data(), event_kinematics_);
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (contacts_[i].followsSlip() &&
          dynamics_.relaxationRatio(i, event_kinematics_.velocity, event_kinematics_.force) >= 1.0)
        releaseDirection(i);
  }

  /// A sliding contact whose direction relaxes faster than the quasi-steady limit (its spring on the friction cone
  /// short against its slip) turns it at |v_t|/ρ, a stiff equation for explicit integration. In an integrated
  /// state it follows its slip quasi-steadily instead, as a slip from relaxed springs does, when its direction
  /// already agrees with the quasi-steady one to DIRECTION_AGREEMENT (it has relaxed onto it; one that has just slipped
  /// from a loaded spring has not, and stays integrated). A cushion grazed at 4e-8 m/s, loading its contacts with 1e-8,
  /// took 300 000 steps of 5e-6 otherwise (random table sweep).
  void followShortSlips()
  {
    if (!options_.quasi_steady_slip)
      return;
    evaluateKinematics(dynamics_, y_.data(), event_kinematics_);
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (hasRelaxedOntoItsSlip(i, y_.data(), event_kinematics_))
      {
        contacts_[i].quasi_steady = true;
        dynamics_.refresh();
      }
  }

  /// Whether contact i slides on an integrated direction that relaxes faster than the quasi-steady limit and has
  /// relaxed onto its quasi-steady direction (to DIRECTION_AGREEMENT) at y, whose kinematics are given. A query: the
  /// quasi-steady direction is the one following the slip would give, the contact's mode stays as it is.
  bool hasRelaxedOntoItsSlip(std::size_t i, const double* y, const Kinematics& kinematics)
  {
    if (!relaxesFast(i, kinematics))
      return false;
    const Eigen::Vector2d integrated = dynamics_.carrierDirection(i, y);
    return (dynamics_.followedSlipDirection(i, y, scratch_) - integrated).norm() <= DIRECTION_AGREEMENT;
  }

  /// Whether at the end t1 of a step some integrated slip direction has relaxed onto its quasi-steady one, so that
  /// the state should end there for followShortSlips to take it. A tip that slips from a loaded spring and turns
  /// into a rigid link has not relaxed when its state starts, but does a few relaxation times later: integrated on,
  /// with a relaxation time of 1e-6 of the collision's, a grazing hit on a nearly plastic cushion took 153 000 steps
  /// (a random table of a wide sweep, 5.9 s).
  template <class Stepper>
  bool aSlipHasRelaxed(const Stepper& stepper, double t1)
  {
    if (!slip_may_follow_ || step_count_ < next_follow_check_)
      return false;
    evaluateAt(stepper, t1);  // the crossing search may have evaluated other instants since the samples
    // The same slips as the candidate flag: one shrinking to separation stays on the clock even when another
    // contact raised the flag.
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (!shrinksToSeparation(i, kinematics_buffer_) && hasRelaxedOntoItsSlip(i, buffer_.data(), kinematics_buffer_))
        return true;
    // A slip that has not relaxed may take long to (on its way to separation its cone shrinks faster than its
    // direction turns, and it never does): the checks, three force evaluations each, back off geometrically. Every
    // step, they cost the bench's three cushion hits 12 % more instructions.
    follow_check_interval_ *= 2;
    next_follow_check_ = step_count_ + follow_check_interval_;
    return false;
  }

  /// The closed form holds its slip directions fixed.
  bool aSlipHasRelaxed(const LinearPhaseStepper& /*stepper*/, double /*t1*/) { return false; }

  /// Integrates to the next transition: in closed form where the dynamics is linear (no sliding direction can
  /// turn), otherwise with Bulirsch–Stoer, on the separation clock while a sliding contact may separate.
  Expected<bool> advanceToNextEvent()
  {
    const bool closed_form = options_.closed_form_linear_phases && tryClosedForm();
    // A chatter is cut where the method stops resolving it (SolverOptions::chatter_resolution): the integrator
    // holds springs to its absolute tolerance, the closed form to round-off. Cut in a closed-form chain, a contact
    // that merely touched lightly three times became a rigid link and the chain ended 7e-3 off.
    chatter_.deformation = closed_form ? 0.0 : options_.chatter_resolution * options_.absolute_tolerance;
    // Likewise a normal velocity: the integrator holds it to about its absolute tolerance. A contact at rest at the
    // far end of a chain, whose velocity is that noise until the collision reaches it, ended its compression at
    // t = 0 on it, separated and came back: 129 of 2 000 random chains ended more than 1e-3 off the closed form.
    separation_floor_ =
        closed_form ? 0.0 : std::max(VELOCITY_TOLERANCE, UNRESOLVED_SPEED * options_.absolute_tolerance);
    if (closed_form)
      return advanceAffine();
    releaseSlowRelaxations();
    followShortSlips();
    const std::vector<Guard>& guards = armedGuards(contacts_, space_, guards_);
    omega_ = fastestFrequency();
    // 0.1 rad of the fastest mode, near the steps the tolerance allows: Bulirsch–Stoer grows a step at most fourfold
    // per step, so a smaller start costs steps at every state (0.01 rad: massé strike +22 % instructions).
    const double first_step = 0.1 / omega_;
    if (options_.separation_clock &&
        std::any_of(contacts_.begin(), contacts_.end(), [](const ContactState& c) { return c.slidingInRestitution(); }))
    {
      if (!clock_stepper_)
        clock_stepper_.emplace(dynamics_, options_.absolute_tolerance, options_.relative_tolerance);
      clock_stepper_->restart(y_, t_, first_step);
      return advanceWith(*clock_stepper_, guards);
    }
    if (!plain_stepper_)
      plain_stepper_.emplace(options_.absolute_tolerance, options_.relative_tolerance);
    plain_stepper_->restart(y_, t_, 0.5 / omega_, first_step);
    return advanceWith(*plain_stepper_, guards);
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
      return advanceWith(closed_form_, guards);
    while (true)
    {
      if (++step_count_ > options_.max_steps)
        return stepLimitError();
      if (auto status = checkClock(); !status)
        return status.error();
      const PerGuard<GuardZero>& zeros = affine_search_.nextStep();
      if (zeros.empty())
        continue;
      crossings_.clear();
      for (const GuardZero& zero : zeros)
        crossings_.push_back({guards[zero.guard], zero.time});
      if (auto status = fireAll(closed_form_, earliestCrossings(affine_search_.stepLength())); !status)
        return status.error();
      return true;
    }
  }

  /// The earliest of crossings_ with every other within round-off of it (of a step `width`), all at the earliest
  /// instant, into fired_.
  const std::vector<FiredGuard>& earliestCrossings(double width)
  {
    fired_.clear();
    if (crossings_.empty())
      return fired_;
    double first = crossings_.front().time;
    for (const FiredGuard& c : crossings_)
      first = std::min(first, c.time);
    for (const FiredGuard& c : crossings_)
      if (c.time <= first + SIMULTANEOUS * width)
        fired_.push_back({c.guard, first});
    return fired_;
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
    return Error{ErrorCode::StepLimitExceeded, "",
                 "the impact did not end within " + std::to_string(options_.max_steps) + " integrator steps"};
  }

  /// Steps through the state to its next transition, sampling `guards`: the state's armed guards, guards_ (the root
  /// finding reads them by index).
  template <class Stepper>
  Expected<bool> advanceWith(Stepper& stepper, const std::vector<Guard>& guards)
  {
    next_follow_check_ = 0;
    follow_check_interval_ = 1;
    guard_values_.resize(SAMPLES_PER_STEP + 1, static_cast<Eigen::Index>(guards.size()));
    samples_ = SAMPLES_PER_STEP;
    bool first_row_known = sampleStart(stepper, guards);  // later, a step's first sample is the previous step's last
    previous_row_known_ = false;
    while (true)
    {
      if (++step_count_ > options_.max_steps)
        return stepLimitError();
      if (auto status = checkClock(); !status)
        return status.error();
      const auto [t0, t1] = stepper.do_step(std::ref(springs_));
      samples_ = guardSamples(stepper, t0, t1);
      guard_values_.conservativeResize(samples_ + 1, Eigen::NoChange);
      sampleGuards(stepper, guards, t0, t1, first_row_known);
      const std::vector<FiredGuard>& fired = firedGuards(stepper, guards, t0, t1);
      if (fired.empty())
      {
        recordSamples(stepper, t0, t1);
        if (aSlipHasRelaxed(stepper, t1))
        {
          stepper.calc_state(t1, y_);
          t_ = physicalTime(stepper, t1);
          return true;
        }
        startNextStep(t0, t1);
        first_row_known = true;
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

  /// Points of the impulse curve in (t0, t1], evenly spaced within the step, for plots.
  template <class Stepper>
  void recordSamples(const Stepper& stepper, double t0, double t1)
  {
    if (!options_.record_samples)
      return;
    for (int k = 1; k <= samples_; ++k)
    {
      const double t = sampleTime(t0, t1, k);
      stepper.calc_state(t, buffer_);
      result_.samples.push_back(snapshot(buffer_.data(), physicalTime(stepper, t)));
    }
  }

  /// Guard values at the start of a numerically integrated state, from the state itself into the first row of
  /// guard_values_. Odeint's interpolant reproduces the state there only to round-off, and a guard that starts at
  /// zero — a contact with v_n = 0 about to separate — could come out at +1e-18 and its crossing be missed: the
  /// contact then stayed in compression while pulled apart (the cloth under a cushion nose below the ball's centre,
  /// from a random table sweep). Returns whether the row is known.
  template <class Stepper>
  bool sampleStart(const Stepper& /*stepper*/, const std::vector<Guard>& guards)
  {
    evaluateKinematics(dynamics_, y_.data(), kinematics_buffer_);
    storeGuardRow(0, guards);
    return true;
  }

  /// The closed form is exact at its start, and its samples take their forces from its modes throughout.
  bool sampleStart(const LinearPhaseStepper& /*stepper*/, const std::vector<Guard>& /*guards*/) { return false; }

  /// The state at t of the current step into buffer_, with its kinematics into kinematics_buffer_.
  template <class Stepper>
  void evaluateAt(const Stepper& stepper, double t) const
  {
    stepper.calc_state(t, buffer_);
    evaluateKinematics(dynamics_, buffer_.data(), kinematics_buffer_);
  }

  void evaluateAt(const LinearPhaseStepper& stepper, double t) const
  {
    stepper.calc_kinematics(t, buffer_, kinematics_buffer_);
  }

  template <class Stepper>
  double guardAt(const Stepper& stepper, std::size_t g, double t) const
  {
    evaluateAt(stepper, t);
    return resolvedGuard(guards_[g], kinematics_buffer_);
  }

  /// A guard's value as the current state's method resolves it: an end of compression is due once the contact
  /// separates faster than separation_floor_, not at the first positive noise of its normal velocity.
  double resolvedGuard(const Guard& guard, const Kinematics& kinematics) const
  {
    const double value = guardValue(guard, kinematics, contacts_, dynamics_, space_);
    return guard.type == ContactEventType::EndOfCompression ? value - separation_floor_ : value;
  }

  /// Values of every guard at evenly spaced instants of the step into guard_values_ (one state evaluation per
  /// instant; the first one skipped when known).
  template <class Stepper>
  void sampleGuards(const Stepper& stepper, const std::vector<Guard>& guards, double t0, double t1,
                    bool first_row_known) const
  {
    for (int k = first_row_known ? 1 : 0; k <= samples_; ++k)
    {
      evaluateAt(stepper, sampleTime(t0, t1, k));
      storeGuardRow(k, guards);
    }
    // From the kinematics at t1; the closed form holds its slips fixed and never asks.
    if constexpr (!std::is_same_v<Stepper, LinearPhaseStepper>)
      slip_may_follow_ = anIntegratedSlipRelaxesFast(kinematics_buffer_);
  }

  /// Whether a sliding contact on its way to separation has a cone that shrinks fast against its slip: ρ̇ = μη²v_n
  /// above SEPARATION_RATE_FOLLOW of |v_t|. Its direction is then left to the separation clock, which follows it to
  /// the end in a few steps; handed to the quasi-steady lag, the bench's three cushion hits took 11 % more
  /// instructions.
  bool shrinksToSeparation(std::size_t i, const Kinematics& kinematics) const
  {
    const ContactState& contact = contacts_[i];
    if (!contact.slidingInRestitution())
      return false;
    const int row = space_.offset[i];
    return contact.coneRate(std::abs(kinematics.velocity(row))) >
           SEPARATION_RATE_FOLLOW * kinematics.velocity.segment<2>(row + 1).norm();
  }

  /// Whether contact i slides on an integrated direction whose relaxation time is below the quasi-steady limit.
  bool relaxesFast(std::size_t i, const Kinematics& kinematics) const
  {
    const ContactState& contact = contacts_[i];
    return contact.sliding() && !contact.quasi_steady &&
           dynamics_.relaxationRatio(i, kinematics.velocity, kinematics.force) < 1.0;
  }

  /// Whether some contact could be handed to the quasi-steady lag mid-state: its integrated slip relaxes fast and
  /// it is not on its way to separation with a fast-shrinking cone.
  bool anIntegratedSlipRelaxesFast(const Kinematics& kinematics) const
  {
    if (!options_.quasi_steady_slip)
      return false;
    for (std::size_t i = 0; i < contacts_.size(); ++i)
      if (relaxesFast(i, kinematics) && !shrinksToSeparation(i, kinematics))
        return true;
    return false;
  }

  /// Every guard's value at kinematics_buffer_ into row k of guard_values_.
  void storeGuardRow(int k, const std::vector<Guard>& guards) const
  {
    for (std::size_t g = 0; g < guards.size(); ++g)
      guard_values_(k, static_cast<Eigen::Index>(g)) = resolvedGuard(guards[g], kinematics_buffer_);
  }

  double sampleTime(double t0, double t1, int k) const { return k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_; }

  /// Guard samples for a step: SAMPLES_PER_STEP per half radian of the fastest mode in physical time. Only the
  /// separation clock's steps can be longer (their length in u is not bounded in t).
  template <class Stepper>
  int guardSamples(const Stepper& /*stepper*/, double /*t0*/, double /*t1*/) const
  {
    return SAMPLES_PER_STEP;
  }

  int guardSamples(const SeparationClockStepper& stepper, double u0, double u1) const
  {
    const double half_radians = 2.0 * omega_ * (stepper.timeAt(u1) - stepper.timeAt(u0));
    return SAMPLES_PER_STEP * static_cast<int>(std::clamp(std::ceil(half_radians), 1.0, MAX_STEP_SUBDIVISION));
  }

  /// The next step starts where this one ended: its first sample is this step's last, the one before that is kept
  /// as its neighbour (for firstRise).
  void startNextStep(double t0, double t1)
  {
    previous_time_ = sampleTime(t0, t1, samples_ - 1);
    previous_row_ = guard_values_.row(samples_ - 1);
    previous_row_known_ = true;
    guard_values_.row(0) = guard_values_.row(samples_);
  }

  /// The earliest guard to rise through zero in [t0, t1] (from the samples in guard_values_, refined where two may
  /// straddle a positive bump), with every other one within round-off of it.
  template <class Stepper>
  const std::vector<FiredGuard>& firedGuards(const Stepper& stepper, const std::vector<Guard>& guards, double t0,
                                             double t1)
  {
    crossings_.clear();
    for (std::size_t g = 0; g < guards.size(); ++g)
    {
      const auto column = static_cast<Eigen::Index>(g);
      samples_of_guard_.clear();
      for (int k = 0; k <= samples_; ++k)
        samples_of_guard_.push_back({sampleTime(t0, t1, k), guard_values_(k, column)});
      const GuardSample before{previous_time_, previous_row_known_ ? previous_row_(column) : 0.0};
      // Without a previous step this is the state's first, and its first sample the state's start.
      const bool starts_at_zero = !previous_row_known_ && std::abs(samples_of_guard_.front().g) <= START_ROUND_OFF;
      auto evaluate = [&](double t) { return guardAt(stepper, g, t); };
      if (const auto rise = firstRise(samples_of_guard_.data(), samples_of_guard_.size(),
                                      previous_row_known_ ? &before : nullptr, nullptr, evaluate, starts_at_zero))
        crossings_.push_back(
            {guards[g], locateRoot(stepper, g, rise->below.t, rise->above.t, rise->below.g, rise->above.g)});
    }
    return earliestCrossings(t1 - t0);
  }

  /// The instant just after the guard's zero (so that the transition has numerically happened).
  template <class Stepper>
  double locateRoot(const Stepper& stepper, std::size_t g, double a, double b, double ga, double gb) const
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
  SpringSystem springs_;     ///< the dynamics as the integrator's system
  ForceEvaluation scratch_;  ///< of the force evaluations that only a slip direction or a strain energy is read from
  LinearPhaseStepper closed_form_;  ///< rebuilt at every linear state (its storage kept)
  /// Numerical steppers, made at their first use and restarted at every state (their storage kept).
  std::optional<DenseStepper> plain_stepper_;
  std::optional<SeparationClockStepper> clock_stepper_;
  ChatterLimit chatter_{};
  OdeState y_;
  mutable OdeState buffer_;                 ///< scratch state for dense-output evaluations
  mutable Kinematics kinematics_buffer_{};  ///< of the guard samples
  Kinematics event_kinematics_{};           ///< at the current instant, for transitions
  mutable Eigen::VectorXd momentum_;        ///< scratch of kineticEnergy
  // Storage kept across the solve (a short impact is a few states; allocating per event cost a third of it).
  std::vector<Guard> guards_;
  PerGuard<std::optional<AffineGuard>> affine_guards_;  ///< of guards_
  AffineCrossingSearch affine_search_;
  std::vector<FiredGuard> crossings_, fired_;
  std::vector<int> switches_;
  std::vector<bool> settled_;
  mutable Eigen::MatrixXd guard_values_;  ///< guard samples of the current step: instants × guards
  Eigen::VectorXd previous_row_;          ///< the guards at the previous step's last sample but one, at previous_time_
  double previous_time_ = 0.0;
  bool previous_row_known_ = false;  ///< false in a state's first step
  boost::container::small_vector<GuardSample, SAMPLES_PER_STEP + 1> samples_of_guard_;  ///< scratch of firedGuards
  int samples_ = SAMPLES_PER_STEP;        ///< guard samples of the current step
  double omega_ = 1.0;                    ///< fastest angular frequency of the current state
  double separation_floor_ = 0.0;         ///< normal speed an end of compression must reach in the current state
  mutable bool slip_may_follow_ = false;  ///< at the end of the step sampled last (see anIntegratedSlipRelaxesFast)
  std::size_t next_follow_check_ = 0;     ///< first step at which aSlipHasRelaxed checks again
  std::size_t follow_check_interval_ = 1;
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
      return Error{ErrorCode::NumericalFailure, "", "numerical failure: the final velocities are not finite"};
    return result;
  }
  catch (const std::exception& e)
  {
    // Odeint signals a step size collapse, and Boost.Math a failed bracket, by exceptions.
    return Error{ErrorCode::NumericalFailure, "", std::string("numerical failure: ") + e.what()};
  }
}

}  // namespace billiard_shot_planner
