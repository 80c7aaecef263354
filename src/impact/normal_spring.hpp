#pragma once

#include <variant>

#include "billiard_shot_planner/impact/laws/normal_law.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// A contact's normal spring: its law (immutable) and what the law's state is now — the current stiffness and the
/// restitution of the current compression. Every force, energy and rate of a normal spring the engine reads comes
/// from here, and through here from the law (docs/extending.md, "A new contact law").
struct NormalSpring
{
  NormalLaw law;
  bool linear = true;      ///< the law's LINEAR: gates the closed form of a phase (LinearPhaseStepper::build)
  double stiffness = 1.0;  ///< current k = k̄ / e^{2j} (dimensionless)
  double original_stiffness = 1.0;
  /// The restitution of the current (or last) compression, as the law gives it at its end (see restituteAt).
  double restitution = 1.0;
  double low_speed_restitution = 1.0;  ///< the law's e0: ContactLaw::restitution

  /// The force F(s) at deformation s (s < 0 pressed).
  double force(double deformation) const
  {
    return std::visit([&](const auto& l) { return l.spring().force(stiffness, deformation); }, law);
  }
  /// The energy it stores at s.
  double energy(double deformation) const
  {
    return std::visit([&](const auto& l) { return l.spring().energy(stiffness, deformation); }, law);
  }
  /// Ḟ as it deforms at ṡ = `deformation_rate` from s.
  double forceRate(double deformation, double deformation_rate) const
  {
    return std::visit([&](const auto& l) { return l.spring().forceRate(stiffness, deformation, deformation_rate); },
                      law);
  }
  /// The tangent stiffness −dF/ds at s: the frequency bound's and the friction cone's rate's.
  double stiffnessAt(double deformation) const
  {
    return std::visit([&](const auto& l) { return l.spring().stiffnessAt(stiffness, deformation); }, law);
  }
  /// The stiffness the restitution phase would take after this compression (the chatter bound reads it).
  double restitutionStiffness() const
  {
    return std::visit(
        [&](const auto& l) { return l.spring().restitutionStiffness(stiffness, restitution * restitution); }, law);
  }
  /// Sets `restitution` to the law's for a compression whose energy-equivalent approach speed is `impact_speed`
  /// (m/s), and returns it.
  double restituteAt(double impact_speed)
  {
    restitution = restitutionOf(law, low_speed_restitution, impact_speed);
    return restitution;
  }
  /// Ends a compression at deformation s: the spring keeps e² of its energy at a continuous force, and the returned
  /// deformation is the restitution phase's start.
  double endCompression(double deformation)
  {
    const double kept_energy = restitution * restitution;
    return std::visit(
        [&](const auto& l)
        {
          const auto spring = l.spring();
          stiffness = spring.restitutionStiffness(stiffness, kept_energy);
          return spring.restitutionDeformation(deformation, kept_energy);
        },
        law);
  }
};

}  // namespace detail
}  // namespace billiard_shot_planner
