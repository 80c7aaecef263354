#pragma once

namespace billiard_shot_planner
{
/// The normal spring of the paper's compliant contact, F = −k s with s < 0 pressed (dimensionless: the solver's
/// contact space), and what an end of compression does to it: the restitution phase stiffens to k/e², so the spring
/// gives back the fraction e² of the energy it stored at the same force (paper §3.3).
///
/// A law names its spring by its spring() (docs/extending.md, "A new contact law"). A spring is linear when its
/// force is linear in the deformation between two ends of compression: the engine then solves a phase in closed form
/// and finds the state diagram's events by their affine bounds. A spring that is not linear says so (LINEAR = false)
/// and its phases are integrated, the step bounded by its tangent stiffness (stiffnessAt).
struct LinearSpring
{
  static constexpr bool LINEAR = true;

  /// The force F(s) = −k s at the current stiffness k.
  double force(double stiffness, double deformation) const { return -stiffness * deformation; }
  /// The energy the spring stores, ½ k s².
  double energy(double stiffness, double deformation) const { return 0.5 * stiffness * deformation * deformation; }
  /// The force's rate Ḟ = −k ṡ as the spring deforms at ṡ = `deformation_rate`.
  double forceRate(double stiffness, double /*deformation*/, double deformation_rate) const
  {
    return -stiffness * deformation_rate;
  }
  /// The tangent stiffness −dF/ds at s: k. It bounds the frequency of a phase and sets the friction cone's rate.
  double stiffnessAt(double stiffness, double /*deformation*/) const { return stiffness; }
  /// The stiffness of the restitution phase after an end of compression that keeps the fraction `kept_energy` = e²
  /// of the stored energy: k/e². The deformation shrinks by e² with it, so the force is continuous.
  double restitutionStiffness(double stiffness, double kept_energy) const { return stiffness / kept_energy; }
  /// The deformation at which the restitution phase starts from a compression that ended at s: e² s.
  double restitutionDeformation(double deformation, double kept_energy) const { return deformation * kept_energy; }
};

}  // namespace billiard_shot_planner
