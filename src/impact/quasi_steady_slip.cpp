#include "quasi_steady_slip.hpp"

#include <algorithm>
#include <cmath>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// How closely an integrated slip direction must agree with the quasi-steady one for a sliding contact with a short
/// cone to follow its slip from then on (see QuasiSteadySlip::followShortSlips): the jump it makes is at most this.
constexpr double DIRECTION_AGREEMENT = 1e-6;

/// A slip on its way to separation is handed to the quasi-steady lag mid-state only while its cone shrinks slower
/// than this fraction of its slip speed (see QuasiSteadySlip::shrinksToSeparation).
constexpr double SEPARATION_RATE_FOLLOW = 0.01;
}  // namespace

QuasiSteadySlip::QuasiSteadySlip(const SolverOptions& options, const ContactSpace& space,
                                 std::vector<ContactState>& contacts, ContactDynamics& dynamics)
    : enabled_(options.quasi_steady_slip), space_(space), contacts_(contacts), dynamics_(dynamics)
{
}

/// The second-order lag leaves errors of order ε⁴ in the friction, so the limit is (tolerance/10)^¼, which keeps them
/// a tenth of the tolerance: 5.6e-4 at the default tolerance. At most 1e-2, where the expansion's terms no longer
/// shrink.
double QuasiSteadySlip::relaxationLimit(const SolverOptions& options)
{
  return std::min(std::pow(0.1 * options.relative_tolerance, 0.25), 1e-2);
}

void QuasiSteadySlip::release(std::size_t contact, OdeState& y)
{
  const Eigen::Vector2d direction = dynamics_.slipDirection(contact, y.data(), scratch_);
  contacts_[contact].tangential.quasi_steady = false;
  double* carrier = y.data() + space_.size + space_.offset[contact] + 1;
  carrier[0] = direction.x();
  carrier[1] = direction.y();
  dynamics_.refresh();
}

void QuasiSteadySlip::integrateEverySlipWhenOff(OdeState& y)
{
  if (enabled_)
    return;
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (contacts_[i].followsSlip())
      release(i, y);
}

void QuasiSteadySlip::releaseAll(OdeState& y)
{
  released_.clear();
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (contacts_[i].followsSlip())
      released_.push_back(i);
  for (std::size_t i : released_)
    release(i, y);
}

void QuasiSteadySlip::followReleasedAgain()
{
  if (released_.empty())
    return;
  for (std::size_t i : released_)
    contacts_[i].tangential.quasi_steady = true;
  dynamics_.refresh();
}

void QuasiSteadySlip::startIntegratedState(OdeState& y)
{
  releaseSlowRelaxations(y);
  followShortSlips(y);
}

/// A contact that follows its slip is released once its relaxation time reaches the quasi-steady limit, by a
/// guard that rises through it. One that starts a state beyond it is released at once: a rigid link reactivated
/// sliding (a plastic tip touching again) carries a finite force from its first instant, so its guard starts above
/// zero and never rises through it, and the lag would stay in use far beyond the limit.
void QuasiSteadySlip::releaseSlowRelaxations(OdeState& y)
{
  if (!std::any_of(contacts_.begin(), contacts_.end(), [](const ContactState& c) { return c.followsSlip(); }))
    return;
  evaluateKinematics(dynamics_, y.data(), kinematics_);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (contacts_[i].followsSlip() && dynamics_.relaxationRatio(i, kinematics_.velocity, kinematics_.force) >= 1.0)
      release(i, y);
}

/// A sliding contact whose direction relaxes faster than the quasi-steady limit (its spring on the friction cone
/// short against its slip) turns it at |v_t|/ρ, a stiff equation for explicit integration. In an integrated
/// state it follows its slip quasi-steadily instead, as a slip from relaxed springs does, when its direction
/// already agrees with the quasi-steady one to DIRECTION_AGREEMENT (it has relaxed onto it; one that has just slipped
/// from a loaded spring has not, and stays integrated). Integrated, a barely grazed cushion, its contacts loaded
/// lightly, would take hundreds of thousands of tiny steps.
void QuasiSteadySlip::followShortSlips(const OdeState& y)
{
  if (!enabled_)
    return;
  evaluateKinematics(dynamics_, y.data(), kinematics_);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (hasRelaxedOntoItsSlip(i, kinematics_, scratch_))
    {
      contacts_[i].tangential.quasi_steady = true;
      dynamics_.refresh();
    }
}

bool QuasiSteadySlip::hasRelaxedOntoItsSlip(std::size_t i, const Kinematics& at, ForceEvaluation& scratch) const
{
  if (!relaxesFast(i, at))
    return false;
  const Eigen::Vector2d integrated = dynamics_.carrierDirection(i, at.y);
  return (dynamics_.followedSlipDirection(i, at.y, scratch) - integrated).norm() <= DIRECTION_AGREEMENT;
}

bool QuasiSteadySlip::relaxesFast(std::size_t i, const Kinematics& at) const
{
  const ContactState& contact = contacts_[i];
  return contact.sliding() && !contact.tangential.quasi_steady &&
         dynamics_.relaxationRatio(i, at.velocity, at.force) < 1.0;
}

/// A sliding contact on its way to separation has a cone that shrinks fast against its slip where ρ̇ = μη²v_n is
/// above SEPARATION_RATE_FOLLOW of |v_t|. Its direction is then left to the separation clock, which follows it to
/// the end in a few steps, fewer than the quasi-steady lag's checks and switches would cost.
bool QuasiSteadySlip::shrinksToSeparation(std::size_t i, const Kinematics& at) const
{
  const ContactState& contact = contacts_[i];
  if (!contact.slidingInRestitution())
    return false;
  const int row = space_.offset[i];
  return contact.coneRate(std::abs(at.velocity(row)), at.y[space_.size + row]) >
         SEPARATION_RATE_FOLLOW * at.velocity.segment<2>(row + 1).norm();
}

bool QuasiSteadySlip::anIntegratedSlipRelaxesFast(const Kinematics& at) const
{
  if (!enabled_)
    return false;
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (relaxesFast(i, at) && !shrinksToSeparation(i, at))
      return true;
  return false;
}

void QuasiSteadySlip::restartChecks()
{
  next_check_ = 0;
  check_interval_ = 1;
}

/// A tip that slips from a loaded spring and turns into a rigid link has not relaxed when its state starts, but
/// does a few relaxation times later: integrated on, with a relaxation time of a millionth of the collision's (a
/// grazing hit on a nearly plastic cushion), it would take steps of that order to the state's end.
bool QuasiSteadySlip::anIntegratedSlipHasRelaxed(const Kinematics& at, std::size_t step)
{
  // The same slips as anIntegratedSlipRelaxesFast: one shrinking to separation stays on the clock even when another
  // contact relaxes fast.
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (!shrinksToSeparation(i, at) && hasRelaxedOntoItsSlip(i, at, scratch_))
      return true;
  // A slip that has not relaxed may take long to (on its way to separation its cone shrinks faster than its
  // direction turns, and it never does): the checks, three force evaluations each, back off geometrically so that
  // such a state does not pay for one at every step.
  check_interval_ *= 2;
  next_check_ = step + check_interval_;
  return false;
}

}  // namespace detail
}  // namespace billiard_shot_planner
