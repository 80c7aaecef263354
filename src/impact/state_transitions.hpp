#pragma once

#include <boost/container/static_vector.hpp>
#include <optional>
#include <vector>

#include "billiard_shot_planner/impact/impact_result.hpp"
#include "contact_dynamics.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The state transition diagram (paper §3.1, generated on the fly for any number of contacts as in §10, with the
/// tangential modes of docs/impact_model.md, Coulomb friction and tangential compliance): which transitions are
/// armed in a discrete state, when they fire, and what they do to the contact.

/// A transition that may fire: it fires when its guard function rises through zero.
struct Guard
{
  std::size_t contact;
  ContactEventType type;
  /// Not a transition of the diagram but of the numerics: a contact's slip direction stops following the slip
  /// (TangentialSpring::quasi_steady) and is integrated from then on. Logged as no event.
  bool releases_direction = false;
};

/// A guard that is one kinematic quantity of one contact-space row, signed and offset: g = sign · q(row) + offset.
/// Every guard of the normal phases is one. Where the dynamics is linear, such a guard is a sum of sines whose value
/// and rate the closed form gives from its modes alone, without the state or the force law.
struct AffineGuard
{
  enum class Quantity
  {
    Velocity,  ///< relative contact velocity w
    Spring,    ///< spring deformation s
    Force,     ///< contact force F
  };
  Quantity quantity;
  int row;
  double sign;
  double offset;
};

/// The guard's affine form, if it has one (the tangential and direction guards do not).
std::optional<AffineGuard> affineForm(const Guard& guard, const std::vector<ContactState>& contacts,
                                      const ContactSpace& space);

/// Guard values (dimensionless) within round-off of zero at the start of a state: the contact that has just switched
/// starts its new guard at zero, but the state it switched at was found by the old state's dynamics and is re-read by
/// the new one's, up to round-off on either side. Both crossing searches take such a start for zero.
constexpr double START_ROUND_OFF = 1e-12;

/// Values that every guard evaluation at one instant shares: the velocities, forces and slip directions at y.
struct Kinematics : ForceEvaluation
{
  const double* y = nullptr;
};

/// Relative velocity, forces and slip directions at y, into an existing Kinematics (its vectors reused).
void evaluateKinematics(const ContactDynamics& dynamics, const double* y, Kinematics& kinematics);

/// Guards armed by the current discrete state, into `guards` (returned).
const std::vector<Guard>& armedGuards(const std::vector<ContactState>& contacts, const ContactSpace& space,
                                      std::vector<Guard>& guards);

/// g such that the transition fires when g rises through zero.
double guardValue(const Guard& guard, const Kinematics& kinematics, const std::vector<ContactState>& contacts,
                  const ContactDynamics& dynamics, const ContactSpace& space);

/// Round-off of the velocity of contact-space row `row` from the impulses, w = w0 + W I (dimensionless): large where
/// the impulses are, against a velocity that is their difference (a ball between a heavy cue and the cloth).
double velocityRoundOff(const ContactSpace& space, const double* impulses, int row);

/// When a contact's sequence of compressions is taken to be infinite and replaced by its limit.
struct ChatterLimit
{
  double energy;            ///< dimensionless stored energy below which a further end of compression means chatter
  double stiffness_growth;  ///< or once k/k̄ exceeds this
  double deformation;       ///< or once the deformation |s_n| at a third or later end of compression is below this
                            ///< (zero in closed-form states: their springs are exact to round-off)
};

/// The events one transition logs: at most two (an end of compression that makes a rigid link, a reactivation that
/// separates at once). Kept off the heap: transitions are a large part of a short impact.
using TransitionEvents = boost::container::static_vector<ContactEventType, 2>;

/// Applies a fired transition to the contact (and its springs in y). Returns the events to log, in order: usually
/// just guard.type, but an end of compression can also turn the contact into a rigid link, and one on an unloaded
/// contact is a separation.
TransitionEvents applyTransition(const Guard& guard, const Kinematics& kinematics, double* y,
                                 std::vector<ContactState>& contacts, const ContactSpace& space,
                                 const ChatterLimit& chatter);

/// A transition that must happen at once in the current configuration, without any time passing: an inactive
/// contact that approaches (or is about to), a rigid link whose force is not compressive, a contact in
/// compression that never loaded and is opening, a contact that touches without force or normal velocity when
/// nothing can load it any more. Contacts marked `settled` are left as they are.
std::optional<Guard> immediateTransition(const Kinematics& kinematics, const std::vector<ContactState>& contacts,
                                         const ContactSpace& space, const std::vector<bool>& settled);

/// A sliding rigid link that cannot slide, and so jams: it sticks (a slip-to-stick transition, returned), and
/// stays stuck while it holds (ContactState::jammed). A compliant contact slips only with a sliding speed
/// σ = ŝ·v_t + μη²v_n ≥ 0, continuous in its state; a link's force is a constraint's, and where friction couples
/// the links' normals strongly enough (Painlevé's inconsistency: for one link, W_nn − μ W_n·ŝ < 0) its slip has
/// σ = ŝ·v_t − μḟ/κ < 0, or needs a pulling force while, released, the contact would approach. Such a slip makes
/// friction work with the motion, and the force and the energy grow without bound. The limit of a stiff contact
/// that slips in that configuration is a jam: the normal force builds up until the contact sticks. Contacts marked
/// `settled` are left as they are. May refresh `dynamics` (it restores what it changes).
std::optional<Guard> jammedLink(ContactDynamics& dynamics, const Kinematics& kinematics,
                                std::vector<ContactState>& contacts, const ContactSpace& space,
                                const std::vector<bool>& settled);

/// Contacts that touch at rest when the impact starts (a ball on the cloth under the cue) take part only if the
/// impact presses them together: those that the approaching contacts pull apart (a draw shot lifting the ball) or
/// never load (a level hit through the ball's centre) start inactive, and join later by reactivation if they are
/// pressed after all. `jerk` = d²w/dt² at 0⁺, `w` the initial contact velocities.
void releaseUnpressedRestingContacts(const Eigen::VectorXd& jerk, const Eigen::VectorXd& w,
                                     std::vector<ContactState>& contacts, const ContactSpace& space);

/// Initial tangential mode of contacts that start at rest relative to each other (the ball on the cloth at the first
/// instant of a shot; docs/impact_model.md, Resting contacts): the limit of the spring ratio is set by
/// J = d²w/dt² at 0⁺, so the contact sticks iff |J_t| ≤ μη²|J_n|, and otherwise slips along Ĵ_t.
/// First releases the resting contacts that the impact does not press (releaseUnpressedRestingContacts).
/// Also places the slip-direction carrier of every contact that starts slipping.
void chooseRestingModes(const ContactDynamics& dynamics, OdeState& y, std::vector<ContactState>& contacts,
                        const ContactSpace& space);

/// Initial discrete state: every contact whose bodies approach or touch (normal velocity ≤ 0) starts compressing.
std::vector<ContactState> initialContactStates(const ImpactProblem& problem, const ContactSpace& space);

}  // namespace detail
}  // namespace billiard_shot_planner
