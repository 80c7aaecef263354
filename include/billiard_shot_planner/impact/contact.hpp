#pragma once

#include <Eigen/Core>
#include <string>

#include "billiard_shot_planner/impact/laws/normal_law.hpp"

namespace billiard_shot_planner
{
/// The constitutive law of one contact (paper §2–3 and §8.1; docs/impact_model.md): a normal virtual spring whose
/// stiffness grows by 1/e² at every end of compression, e as `normal_law` gives it for that compression, and
/// optionally two tangential springs with Coulomb friction.
struct ContactLaw
{
  double restitution = 1.0;  ///< energetic coefficient of restitution e, in [0, 1] (at low speed, under normal_law)
  double stiffness = 1.0;    ///< original normal stiffness k̄ (> 0); only ratios between contacts matter
  double friction = 0.0;     ///< Coulomb coefficient μ (≥ 0); 0 makes the contact frictionless
  double eta2 = 1.0;         ///< η̄² = k̄/κ, normal over tangential stiffness (> 0); unused when friction is 0
  NormalLaw normal_law;      ///< how e depends on the compression (default: constant, the paper's law)
};

/// One contact between two bodies (or a body and a fixed obstacle), described by its contact Jacobian.
///
/// The relative velocity of body A with respect to body B at the contact point, in the contact frame
/// (t̂1, t̂2, n̂) with n̂ pointing from B to A, is (tangent * u, normal * u) for generalised velocity u.
/// The impulse reported for the contact is the impulse on A. A negative normal velocity means approach.
struct Contact
{
  std::string name;                                  ///< for reports and error messages
  Eigen::RowVectorXd normal;                         ///< 1×d row: normal relative velocity
  Eigen::Matrix<double, 2, Eigen::Dynamic> tangent;  ///< 2×d rows (t̂1, t̂2); may be left empty when friction is 0
  ContactLaw law;

  bool hasFriction() const { return law.friction > 0.0; }
};

}  // namespace billiard_shot_planner
