#pragma once

#include <string>
#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// A ball rolling without side spin, driven straight into a cushion: its speed along the cushion's normal before
/// and right after the impact, as tracked (m/s).
struct CushionRebound
{
  double speed_in = 0.0;
  double speed_out = 0.0;
};

/// The table a set of rebounds was measured on: the ball, the height of the cushion's contact and the constants of
/// the impact (the cushion's are what fitCushionRebounds fits).
struct CushionReboundTable
{
  double ball_mass = 0.17;         ///< kg
  double ball_radius = 0.0286;     ///< m
  double contact_height = 0.0363;  ///< m above the cloth, in (R, 2R): where the cushion's nose touches the ball
  SurfaceContact cushion{0.85, 0.2, 10.0};
  SurfaceContact cloth{0.51625, 0.152479, 10.0};
  double cushion_stiffness_ratio = 1.0;  ///< k_cushion / k_cloth
};

/// The parameters a rebound fit may fit: "cushion.restitution", "cushion.friction", "cushion.eta2",
/// "cushion_stiffness_ratio" and the cushion law's own ("cushion.law.yield_speed").
std::vector<std::string> reboundParameters(const CushionReboundTable& table);

/// The table with the named values applied. Errors: a name reboundParameters does not list.
Status applyReboundValues(const std::vector<std::string>& names, const std::vector<double>& values,
                          CushionReboundTable& table);

/// The speed along the normal right after the impact of a ball rolling into the cushion at `speed_in` (m/s): one
/// multiple impact of the ball with the cushion and the cloth. Errors: the table's constants out of range
/// (InvalidArgument naming them), a contact height outside (R, 2R), and the engine's.
Expected<double> predictRebound(const CushionReboundTable& table, double speed_in, const SolverOptions& options = {});

/// Fits the named parameters to measured rebounds by fitLeastSquares on the ratios, (v_out − v_obs)/(σ v_in), with
/// σ = `ratio_sigma` (> 0) the standard deviation of a measured ratio v_out/v_in: the scatter of repeated impacts
/// grows with their speed. Errors: InvalidArgument naming a parameter (unknown, or a start the table rejects),
/// `ratio_sigma`, or a rebound ("rebounds[3].speed_in": speeds must be > 0), and fitLeastSquares' own.
Expected<FitResult> fitCushionRebounds(const CushionReboundTable& table, const std::vector<FitParameter>& parameters,
                                       const std::vector<CushionRebound>& rebounds, double ratio_sigma,
                                       const FitOptions& options = {});

}  // namespace billiard_shot_planner
