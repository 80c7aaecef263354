#include "state_transitions.hpp"

#include <cmath>
#include <limits>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Dimensionless threshold below which a force is round-off (the normalised state is of order one); velocities:
/// VELOCITY_TOLERANCE (contact_space.hpp).
constexpr double FORCE_TOLERANCE = 1e-12;
/// A touching contact without force is let go only while it approaches slower than this, half the approach at
/// which an inactive contact reactivates (VELOCITY_TOLERANCE). With one threshold for both, a contact reactivated
/// at its guard's root, approaching at exactly the threshold (a grazing cushion hit), would be let go at once and
/// reactivated again at the same instant, for ever.
constexpr double RELEASE_VELOCITY = 0.5 * VELOCITY_TOLERANCE;

double* springs(double* y, const ContactSpace& space, std::size_t contact)
{
  return y + space.size + space.offset[contact];
}

void relaxSprings(double* y, const ContactSpace& space, std::size_t contact)
{
  double* s = springs(y, space, contact);
  for (int k = 0; k < space.dim[contact]; ++k)
    s[k] = 0.0;
}

/// Initial tangential mode of a contact whose springs are relaxed (docs/impact_model.md, Coulomb friction and
/// tangential compliance: modes from relaxed springs).
void chooseInitialMode(ContactState& contact, const Eigen::VectorXd& velocity, const ContactSpace& space,
                       std::size_t index)
{
  contact.tangential.slipping = false;
  if (space.dim[index] != 3)
    return;
  const int row = space.offset[index];
  const Eigen::Vector2d v_t(velocity(row + 1), velocity(row + 2));
  const double v_n = velocity(row);
  if (v_t.norm() > contact.coneRate(std::abs(v_n), /*deformation: relaxed=*/0.0) + VELOCITY_TOLERANCE)
  {
    contact.tangential.slipping = true;
    contact.tangential.slip_direction = v_t.normalized();
  }
}

/// Puts a contact into slip along `direction`. Its tangential spring state becomes the unit carrier of the slip
/// direction (see ContactDynamics::springRates). A slip from relaxed springs starts by following the slip
/// (TangentialSpring::quasi_steady); one from a loaded spring (stick to slip) is integrated from the start.
void startSlip(ContactState& contact, const Eigen::Vector2d& direction, double* y, const ContactSpace& space,
               std::size_t index, bool from_relaxed_springs)
{
  contact.tangential.slipping = true;
  contact.tangential.quasi_steady = from_relaxed_springs;
  contact.tangential.slip_direction = direction;
  double* s = springs(y, space, index);
  s[1] = direction.x();
  s[2] = direction.y();
}

/// Round-offs of a contact's velocity (velocityRoundOff) beyond which its approach is one: twice for the impulses
/// that may grow while it is apart, twice again for a guard read on either side of its noise.
constexpr double REACTIVATION_ROUND_OFFS = 4.0;

/// The contact stops touching: inactive, its springs relaxed, and reactivated only by an approach beyond the
/// round-off of its velocity. With large impulses (a heavy cue jammed on the ball) that round-off is far above
/// VELOCITY_TOLERANCE; read against VELOCITY_TOLERANCE alone, the noise of a released cue tip's velocity would
/// reactivate it, its link pull and be released, and so on until the event bound.
void stopTouching(std::size_t index, double* y, ContactState& contact, const ContactSpace& space)
{
  contact.phase = NormalPhase::Inactive;
  contact.tangential.slipping = false;
  contact.jammed = false;
  relaxSprings(y, space, index);
  contact.reactivation_speed =
      std::max(VELOCITY_TOLERANCE, REACTIVATION_ROUND_OFFS * velocityRoundOff(space, y, space.offset[index]));
}

/// Changes a rigid contact's normal velocity by `change` with an impulse along the rigid normals alone: the other links
/// keep their normal velocities and every compliant force is finite (so gives no impulse).
void rigidImpulse(std::size_t index, double change, double* y, const std::vector<ContactState>& contacts,
                  const ContactSpace& space)
{
  std::vector<int> rows{space.offset[index]};
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if (i != index && contacts[i].phase == NormalPhase::RigidLink)
      rows.push_back(space.offset[i]);
  const auto n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd block(n, n);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < n; ++b)
      block(a, b) = space.delassus(rows[a], rows[b]);
  Eigen::VectorXd target = Eigen::VectorXd::Zero(n);
  target(0) = change;
  const Eigen::VectorXd impulse = block.completeOrthogonalDecomposition().solve(target);
  for (Eigen::Index a = 0; a < n; ++a)
    y[rows[a]] += impulse(a);
}

/// Makes a contact a rigid link at zero normal velocity. A link keeps its normal velocity for as long as it holds,
/// and its force does work at that velocity: made where an end of compression located a little late leaves it
/// separating (a light ball on a plastic table under a heavy one), the link would push the heavy ball out with more
/// energy than it came in with. The limit of infinite stiffness has v_n = 0 (paper Theorem 12;
/// an end of compression is where v_n crosses zero), so what is left, the event's location error, is removed by a
/// plastic impulse of the contact: −½ v_n²/W_eff of kinetic energy, never a gain.
void makeRigidLink(std::size_t index, const Kinematics& kinematics, double* y, std::vector<ContactState>& contacts,
                   const ContactSpace& space)
{
  const double normal_velocity = kinematics.velocity(space.offset[index]);
  if (normal_velocity != 0.0)
    rigidImpulse(index, -normal_velocity, y, contacts, space);
  contacts[index].phase = NormalPhase::RigidLink;
}

/// The energy-equivalent approach speed of a compression that ends with normal deformation s_n (m/s): the speed
/// at which the contact, alone, would have stored the energy E_n it holds, v* = V √(2 E_n W̃_nn), for a linear spring
/// V |s_n| √(k W̃_nn). For one contact that is its approach speed exactly; in a multiple impact, the part of the
/// impact's energy that this contact's spring took (docs/impact_model.md, "Restitution that depends on the impact").
double compressionSpeed(std::size_t index, double deformation, const ContactState& contact, const ContactSpace& space)
{
  const int row = space.offset[index];
  if (!contact.normal.linear)
    return space.velocity_scale * std::sqrt(2.0 * contact.normal.energy(deformation) * space.delassus(row, row));
  return space.velocity_scale * std::abs(deformation) * std::sqrt(contact.normal.stiffness * space.delassus(row, row));
}

bool isChattering(const ContactState& contact, double deformation, const ChatterLimit& chatter)
{
  if (contact.normal.restitution == 0.0)
    return true;
  const double stored_energy = contact.normal.energy(deformation);
  const bool repeated = contact.ends_of_compression >= 3;
  const bool negligible = repeated && stored_energy <= chatter.energy;
  const bool unresolved = repeated && std::abs(deformation) <= chatter.deformation;
  // The bound is on the stiffness the restitution would have, k/e²: a phase that stiff is the rigid limit already,
  // and no method resolves it. Checked against the stiffness before it grows, a nearly plastic contact would
  // restitute at 1e21 k̄ or more after an end of compression and, reactivated at once, press with a deformation
  // whose end no method finds, stepping at its period to the step bound; a restitution that stiff can also make the
  // energy rise.
  const double restitution_stiffness = contact.normal.restitutionStiffness();
  return negligible || unresolved ||
         restitution_stiffness / contact.normal.original_stiffness >= chatter.stiffness_growth;
}

TransitionEvents endCompression(std::size_t index, const Kinematics& kinematics, double* y,
                                std::vector<ContactState>& contacts, const ContactSpace& space,
                                const ChatterLimit& chatter)
{
  ContactState& contact = contacts[index];
  double* s = springs(y, space, index);
  if (s[0] >= 0.0)
  {
    // Touched without ever loading: the bodies simply move apart.
    stopTouching(index, y, contact, space);
    return {ContactEventType::Separation};
  }
  ++contact.ends_of_compression;
  contact.normal.restituteAt(compressionSpeed(index, s[0], contact, space));
  if (isChattering(contact, s[0], chatter))
  {
    // Limit of infinite stiffness: the remaining normal strain energy (negligible, or lost when e = 0) is dropped.
    contact.rigid = true;
    contact.chattered = contact.normal.restitution > 0.0;
    s[0] = 0.0;
    makeRigidLink(index, kinematics, y, contacts, space);
    return {ContactEventType::EndOfCompression, ContactEventType::RigidLink};
  }
  // Paper §3.3 (i): E ← e²E at a continuous force (for the linear spring k ← k/e², s_n ← e² s_n).
  s[0] = contact.normal.endCompression(s[0]);
  contact.phase = NormalPhase::Restitution;
  return {ContactEventType::EndOfCompression};
}

TransitionEvents activate(std::size_t index, const Kinematics& kinematics, double* y,
                          std::vector<ContactState>& contacts, const ContactSpace& space)
{
  ContactState& contact = contacts[index];
  relaxSprings(y, space, index);
  const double approach = kinematics.velocity(space.offset[index]);
  if (contact.rigid)
    contact.normal.restituteAt(std::abs(approach) * space.velocity_scale);
  if (contact.rigid && -contact.normal.restitution * approach > contact.reactivation_speed)
  {
    // A contact of infinite stiffness (a former chattering one) approached at a finite speed: an instantaneous
    // impact of that contact alone, v_n ← −e v_n, and it separates at once.
    rigidImpulse(index, -(1.0 + contact.normal.restitution) * approach, y, contacts, space);
    stopTouching(index, y, contact, space);
    return {ContactEventType::Reactivation, ContactEventType::Separation};
  }
  // A plastic impact, a graze within round-off, or a rebound no faster than an approach the contact can resolve:
  // pressed together, such a contact is approached again at once, and again, a sequence whose limit is the link
  // (paper Theorem 12).
  if (contact.rigid)
  {
    // Its force is the constraint's from the first instant, while its tangential spring is relaxed: it sticks until
    // the spring reaches the cone, μf/κ. Sliding at once, it would stand on a cone of that length, whose energy
    // ½(μf)²/κ nothing had paid for.
    makeRigidLink(index, kinematics, y, contacts, space);
    contact.tangential.slipping = false;
    return {ContactEventType::Reactivation};
  }
  contact.phase = NormalPhase::Compression;
  chooseInitialMode(contact, kinematics.velocity, space, index);
  if (contact.tangential.slipping)
    startSlip(contact, contact.tangential.slip_direction, y, space, index, /*from_relaxed_springs=*/true);
  return {ContactEventType::Reactivation};
}

double quantityAt(const AffineGuard& guard, const Kinematics& kinematics, const ContactSpace& space)
{
  switch (guard.quantity)
  {
    case AffineGuard::Quantity::Velocity:
      return kinematics.velocity(guard.row);
    case AffineGuard::Quantity::Spring:
      return kinematics.y[space.size + guard.row];
    case AffineGuard::Quantity::Force:
      return kinematics.force(guard.row);
  }
  return 0.0;
}
}  // namespace

double velocityRoundOff(const ContactSpace& space, const double* impulses, int row)
{
  // The worst case of a sum of 16 terms, against the sum of their magnitudes.
  constexpr double SUM_ROUND_OFF = 16.0 * std::numeric_limits<double>::epsilon();
  double magnitude = std::abs(space.w0(row));
  for (Eigen::Index k = 0; k < space.size; ++k)
    magnitude += std::abs(space.delassus(row, k) * impulses[k]);
  return SUM_ROUND_OFF * magnitude;
}

void evaluateKinematics(const ContactDynamics& dynamics, const double* y, Kinematics& kinematics)
{
  kinematics.y = y;
  dynamics.evaluate(y, kinematics);
}

const std::vector<Guard>& armedGuards(const std::vector<ContactState>& contacts, const ContactSpace& space,
                                      std::vector<Guard>& guards)
{
  guards.clear();
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    switch (contacts[i].phase)
    {
      case NormalPhase::Inactive:
        guards.push_back({i, ContactEventType::Reactivation});
        continue;
      case NormalPhase::Compression:
        guards.push_back({i, ContactEventType::EndOfCompression});
        break;
      case NormalPhase::Restitution:
        guards.push_back({i, ContactEventType::RestartOfCompression});
        guards.push_back({i, ContactEventType::Separation});
        break;
      case NormalPhase::RigidLink:
        guards.push_back({i, ContactEventType::LinkRelease});
        break;
    }
    if (space.dim[i] == 3 && (contacts[i].tangential.slipping || !contacts[i].jammed))
      guards.push_back(
          {i, contacts[i].tangential.slipping ? ContactEventType::SlipToStick : ContactEventType::StickToSlip});
    if (contacts[i].followsSlip())
      guards.push_back({i, ContactEventType::StickToSlip, /*releases_direction=*/true});
  }
  return guards;
}

std::optional<AffineGuard> affineForm(const Guard& guard, const std::vector<ContactState>& contacts,
                                      const ContactSpace& space)
{
  using Quantity = AffineGuard::Quantity;
  const int row = space.offset[guard.contact];
  if (guard.releases_direction)
    return std::nullopt;
  switch (guard.type)
  {
    case ContactEventType::EndOfCompression:
      return AffineGuard{Quantity::Velocity, row, 1.0, 0.0};
    case ContactEventType::RestartOfCompression:
      return AffineGuard{Quantity::Velocity, row, -1.0, 0.0};
    case ContactEventType::Reactivation:
      // Approaching by more than round-off: a released rigid link left touching at v_n = 0 with a force of round-off
      // would otherwise cross zero again at the same instant, and link and release for ever (a chain's far balls).
      return AffineGuard{Quantity::Velocity, row, -1.0, -contacts[guard.contact].reactivation_speed};
    case ContactEventType::Separation:
      return AffineGuard{Quantity::Spring, row, 1.0, 0.0};
    case ContactEventType::LinkRelease:
      return AffineGuard{Quantity::Force, row, -1.0, 0.0};
    case ContactEventType::StickToSlip:
    case ContactEventType::SlipToStick:
    case ContactEventType::RigidLink:
      break;
  }
  return std::nullopt;
}

double guardValue(const Guard& guard, const Kinematics& kinematics, const std::vector<ContactState>& contacts,
                  const ContactDynamics& dynamics, const ContactSpace& space)
{
  if (const std::optional<AffineGuard> affine = affineForm(guard, contacts, space))
    return affine->sign * quantityAt(*affine, kinematics, space) + affine->offset;
  const int row = space.offset[guard.contact];
  const ContactState& contact = contacts[guard.contact];
  if (guard.releases_direction)
    return dynamics.relaxationRatio(guard.contact, kinematics.velocity, kinematics.force) - 1.0;
  // Stick to slip: |F_t| − μ F_n, i.e. E_t − μ²η²E_n in force form (docs/impact_model.md, Coulomb friction and
  // tangential compliance).
  if (guard.type == ContactEventType::StickToSlip)
    return std::hypot(kinematics.force(row + 1), kinematics.force(row + 2)) -
           contact.tangential.friction * kinematics.force(row);
  if (guard.type == ContactEventType::SlipToStick)
    return -dynamics.slidingSpeed(guard.contact, kinematics.y, kinematics);
  return -1.0;  // a rigid link is made by an end of compression, never by a guard of its own
}

TransitionEvents applyTransition(const Guard& guard, const Kinematics& kinematics, double* y,
                                 std::vector<ContactState>& contacts, const ContactSpace& space,
                                 const ChatterLimit& chatter)
{
  ContactState& contact = contacts[guard.contact];
  switch (guard.type)
  {
    case ContactEventType::EndOfCompression:
      return endCompression(guard.contact, kinematics, y, contacts, space, chatter);
    case ContactEventType::RestartOfCompression:
      contact.phase = NormalPhase::Compression;  // paper §3.3 (ii): k kept
      break;
    case ContactEventType::Separation:
    case ContactEventType::LinkRelease:
      stopTouching(guard.contact, y, contact, space);
      break;
    case ContactEventType::Reactivation:
      return activate(guard.contact, kinematics, y, contacts, space);  // paper §3.3 (iii): k kept
    case ContactEventType::StickToSlip:
    {
      const int row = space.offset[guard.contact];
      const Eigen::Vector2d force(kinematics.force(row + 1), kinematics.force(row + 2));
      if (force.norm() <= FORCE_TOLERANCE)
      {
        // A contact that slips as soon as it is touched (the cloth under a struck ball, pushed out of its cone from
        // the first instant): its springs hold round-off, whose direction is noise, even against the slip. It
        // slips from relaxed springs, along its slip velocity. Integrated from a noise direction, the friction could
        // push along the slip, and the result would depend on the tolerance.
        const Eigen::Vector2d slip(kinematics.velocity(row + 1), kinematics.velocity(row + 2));
        startSlip(contact, slip.norm() > 0.0 ? Eigen::Vector2d(slip.normalized()) : contact.tangential.slip_direction,
                  y, space, guard.contact, /*from_relaxed_springs=*/true);
        break;
      }
      // The spring points against its force.
      startSlip(contact, -force.normalized(), y, space, guard.contact, /*from_relaxed_springs=*/false);
      break;
    }
    case ContactEventType::SlipToStick:
      contact.tangential.slipping = false;
      {
        // While sliding the friction came from the normal force; from now on the spring holds that force. A link
        // that jams while it pulls (jammedLink) held none: −μfŝ with f < 0 is no friction, and as a spring it would
        // hold energy nothing paid for.
        double* spring = springs(y, space, guard.contact);
        const int row = space.offset[guard.contact];
        const bool holds = kinematics.force(row) > 0.0;
        spring[1] = holds ? -kinematics.force(row + 1) / contact.tangential.kappa : 0.0;
        spring[2] = holds ? -kinematics.force(row + 2) / contact.tangential.kappa : 0.0;
      }
      break;
    case ContactEventType::RigidLink:
      break;
  }
  return {guard.type};
}

namespace
{
/// Whether no contact can load again: none carries a force, none approaches, and none sticks while its bodies slip
/// (its tangential spring would load). The forces then stay zero and the velocities constant, so a contact that
/// touches without force and without normal velocity (a ball pushed into a cushion at the height of its centre
/// leaves the cloth under it unloaded) would touch for ever: it is let go.
bool nothingCanLoad(const Kinematics& kinematics, const std::vector<ContactState>& contacts, const ContactSpace& space)
{
  if (kinematics.force.lpNorm<Eigen::Infinity>() > FORCE_TOLERANCE)
    return false;
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const int row = space.offset[i];
    // An inactive contact loads only by reactivating, which takes an approach faster than its reactivation speed; with
    // RELEASE_VELOCITY for it too, one approaching slower than that (a chain's far balls) would keep a contact
    // touching at rest from being let go, and the state would run to the step bound.
    const double approach = contacts[i].active() ? RELEASE_VELOCITY : contacts[i].reactivation_speed;
    if (kinematics.velocity(row) < -approach)
      return false;
    const bool sticking = contacts[i].active() && space.dim[i] == 3 && !contacts[i].tangential.slipping;
    if (sticking && kinematics.velocity.segment<2>(row + 1).norm() > VELOCITY_TOLERANCE)
      return false;
  }
  return true;
}
}  // namespace

std::optional<Guard> immediateTransition(const Kinematics& kinematics, const std::vector<ContactState>& contacts,
                                         const ContactSpace& space, const std::vector<bool>& settled)
{
  Eigen::VectorXd acceleration;
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    if (settled[i])
      continue;
    const int row = space.offset[i];
    const double v_n = kinematics.velocity(row);
    const double s_n = kinematics.y[space.size + row];
    switch (contacts[i].phase)
    {
      case NormalPhase::Inactive:
        if (v_n < -contacts[i].reactivation_speed)
          return Guard{i, ContactEventType::Reactivation};
        if (v_n <= contacts[i].reactivation_speed)
        {
          // Grazing: the bodies touch with zero normal velocity; they stay in contact if they are pushed together.
          if (acceleration.size() == 0)
            acceleration = space.delassus * kinematics.force;
          if (acceleration(row) < -FORCE_TOLERANCE)
            return Guard{i, ContactEventType::Reactivation};
        }
        break;
      case NormalPhase::RigidLink:
        if (kinematics.force(row) <= FORCE_TOLERANCE)
          return Guard{i, ContactEventType::LinkRelease};
        break;
      case NormalPhase::Compression:
        if (s_n >= 0.0 && v_n > VELOCITY_TOLERANCE)
          return Guard{i, ContactEventType::EndOfCompression};
        [[fallthrough]];
      case NormalPhase::Restitution:
        // Relaxed and opening: its spring would pull from now on. A state can start so, its separation's guard
        // above zero by round-off where another transition takes the instant (a cue tip's link released as the
        // cloth relaxes: the cloth would pull the ball down and gain energy).
        if (contacts[i].phase == NormalPhase::Restitution && s_n >= 0.0 && v_n > VELOCITY_TOLERANCE)
          return Guard{i, ContactEventType::Separation};
        if (s_n >= 0.0 && std::abs(v_n) <= RELEASE_VELOCITY && nothingCanLoad(kinematics, contacts, space))
          return Guard{i, ContactEventType::Separation};
        break;
    }
  }
  return std::nullopt;
}

std::optional<Guard> jammedLink(ContactDynamics& dynamics, const Kinematics& kinematics,
                                std::vector<ContactState>& contacts, const ContactSpace& space,
                                const std::vector<bool>& settled)
{
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    ContactState& contact = contacts[i];
    if (settled[i] || contact.phase != NormalPhase::RigidLink || !contact.tangential.slipping)
      continue;
    const int row = space.offset[i];
    bool jams = dynamics.slidingSpeed(i, kinematics.y, kinematics) < -VELOCITY_TOLERANCE;
    if (!jams && kinematics.force(row) <= FORCE_TOLERANCE)
    {
      // Released, would it approach? Its grazing acceleration with the contact inactive (as a released one is
      // reactivated by immediateTransition).
      contact.phase = NormalPhase::Inactive;
      dynamics.refresh();
      const Eigen::VectorXd released = dynamics.forces(kinematics.y);
      contact.phase = NormalPhase::RigidLink;
      dynamics.refresh();
      jams = space.delassus.row(row).dot(released) < -FORCE_TOLERANCE;
    }
    if (jams)
    {
      contact.jammed = true;
      return Guard{i, ContactEventType::SlipToStick};
    }
  }
  return std::nullopt;
}

namespace
{
/// Relative size below which a derivative of a resting contact's normal velocity is round-off of the others.
constexpr double PRESS_TOLERANCE = 1e-12;

/// Whether the impact presses a contact that touches at rest at 0⁺: the sign of the first derivative of its normal
/// velocity that is not zero. With every spring relaxed, ẇ(0) = W F(0) = 0 and ẅ(0) = W Ḟ(0) = `jerk`; while the
/// dynamics is that of the springs, Ḟ = −K w, so the even derivatives go on as d ← −W K d (the odd ones vanish).
/// A contact that the approaching ones load only through others (the far balls of a chain) sees a later
/// derivative; one that no derivative reaches within as many orders as there are contacts is never pressed (the
/// cloth under a level hit through the ball's centre).
bool isPressed(std::size_t index, const Eigen::VectorXd& jerk, const Eigen::VectorXd& w,
               const std::vector<ContactState>& contacts, const ContactSpace& space)
{
  // The springs' stiffness along each row, their tangent stiffness relaxed (s = 0 at 0⁺). A resting contact's friction
  // is bounded by its own normal force, which is what is being decided: its tangential springs hold nothing at these
  // orders.
  Eigen::VectorXd stiffness = Eigen::VectorXd::Zero(space.size);
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    if (!contacts[i].compliant())
      continue;
    const int row = space.offset[i];
    stiffness(row) = contacts[i].normal.stiffnessAt(0.0);
    const bool resting = std::abs(w(row)) <= VELOCITY_TOLERANCE;
    if (space.dim[i] == 3 && !contacts[i].tangential.slipping && !resting)
      stiffness.segment<2>(row + 1).setConstant(contacts[i].tangential.kappa);
  }
  const int row = space.offset[index];
  Eigen::VectorXd derivative = jerk;
  for (std::size_t order = 0; order <= contacts.size(); ++order)
  {
    const double value = derivative(row);
    if (std::abs(value) > PRESS_TOLERANCE * derivative.lpNorm<Eigen::Infinity>())
      return value < 0.0;
    derivative = -(space.delassus * stiffness.asDiagonal() * derivative).eval();
  }
  return false;
}
}  // namespace

void releaseUnpressedRestingContacts(const Eigen::VectorXd& jerk, const Eigen::VectorXd& w,
                                     std::vector<ContactState>& contacts, const ContactSpace& space)
{
  std::vector<std::size_t> unpressed;
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const bool resting = contacts[i].compliant() && std::abs(w(space.offset[i])) <= VELOCITY_TOLERANCE;
    if (resting && !isPressed(i, jerk, w, contacts, space))
      unpressed.push_back(i);
  }
  // Decided together: each decision assumes the others' springs take part, as they do at 0⁺.
  for (std::size_t i : unpressed)
    contacts[i].phase = NormalPhase::Inactive;
}

void chooseRestingModes(const ContactDynamics& dynamics, OdeState& y, std::vector<ContactState>& contacts,
                        const ContactSpace& space)
{
  const Eigen::VectorXd w = dynamics.relativeVelocity(y.data());
  OdeState rates(y.size());
  SpringSystem springs(dynamics);
  springs(y, rates, 0.0);
  // J = d²w/dt² = W dF/dt, with dF/dt = −k ṡ_n, −κ ṡ_t for every spring.
  Eigen::VectorXd force_rate = Eigen::VectorXd::Zero(space.size);
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const int row = space.offset[i];
    const double* spring_rate = rates.data() + space.size + row;
    if (contacts[i].compliant())
      force_rate(row) = contacts[i].normal.forceRate(y.data()[space.size + row], spring_rate[0]);
    if (contacts[i].compliant() && space.dim[i] == 3)
      force_rate.segment<2>(row + 1) =
          contacts[i].tangential.forceRate(Eigen::Vector2d(spring_rate[1], spring_rate[2]));
  }
  const Eigen::VectorXd jerk = space.delassus * force_rate;
  releaseUnpressedRestingContacts(jerk, w, contacts, space);
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const int row = space.offset[i];
    if (!contacts[i].compliant() || space.dim[i] != 3 || w.segment<3>(row).norm() > VELOCITY_TOLERANCE)
      continue;
    const Eigen::Vector2d j_t = jerk.segment<2>(row + 1);
    const double bound = contacts[i].coneRate(std::abs(jerk(row)), y.data()[space.size + row]);
    contacts[i].tangential.slipping = j_t.norm() > bound * (1.0 + 1e-12) + VELOCITY_TOLERANCE * jerk.norm();
    if (contacts[i].tangential.slipping)
      contacts[i].tangential.slip_direction = j_t.normalized();
  }
  // Every contact that starts slipping (here, or the cue tip by its velocity) gets its direction carrier.
  // All springs are relaxed at the start, so they all follow their slip at first.
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if (contacts[i].sliding())
      startSlip(contacts[i], contacts[i].tangential.slip_direction, y.data(), space, i, /*from_relaxed_springs=*/true);
}

std::vector<ContactState> initialContactStates(const ImpactProblem& problem, const ContactSpace& space)
{
  std::vector<ContactState> contacts;
  for (std::size_t i = 0; i < problem.contacts.size(); ++i)
  {
    ContactState contact = initialContactState(problem.contacts[i].law, space.stiffness_scale);
    if (space.w0(space.offset[i]) <= VELOCITY_TOLERANCE)
    {
      contact.phase = NormalPhase::Compression;
      chooseInitialMode(contact, space.w0, space, i);
    }
    contacts.push_back(contact);
  }
  return contacts;
}

}  // namespace detail
}  // namespace billiard_shot_planner
