#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// A pocket's capture region: a ball whose centre comes within `radius` of `centre` (table plane) drops in.
struct Pocket
{
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.06;
};

/// Six pockets of a pool table: corner capture regions centred on the corners (radius 0.06 m), side ones on the
/// middle of the long cushions (radius 0.065 m).
std::vector<Pocket> sixPockets(double length, double width);

/// A rectangular pool table in the table frame: origin at the centre of the playing surface (the cloth), x along
/// its length, z up. Cushion noses run along the four edges of the playing surface at `cushion_height` above the
/// cloth. Defaults: a 9-ft pool table (see config/table_9ft.yaml for sources).
struct Table
{
  double length = 2.54;            ///< m, playing surface between cushion noses along x (WPA: 100 in)
  double width = 1.27;             ///< m, along y (WPA: 50 in)
  double cushion_height = 0.0363;  ///< m, nose above the cloth (WPA: 63.5 % of a 57.15 mm ball)
  std::vector<Pocket> pockets = sixPockets(2.54, 1.27);

  SurfaceContact cloth{0.51625, 0.152479, 10.0};  ///< ball on cloth: e, μ, η² (paper §9.2)
  SurfaceContact cushion{0.85, 0.2, 10.0};        ///< ball on cushion nose: e, μ, η²
  double cushion_stiffness_ratio = 1.0;           ///< k_cushion / k_cloth
};

/// Checks dimensions, pockets and contact laws; the error names the field ("table.cushion.friction").
Status validate(const Table& table, const std::string& field = "table");

}  // namespace billiard_shot_planner
