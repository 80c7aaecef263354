#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// A pocket's capture region: a ball whose centre comes within `radius` of `centre` (table plane) drops in. `id`
/// names it in events and plans; a pocket given without one is named by its place in the list ("pocket0", …).
struct Pocket
{
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.06;
  std::string id{};
};

/// Six pockets of a pool table: corner capture regions centred on the corners (radius 0.06 m), side ones on the
/// middle of the long cushions (radius 0.065 m), named as the outline names them (bottom_left, bottom_right,
/// top_left, top_right, bottom_side, top_side: docs/tables.md).
std::vector<Pocket> sixPockets(double length, double width);

/// The ids of the four rails as straight cushions through the pockets (PocketModel::Circles, and a carom table's
/// outline): along −x, +x, −y and +y.
inline constexpr std::array<const char*, 4> RAIL_IDS = {"rail.left", "rail.right", "rail.bottom", "rail.top"};

/// The index in `pockets` of the pocket with `id` (pocketId), or −1.
int pocketIndex(const std::vector<Pocket>& pockets, const std::string& id);

/// The id of `pockets[index]`: its own, or for a pocket given without one its place in the list ("pocket0", …).
std::string pocketId(const std::vector<Pocket>& pockets, std::size_t index);

/// How a pocket is cut into the cushions, in the terms of the WPA's equipment specifications (docs/tables.md).
struct PocketCut
{
  double mouth = 0.0;         ///< m, between the jaw points, where the two cushions' noses turn into the pocket
  double facing_angle = 0.0;  ///< deg, the cushion's angle at its jaw point, between its nose and its facing
  double shelf = 0.0;         ///< m, from the middle of the mouth, along the pocket's axis, to the slate's cut
  double jaw_radius = 0.0;    ///< m, the rounding of each jaw point (0: a sharp point)
  double drop_radius = 0.0;   ///< m, the slate's cut as a circle: a ball whose centre passes over it falls

  /// The facing angle in radians.
  double cutAngle() const { return facing_angle * M_PI / 180.0; }
};

/// Which pockets the table has: six (pool, snooker) or none (carom).
enum class PocketLayout
{
  Six,
  None
};

/// How the motion meets the pockets.
enum class PocketModel
{
  /// The rails run straight through the pockets and a ball drops when its centre enters a capture circle
  /// (Table::pockets): the planner's model.
  Circles,
  /// The table's outline (tableOutline): the rails end at rounded jaw points, the jaws' facings are cushions like the
  /// rails, and a ball drops when its centre passes over the slate's cut behind the shelf.
  Jaws
};

/// A rectangular pool table in the table frame: origin at the centre of the playing surface (the cloth), x along
/// its length, z up. Cushion noses run along the four edges of the playing surface at `cushion_height` above the
/// cloth. Defaults: a 9-ft pool table (see config/table_9ft.yaml for sources).
struct Table
{
  double length = 2.54;            ///< m, playing surface between cushion noses along x (WPA: 100 in)
  double width = 1.27;             ///< m, along y (WPA: 50 in)
  double cushion_height = 0.0363;  ///< m, nose above the cloth (WPA: 63.5 % of a 57.15 mm ball)
  std::vector<Pocket> pockets = sixPockets(2.54, 1.27);

  /// The pockets' cuts, from which the table's geometry (tableOutline) lays out its jaws and drop regions. The WPA
  /// ranges' middles: corner mouth 4.5-4.625 in at 142 deg, shelf 1-2.25 in; side mouth 5-5.125 in at 104 deg, shelf
  /// 0-0.375 in. The jaw's rounding and the slate's cut are not specified (docs/tables.md says how they are chosen).
  PocketLayout pocket_layout = PocketLayout::Six;
  PocketModel pocket_model = PocketModel::Circles;
  PocketCut corner_pockets{0.1158875, 142.0, 0.041275, 0.005, 0.0529};
  PocketCut side_pockets{0.12858750, 104.0, 0.0047625, 0.005, 0.0631};

  SurfaceContact cloth{0.51625, 0.152479, 10.0};  ///< ball on cloth: e, μ, η² (paper §9.2)
  SurfaceContact cushion{0.85, 0.2, 10.0};        ///< ball on cushion nose: e, μ, η²
  double cushion_stiffness_ratio = 1.0;           ///< k_cushion / k_cloth
};

/// The capture regions a table has when none are given: sixPockets for its size, none without pockets.
std::vector<Pocket> defaultPockets(const Table& table);

/// Whether two tables have the same default capture regions (the same size and pocket layout): a reader that finds
/// no pockets keeps the ones it started from only then.
bool sameDefaultPockets(const Table& a, const Table& b);

/// Checks a pocket's cut field by field; the error names the field ("table.corner_pockets.mouth").
Status validate(const PocketCut& cut, const std::string& field);

/// Checks dimensions, pockets (finite centres, positive radii, ids unique, capture regions apart) and contact laws, and
/// that the pockets' cuts lay out (tableOutline); the error names the field ("table.cushion.friction",
/// "table.pockets[2].id").
Status validate(const Table& table, const std::string& field = "table");

/// The horizontal distance between a ball's centre and a cushion nose when they touch with the ball on the cloth:
/// R cos θ with sin θ = (h − R)/R, the nose being h above the cloth.
double cushionReach(const Table& table, double radius);

/// The lowest cushion nose that can hold a ball on the table, in ball radii: 1 − 1/√2 ≈ 0.293. Below it the
/// contact normal rises more than 45° above the cloth (sin α = (R − h)/R), and even a frictionless, perfectly
/// elastic nose leaves a ball that meets it head-on moving on into the rail (v' = v (sin²α − e cos²α), e ≤ 1) and
/// up over it. Friction on a rolling ball, whose contact point slips down the nose, only adds to that: the engine
/// turns a ball rolling into a nose with e = 1 back from 0.295 R without friction, from 0.2975 to 0.325 R with μ from
/// 0.1 to 1 and η² from 1 to 10.
constexpr double MIN_CUSHION_HEIGHT = 1.0 - 0.70710678118654752440;

/// Checks the cushion nose against the ball: at least MIN_CUSHION_HEIGHT radii above the cloth and below the top of
/// the ball. `field` names the nose height in the error.
Status validateCushionHeight(double cushion_height, double ball_radius, const std::string& field);

/// Checks the table against its balls: the cushion's nose (validateCushionHeight, `field`.cushion_height) and, on a
/// table with pockets, each cut's mouth wider than a ball (`field`.corner_pockets.mouth): through a narrower one no
/// ball could drop.
Status validateForBall(const Table& table, double ball_radius, const std::string& field = "table");

}  // namespace billiard_shot_planner
