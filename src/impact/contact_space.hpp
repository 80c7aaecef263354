#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "billiard_shot_planner/impact/impact_problem.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The impact problem projected onto its contacts and made dimensionless.
///
/// Contact i owns rows [offset[i], offset[i] + dim[i]) of contact space: the normal first, then (for a
/// frictional contact) the two tangents. Relative contact velocity is w = w0 + W·I, with W = J M⁻¹ Jᵀ the
/// Delassus matrix, so the impulses I (with the springs) are the whole state. Velocities are scaled by the
/// largest initial relative velocity, W by its largest normal diagonal entry and stiffnesses by the largest
/// original normal stiffness; paper Theorem 5 and its frictional analogue (docs/impact_model.md, Scaling) make this
/// exact.
struct ContactSpace
{
  std::vector<int> offset;
  std::vector<int> dim;
  int size = 0;

  Eigen::MatrixXd delassus;  ///< W̃, dimensionless
  /// W̃ without its zeros, when it has few: balls that share no contact leave zero blocks (a rack's W̃ is four
  /// fifths zeros), and products with it are most of a large impact's cost. Empty when W̃ is small or dense.
  Eigen::SparseMatrix<double, Eigen::RowMajor> sparse_delassus;
  Eigen::VectorXd w0;        ///< w̃0, dimensionless
  Eigen::MatrixXd response;  ///< M⁻¹ Jᵀ in physical units: Δu = response · I

  double velocity_scale = 1.0;   ///< V
  double impulse_scale = 1.0;    ///< V / W_ref
  double energy_scale = 1.0;     ///< V² / W_ref
  double time_scale = 1.0;       ///< 1 / √(k_ref W_ref)
  double stiffness_scale = 1.0;  ///< k_ref

  std::size_t contactCount() const { return offset.size(); }
  bool sparse() const { return sparse_delassus.nonZeros() > 0; }
};

/// Dimensionless velocity below which a contact velocity is round-off (the normalised velocities are of order one).
constexpr double VELOCITY_TOLERANCE = 1e-12;

/// Builds the contact space of a validated problem. A contact whose relative velocity is round-off starts at rest,
/// exactly: a rolling ball's cloth contact carries a slip of 1e-16 from v + ω × r.
ContactSpace buildContactSpace(const ImpactProblem& problem);

}  // namespace detail
}  // namespace billiard_shot_planner
