#include "contact_dynamics.hpp"

#include <algorithm>
#include <cmath>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Smallest spring length (dimensionless; a spring's peak length is of order one) used to turn a sliding contact's
/// direction. Where the spring is shorter — the first and last instants of a contact that slides from its start or
/// to its end — the direction would turn faster than the dynamics around it, a stiff equation that explicit
/// integration can only follow in tiny steps; there the friction force is of the same small order, so bounding
/// the rate leaves the result unchanged far below the solver's tolerance. It is joined smoothly (a hypotenuse, not a
/// maximum) so that the dynamics stays analytic up to and through a separation, where integrator steps end: a kink
/// there makes the step control reject step after step.
constexpr double SLIP_LENGTH_FLOOR = 1e-6;

/// Normal speed (dimensionless: the largest initial contact speed is 1) below which the separation clock no longer
/// follows v_n down to zero. Any smooth positive clock gives the same solution; this one only sets how much of a
/// restitution phase runs on the slowed clock, and the cost of a solve varies little with it between 0.3 and 1.
/// docs/engine.md, "Separation clock".
constexpr double CLOCK_SPEED_FLOOR = 0.5;
}  // namespace

ContactDynamics::ContactDynamics(const ContactSpace& space, const std::vector<ContactState>& contacts,
                                 double quasi_steady_relaxation)
    : space_(space), contacts_(contacts), quasi_steady_relaxation_(quasi_steady_relaxation)
{
  refresh();
}

void ContactDynamics::refresh()
{
  rigid_contacts_.clear();
  any_quasi_steady_ = false;
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    if (contacts_[i].phase == NormalPhase::RigidLink)
      rigid_contacts_.push_back(i);
    any_quasi_steady_ = any_quasi_steady_ || contacts_[i].followsSlip();
  }
  link_rows_.resize(static_cast<Eigen::Index>(rigid_contacts_.size()), space_.size);
  for (Eigen::Index r = 0; r < link_rows_.rows(); ++r)
    link_rows_.row(r) = space_.delassus.row(space_.offset[rigid_contacts_[r]]);
}

bool ContactDynamics::follows(std::size_t contact, std::size_t also_following) const
{
  return contacts_[contact].followsSlip() || contact == also_following;
}

Eigen::VectorXd ContactDynamics::relativeVelocity(const double* y) const
{
  Eigen::VectorXd velocity;
  relativeVelocity(y, velocity);
  return velocity;
}

void ContactDynamics::relativeVelocity(const double* y, Eigen::VectorXd& velocity) const
{
  // The integrator and the guard samples call this thousands of times per solve. On the sizes of one ball's
  // contacts Eigen's dynamic product spends more on set-up than on arithmetic; a fixed-size product is unrolled and
  // vectorised.
  velocity.resize(space_.size);
  switch (space_.size)
  {
    case 2:
      return addImpulseResponse<2>(y, velocity);
    case 3:
      return addImpulseResponse<3>(y, velocity);
    case 6:
      return addImpulseResponse<6>(y, velocity);
    default:
      velocity = space_.w0;
      if (space_.sparse())
        velocity.noalias() += space_.sparse_delassus * Eigen::Map<const Eigen::VectorXd>(y, space_.size);
      else
        velocity.noalias() += space_.delassus * Eigen::Map<const Eigen::VectorXd>(y, space_.size);
  }
}

template <int N>
void ContactDynamics::addImpulseResponse(const double* y, Eigen::VectorXd& velocity) const
{
  using Vector = Eigen::Matrix<double, N, 1>;
  Eigen::Map<Vector>(velocity.data()).noalias() =
      Eigen::Map<const Vector>(space_.w0.data()) +
      Eigen::Map<const Eigen::Matrix<double, N, N>>(space_.delassus.data()) * Eigen::Map<const Vector>(y);
}

void ContactDynamics::springForces(const double* y, const SlipDirections& directions, Eigen::VectorXd& force) const
{
  // Every row written once (the contacts' rows tile contact space): this runs at every right-hand side.
  const double* s = y + space_.size;
  force.resize(space_.size);
  double* f = force.data();
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    const ContactState& contact = contacts_[i];
    const int row = space_.offset[i];
    f[row] = contact.compliant() ? contact.normal.force(s[row]) : 0.0;
    if (space_.dim[i] != 3)
      continue;
    Eigen::Map<Eigen::Vector2d> tangential(f + row + 1);
    if (contact.active() && !contact.tangential.slipping)
      tangential = contact.tangential.force(s[row + 1], s[row + 2]);
    else if (contact.active() && contact.compliant())
      // Sliding: friction on the cone, −μ F_n ŝ. Equal to −κ s_t on the exact solution, but bounded by the cone
      // even where the spring shrinks to nothing at separation and its integrated length loses accuracy.
      tangential = -contact.tangential.friction * f[row] * directions[i];
    else
      tangential.setZero();  // inactive, or a sliding rigid link (its friction comes with its force, addLinkForces)
  }
}

Eigen::VectorXd ContactDynamics::forces(const double* y) const
{
  Eigen::VectorXd force;
  SlipDirections directions;
  LagScratch scratch;
  forces(y, force, directions, scratch);
  return force;
}

void ContactDynamics::carrierDirections(const double* y, SlipDirections& directions) const
{
  directions.resize(contacts_.size());
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (contacts_[i].sliding())
      directions[i] = carrierDirection(i, y);
}

void ContactDynamics::forces(const double* y, Eigen::VectorXd& force, SlipDirections& directions,
                             LagScratch& scratch) const
{
  if (any_quasi_steady_)
    relativeVelocity(y, scratch.velocity);
  forcesWithVelocity(y, scratch.velocity, force, directions, scratch);
}

void ContactDynamics::forcesWithVelocity(const double* y, const Eigen::VectorXd& w, Eigen::VectorXd& force,
                                         SlipDirections& directions, LagScratch& scratch) const
{
  carrierDirections(y, directions);
  if (any_quasi_steady_)
    followSlip(y, w, NO_CONTACT, force, directions, scratch);
  forcesAlongDirections(y, directions, force);
}

void ContactDynamics::evaluate(const double* y, ForceEvaluation& at) const
{
  relativeVelocity(y, at.velocity);
  forcesWithVelocity(y, at.velocity, at.force, at.directions, at.lag);
}

void ContactDynamics::activeRelativeVelocity(const double* y, Eigen::VectorXd& velocity) const
{
  if (!space_.sparse())
    return relativeVelocity(y, velocity);
  // Row by row, as the sparse product does it (the same sums in the same order), on the active contacts alone.
  if (velocity.size() != space_.size)
    velocity.setZero(space_.size);
  const Eigen::Map<const Eigen::VectorXd> impulses(y, space_.size);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    if (!contacts_[i].active())
      continue;
    for (int row = space_.offset[i]; row < space_.offset[i] + space_.dim[i]; ++row)
      velocity(row) = space_.w0(row) + space_.sparse_delassus.row(row).dot(impulses);
  }
}

void ContactDynamics::forcesAlongDirections(const double* y, const SlipDirections& directions,
                                            Eigen::VectorXd& force) const
{
  springForces(y, directions, force);
  if (!rigid_contacts_.empty())
    addLinkForces(directions, force);
}

void ContactDynamics::followSlip(const double* y, const Eigen::VectorXd& w, std::size_t also_following,
                                 Eigen::VectorXd& force, SlipDirections& directions, LagScratch& scratch) const
{
  // The lag that keeps ρθ̇ = |v_t| sin(ψ − θ), θ the slip direction's angle and ψ the slip velocity's, on the slow
  // manifold: sin δ = ε(ψ̇ − δ̇) with δ = ψ − θ and ε = ρ/|v_t|, expanded in ε. First order (δ̇ = 0) leaves errors
  // of order ε³ in the friction, second order of order ε⁴ (docs/engine.md, "Quasi-steady slip").
  firstOrderLags(y, w, also_following, force, directions, scratch.lags);
  addLagRates(y, w, force, also_following, scratch);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    // Only a sliding contact has tangential rows: a frictionless one last in contact space has none to read.
    if (!follows(i, also_following))
      continue;
    const Eigen::Vector2d v_t = w.segment<2>(space_.offset[i] + 1);
    const double speed = v_t.norm();
    if (speed == 0.0)
      continue;  // its direction stays its carrier's
    const double sin_lag = std::sin(scratch.lags[i].angle), cos_lag = std::cos(scratch.lags[i].angle);
    const Eigen::Vector2d along = v_t / speed;
    directions[i] =
        Eigen::Vector2d(cos_lag * along.x() + sin_lag * along.y(), cos_lag * along.y() - sin_lag * along.x());
  }
  forcesAlongDirections(y, directions, force);
}

void ContactDynamics::firstOrderLags(const double* y, const Eigen::VectorXd& w, std::size_t also_following,
                                     Eigen::VectorXd& force, SlipDirections& directions,
                                     std::vector<SlipLag>& lags) const
{
  // Zeroth order: along the slip. Then the lag under the forces of that guess.
  lags.assign(contacts_.size(), SlipLag{});
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    if (!follows(i, also_following))
      continue;
    const Eigen::Vector2d v_t = w.segment<2>(space_.offset[i] + 1);
    if (v_t.norm() > 0.0)
      directions[i] = v_t.normalized();
  }
  forcesAlongDirections(y, directions, force);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    if (!follows(i, also_following))
      continue;
    const int row = space_.offset[i];
    const Eigen::Vector2d v_t = w.segment<2>(row + 1);
    const double speed = v_t.norm();
    if (speed == 0.0)
      continue;
    const Eigen::Vector2d a_t = tangentialResponse(row, force);
    const double turn_rate = (v_t.x() * a_t.y() - v_t.y() * a_t.x()) / (speed * speed);
    // The true spring length, not the floored one of the integrated slip (coneLength): here it only sets the lag,
    // no stiffness to bound. The floor can be orders of magnitude above a lightly loaded cone (a rolling ball's cloth
    // contact under a cushion hit), and a slowly turning slip would then lag by up to 90° and stick and slip again
    // without end.
    lags[i].relaxation = contacts_[i].tangential.coneLength(force(row)) / speed;
    lags[i].angle = std::asin(std::clamp(lags[i].relaxation * turn_rate, -1.0, 1.0));
  }
}

void ContactDynamics::addLagRates(const double* y, const Eigen::VectorXd& w, const Eigen::VectorXd& force,
                                  std::size_t also_following, LagScratch& scratch) const
{
  // δ̇ of the first-order lag along the motion, by a forward difference over a hundredth of the relaxation time:
  // short against the time on which the lag changes (its truncation error is then 1e-2 of the correction's own
  // second-order term), long enough that the lags' round-off leaves 1e-14 of the lag in the correction εδ̇.
  constexpr double DIFFERENCE_STEP = 1e-2;
  double step = 0.0;
  for (const SlipLag& lag : scratch.lags)
    step += DIFFERENCE_STEP * lag.relaxation;  // a sum, not a maximum: smooth in the state
  if (!(step > 0.0))
    return;
  // The state moved by step × its rate: İ = F, and the spring rates (written in place of the springs first).
  const Eigen::Index n = space_.size;
  OdeState& shifted = scratch.shifted_state;
  shifted.assign(y, y + 2 * n);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    const double cone_length = contacts_[i].sliding() ? coneLength(i, force) : 0.0;
    springRates(i, y, w, cone_length, also_following, shifted.data() + n + space_.offset[i]);
  }
  for (Eigen::Index k = 0; k < n; ++k)
  {
    shifted[k] += step * force(k);
    shifted[n + k] = y[n + k] + step * shifted[n + k];
  }
  // The velocities are affine in the impulses: at the shifted state they are w + step·W F. The lags read them only
  // on the tangent rows of the followed contacts.
  scratch.shifted_velocity = w;
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (follows(i, also_following))
    {
      const int row = space_.offset[i];
      scratch.shifted_velocity.segment<2>(row + 1) += step * tangentialResponse(row, force);
    }
  carrierDirections(shifted.data(), scratch.shifted_directions);
  firstOrderLags(shifted.data(), scratch.shifted_velocity, also_following, scratch.shifted_force,
                 scratch.shifted_directions, scratch.shifted_lags);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    SlipLag& lag = scratch.lags[i];
    if (lag.relaxation == 0.0)
      continue;
    const double lag_rate = (scratch.shifted_lags[i].angle - lag.angle) / step;
    lag.angle = std::asin(std::clamp(std::sin(lag.angle) - lag.relaxation * lag_rate, -1.0, 1.0));
  }
}

Eigen::Vector2d ContactDynamics::tangentialResponse(int row, const Eigen::VectorXd& force) const
{
  if (space_.sparse())
    return {space_.sparse_delassus.row(row + 1).dot(force), space_.sparse_delassus.row(row + 2).dot(force)};
  return {space_.delassus.row(row + 1).dot(force), space_.delassus.row(row + 2).dot(force)};
}

double ContactDynamics::relaxationRatio(std::size_t contact, const Eigen::VectorXd& w,
                                        const Eigen::VectorXd& force) const
{
  const int row = space_.offset[contact];
  const double speed = std::hypot(w(row + 1), w(row + 2), VELOCITY_TOLERANCE);
  return contacts_[contact].tangential.coneLength(force(row)) / (quasi_steady_relaxation_ * speed);
}

double ContactDynamics::linkCoupling(std::size_t link, std::size_t by, const SlipDirections& directions) const
{
  // The column B_by of F = F_s + B f: 1 on the link's normal row and, while it slides, −μŝ on its tangent rows.
  const std::size_t i = rigid_contacts_[by];
  const int row = space_.offset[i];
  const auto w = link_rows_.row(static_cast<Eigen::Index>(link));
  double coupling = w(row);
  if (contacts_[i].tangential.slipping)
    coupling -= contacts_[i].tangential.friction * (w(row + 1) * directions[i].x() + w(row + 2) * directions[i].y());
  return coupling;
}

Eigen::VectorXd ContactDynamics::solveLinks(const SlipDirections& directions, const Eigen::VectorXd& rates) const
{
  // Rigid links: unknown normal forces f keep their normal velocities constant (zero), (W F)_L = 0, so
  // (W_L B) f = −W_L F_s; a sliding link's friction −μfŝ depends on its own unknown, hence B.
  const auto links = static_cast<Eigen::Index>(rigid_contacts_.size());
  const Eigen::VectorXd right = -(link_rows_ * rates);
  if (links == 1)
  {
    // The common case, a single link, without a decomposition (what it would give: the least-norm 0 if singular).
    const double system = linkCoupling(0, 0, directions);
    return Eigen::VectorXd::Constant(1, system == 0.0 ? 0.0 : right(0) / system);
  }
  Eigen::MatrixXd system(links, links);
  for (Eigen::Index r = 0; r < links; ++r)
    for (Eigen::Index c = 0; c < links; ++c)
      system(r, c) = linkCoupling(static_cast<std::size_t>(r), static_cast<std::size_t>(c), directions);
  // Redundant links (a singular system) get the least-norm forces.
  return system.completeOrthogonalDecomposition().solve(right);
}

void ContactDynamics::addLinkForces(const SlipDirections& directions, Eigen::VectorXd& force) const
{
  const Eigen::VectorXd link_forces = solveLinks(directions, force);
  for (Eigen::Index r = 0; r < link_forces.size(); ++r)
  {
    const std::size_t i = rigid_contacts_[r];
    const int row = space_.offset[i];
    force(row) += link_forces(r);
    if (contacts_[i].tangential.slipping)
      force.segment<2>(row + 1) -= contacts_[i].tangential.friction * link_forces(r) * directions[i];
  }
}

Eigen::Vector2d ContactDynamics::directionRate(std::size_t contact, const Eigen::Vector2d& direction,
                                               const Eigen::VectorXd& w, const Eigen::VectorXd& force) const
{
  // The slip direction turns toward the tangential velocity at |(I − ŝŝᵀ)v_t| / ρ, with ρ = μF_n/κ the cone's
  // spring length, bounded below where the spring vanishes at separation (there the friction vanishes too).
  return acrossSlip(contact, direction, w) / coneLength(contact, force);
}

Eigen::Vector2d ContactDynamics::acrossSlip(std::size_t contact, const Eigen::Vector2d& direction,
                                            const Eigen::VectorXd& w) const
{
  const Eigen::Vector2d v_t = w.segment<2>(space_.offset[contact] + 1);
  return v_t - direction * direction.dot(v_t);
}

double ContactDynamics::linkForceRate(std::size_t contact, const double* y, const ForceEvaluation& at) const
{
  const Eigen::VectorXd& w = at.velocity;
  const Eigen::VectorXd& force = at.force;
  const SlipDirections& directions = at.directions;
  // Differentiating (W F)_L = 0 with F = F_s + B f: (W_L B) ḟ = −W_L (Ḟ_s + Ḃ f). The springs move with the contact
  // velocities (ṡ_n = v_n, a sticking ṡ_t = v_t), a compliant sliding contact's friction −μF_nŝ and a sliding
  // link's column −μŝ with their directions.
  Eigen::VectorXd rate = Eigen::VectorXd::Zero(space_.size);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    const ContactState& state = contacts_[i];
    const int row = space_.offset[i];
    if (!state.active())
      continue;
    if (state.compliant())
      rate(row) = state.normal.forceRate(y[space_.size + row], w(row));
    if (space_.dim[i] != 3)
      continue;
    if (!state.tangential.slipping)
      rate.segment<2>(row + 1) = state.tangential.forceRate(w.segment<2>(row + 1));
    else if (state.compliant())
      rate.segment<2>(row + 1) = -state.tangential.friction *
                                 (rate(row) * directions[i] + force(row) * directionRate(i, directions[i], w, force));
    else
      rate.segment<2>(row + 1) = -state.tangential.friction * force(row) * directionRate(i, directions[i], w, force);
  }
  const Eigen::VectorXd rates = solveLinks(directions, rate);
  for (Eigen::Index r = 0; r < rates.size(); ++r)
    if (rigid_contacts_[r] == contact)
      return rates(r);
  return 0.0;
}

double ContactDynamics::strainEnergy(std::size_t contact, const double* y, ForceEvaluation& scratch) const
{
  const ContactState& state = contacts_[contact];
  const double* s = y + space_.size + space_.offset[contact];
  const double normal = state.compliant() ? state.normal.energy(s[0]) : 0.0;
  if (space_.dim[contact] != 3 || !state.active())
    return normal;
  if (!state.tangential.slipping)
    return normal + state.tangential.energy(s[1], s[2]);
  // On the cone (the spring state only carries the direction): E_t = ½κρ², ρ = μF_n/κ, with F_n the spring's force
  // (then E_t = μ²η²E_n) or a rigid link's constraint force, read from the forces.
  double normal_force = state.normal.force(s[0]);
  if (!state.compliant())
  {
    forces(y, scratch.force, scratch.directions, scratch.lag);
    normal_force = scratch.force(space_.offset[contact]);
  }
  // A link that pulls is released at the instant it is made, and has no cone meanwhile (squared, its force would
  // read as strain energy that no spring holds).
  const double cone = state.tangential.coneLength(std::max(normal_force, 0.0));
  return normal + state.tangential.coneEnergy(cone);
}

Eigen::Vector2d ContactDynamics::slipDirection(std::size_t contact, const double* y, ForceEvaluation& scratch) const
{
  if (!contacts_[contact].followsSlip())
    return carrierDirection(contact, y);
  forces(y, scratch.force, scratch.directions, scratch.lag);
  return scratch.directions[contact];
}

Eigen::Vector2d ContactDynamics::followedSlipDirection(std::size_t contact, const double* y,
                                                       ForceEvaluation& scratch) const
{
  // forces() with the contact following too.
  relativeVelocity(y, scratch.lag.velocity);
  carrierDirections(y, scratch.directions);
  followSlip(y, scratch.lag.velocity, contact, scratch.force, scratch.directions, scratch.lag);
  return scratch.directions[contact];
}

Eigen::Vector2d ContactDynamics::carrierDirection(std::size_t contact, const double* y) const
{
  const double* s = y + space_.size + space_.offset[contact];
  const Eigen::Vector2d tangential(s[1], s[2]);
  const double length = tangential.norm();
  // Below this the direction is round-off; the slip direction chosen at the transition is the right one.
  const double relaxed = 1e-14 * (1.0 + std::abs(s[0]));
  return length > relaxed ? Eigen::Vector2d(tangential / length) : contacts_[contact].tangential.slip_direction;
}

double ContactDynamics::slidingSpeed(std::size_t contact, const double* y, const ForceEvaluation& at) const
{
  const ContactState& state = contacts_[contact];
  const int row = space_.offset[contact];
  const double along = at.directions[contact].dot(at.velocity.segment<2>(row + 1));
  if (state.phase != NormalPhase::RigidLink)
    return along + state.coneRate(at.velocity(row), y[space_.size + row]);
  // A rigid link has v_n = 0, but its spring on the friction cone, ρ = μf/κ, still grows and shrinks with its
  // force: σ = ŝ·v_t − ρ̇, the limit of the compliant contact's μη²v_n = −μḞ_n/κ. Without ρ̇ the link would slide
  // on while the cone outgrows the slip, and stick again with spring energy that nothing paid for.
  return along - state.tangential.friction * linkForceRate(contact, y, at) / state.tangential.kappa;
}

void ContactDynamics::springRates(std::size_t contact, const double* y, const Eigen::VectorXd& w, double cone_length,
                                  std::size_t also_following, double* rates) const
{
  const ContactState& state = contacts_[contact];
  const int row = space_.offset[contact];
  const bool tangential = space_.dim[contact] == 3;
  rates[0] = state.compliant() ? w(row) : 0.0;
  if (!tangential)
    return;
  rates[1] = rates[2] = 0.0;
  if (!state.active())
    return;
  // docs/impact_model.md, "Coulomb friction and tangential compliance".
  if (!state.tangential.slipping)
  {
    rates[1] = w(row + 1);  // stick: the contact particle is at rest on B
    rates[2] = w(row + 2);
    return;
  }
  if (follows(contact, also_following))
    return;  // the direction follows the slip (followSlip); the carrier waits for the release
  // Slip: ṡ_t = v_t − σŝ, whose radial part only keeps |s_t| = μη²|s_n| on the cone. The friction is −μF_nŝ, so
  // only the direction ŝ matters: the state carries it at a fixed length (never through zero, where it would flip)
  // and turns it at the physical rate, directionRate's, scaled by the carrier's length.
  const double* s = y + space_.size + row;
  const Eigen::Vector2d carrier(s[1], s[2]);
  const double length = carrier.norm();
  if (length == 0.0)
    return;
  Eigen::Map<Eigen::Vector2d>(rates + 1) = (length / cone_length) * acrossSlip(contact, carrier / length, w);
}

double ContactDynamics::coneLength(std::size_t contact, const Eigen::VectorXd& force) const
{
  const double rho = contacts_[contact].tangential.coneLength(force(space_.offset[contact]));
  return std::sqrt(rho * rho + SLIP_LENGTH_FLOOR * SLIP_LENGTH_FLOOR);  // ρ is of order one: no overflow to guard
}

double ContactDynamics::rates(const double* y, double* dydt, ForceEvaluation& at) const
{
  // The rates read the velocities of active contacts only (an inactive one's spring rests): in a large impact most
  // contacts are inactive at any instant.
  activeRelativeVelocity(y, at.velocity);
  forcesWithVelocity(y, at.velocity, at.force, at.directions, at.lag);
  std::copy_n(at.force.data(), space_.size, dydt);
  double shrink_rate = 0.0;
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    const ContactState& contact = contacts_[i];
    const double cone_length = contact.sliding() ? coneLength(i, at.force) : 0.0;
    springRates(i, y, at.velocity, cone_length, NO_CONTACT, dydt + space_.size + space_.offset[i]);
    if (contact.slidingInRestitution())
    {
      // ρ = μη²|s_n| shrinks at μη² v_n while the contact separates. v_n is smoothed where it reaches zero (a restart
      // of compression) so that the clock stays smooth across that event too.
      const double v_n = at.velocity(space_.offset[i]);
      const double separation_speed = std::sqrt(v_n * v_n + CLOCK_SPEED_FLOOR * CLOCK_SPEED_FLOOR);
      shrink_rate += contact.coneRate(separation_speed, y[space_.size + space_.offset[i]]) / cone_length;
    }
  }
  return shrink_rate;
}

}  // namespace detail
}  // namespace billiard_shot_planner
