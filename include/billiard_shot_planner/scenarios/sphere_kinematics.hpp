#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/contact.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"

namespace billiard_shot_planner
{
/// Contact-frame rows (t̂1, t̂2, n̂) for a unit normal n̂: t̂1 ⟂ n̂ chosen from the coordinate axis least aligned
/// with n̂, t̂2 = n̂ × t̂1, so that t̂1 × t̂2 = n̂. Isotropic tangential springs make results independent of the choice.
inline Eigen::Matrix3d contactFrame(const Eigen::Vector3d& normal)
{
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  Eigen::Index least;
  normal.cwiseAbs().minCoeff(&least);
  axis(least) = 1.0;
  const Eigen::Vector3d t1 = (axis - axis.dot(normal) * normal).normalized();
  Eigen::Matrix3d frame;
  frame.row(0) = t1;
  frame.row(1) = normal.cross(t1);
  frame.row(2) = normal;
  return frame;
}

/// Rows mapping a sphere's (v, ω) to the velocity of its material point at `lever` from the centre, projected on
/// the rows of `frame`: d·(v + ω × lever) = [dᵀ, (lever × d)ᵀ]·(v, ω).
inline Eigen::Matrix<double, 3, 6> pointVelocityRows(const Eigen::Matrix3d& frame, const Eigen::Vector3d& lever)
{
  Eigen::Matrix<double, 3, 6> rows;
  for (int k = 0; k < 3; ++k)
  {
    const Eigen::Vector3d d = frame.row(k).transpose();
    rows.block<1, 3>(k, 0) = d.transpose();
    rows.block<1, 3>(k, 3) = lever.cross(d).transpose();
  }
  return rows;
}

/// A free solid ball (inertia 2/5 m r²) as the body of an impact: mass matrix and generalised velocity (v, ω); the
/// contacts are the scenario's.
inline ImpactProblem freeBallProblem(double mass, double radius, const Eigen::Vector3d& velocity,
                                     const Eigen::Vector3d& angular_velocity)
{
  const double inertia = 0.4 * mass * radius * radius;
  ImpactProblem problem;
  problem.mass_matrix =
      (Eigen::Matrix<double, 6, 1>() << mass, mass, mass, inertia, inertia, inertia).finished().asDiagonal();
  problem.velocity.resize(6);
  problem.velocity << velocity, angular_velocity;
  return problem;
}

/// Rows of the ball's lowest point, where it touches the cloth, in the table axes as the contact frame (normal ẑ).
inline Eigen::Matrix<double, 3, 6> clothContactRows(double radius)
{
  return pointVelocityRows(Eigen::Matrix3d::Identity(), -radius * Eigen::Vector3d::UnitZ());
}

/// Friction and compliance of one kind of surface contact; its normal stiffness is set by the scenario.
struct SurfaceContact
{
  SurfaceContact() = default;
  /// {e, μ, η²}, and optionally the law: the constants' usual order, the law last because most contacts keep the
  /// default.
  SurfaceContact(double restitution_, double friction_, double eta2_, NormalLaw normal_law_ = {})
      : restitution(restitution_), friction(friction_), eta2(eta2_), normal_law(normal_law_)
  {
  }

  double restitution = 1.0;  ///< energetic coefficient e, in [0, 1]
  double friction = 0.0;     ///< Coulomb μ ≥ 0
  double eta2 = 1.0;         ///< η̄² = k̄/κ > 0, normal over tangential stiffness
  NormalLaw normal_law;      ///< how e depends on the impact (default: constant); configuration's "law"
};

/// Checks e ∈ [0, 1], μ ≥ 0, η² > 0 and the law's parameters; the error names the field as `field`.restitution,
/// .friction, .eta2 or .law.<parameter>.
Status validate(const SurfaceContact& surface, const std::string& field);

inline ContactLaw contactLaw(const SurfaceContact& surface, double stiffness)
{
  return ContactLaw{surface.restitution, stiffness, surface.friction, surface.eta2, surface.normal_law};
}

/// Fills a contact from its frame and the rows of its Jacobian in that frame (normal last).
inline Contact makeContact(const char* name, const Eigen::MatrixXd& frame_rows, const ContactLaw& law)
{
  Contact contact;
  contact.name = name;
  contact.tangent = frame_rows.topRows(2);
  contact.normal = frame_rows.row(2);
  contact.law = law;
  return contact;
}

}  // namespace billiard_shot_planner
