#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/table.hpp"

namespace billiard_shot_planner
{
/// One piece of the cushions' noses seen from above (at the nose's height, in the table frame): a straight segment
/// — a rail between two pockets or a jaw's facing — or a circular arc, a jaw's rounded point. Walking from `start`
/// to `end` the cloth lies on the left, so the outline runs counterclockwise around the table.
struct NoseSegment
{
  enum class Shape
  {
    Line,
    Arc
  };

  std::string id;  ///< "rail.bottom.left", "pocket.bottom_left.jaw.bottom.facing", … (docs/tables.md lists them)
  Shape shape = Shape::Line;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< an arc's centre (inside the cushion)
  double radius = 0.0;                               ///< an arc's radius
  double sweep = 0.0;  ///< rad, an arc's turn from start to end about its centre (negative: clockwise)

  double length() const;
  /// The segment's point nearest to `point`.
  Eigen::Vector2d closestPoint(const Eigen::Vector2d& point) const;
};

/// A pocket's opening: the mouth between its two jaw points, its axis and the region a ball's centre falls into.
struct PocketOpening
{
  std::string id;                                         ///< "bottom_left", "bottom_side", … (docs/tables.md)
  Eigen::Vector2d jaw_in = Eigen::Vector2d::Zero();       ///< the jaw point the outline reaches the pocket by
  Eigen::Vector2d jaw_out = Eigen::Vector2d::Zero();      ///< the jaw point it leaves the pocket by
  Eigen::Vector2d axis = Eigen::Vector2d::UnitX();        ///< unit, from the mouth's middle into the pocket
  Eigen::Vector2d drop_centre = Eigen::Vector2d::Zero();  ///< the slate's cut, a circle behind the shelf
  double drop_radius = 0.0;

  Eigen::Vector2d mouthMiddle() const { return 0.5 * (jaw_in + jaw_out); }
  double mouth() const { return (jaw_out - jaw_in).norm(); }
  /// Whether a ball whose centre is at `point` has passed over the slate's edge and falls.
  bool drops(const Eigen::Vector2d& point) const { return (point - drop_centre).norm() < drop_radius; }
};

/// The table's outline: cushion segments counterclockwise from the bottom-left corner pocket (the corner at −x, −y)
/// and the pockets, each with an id unique on the table.
struct TableOutline
{
  std::vector<NoseSegment> cushions;
  std::vector<PocketOpening> pockets;

  /// The segment or pocket with `id`, or null.
  const NoseSegment* cushion(const std::string& id) const;
  const PocketOpening* pocket(const std::string& id) const;
  /// The segments of pocket `id`'s jaws (each facing and its rounded point), in the outline's order.
  std::vector<NoseSegment> jawsOf(const std::string& pocket) const;
};

/// Lays out the table's cushions and pockets from its size and its pockets' cuts (Table::pocket_layout,
/// corner_pockets, side_pockets): the rails follow the length and width, each pocket's jaws are cut at its facing
/// angle with their points rounded, and its drop region lies behind the shelf. Errors: validate(table)'s, which
/// include a cut that does not fit (two pockets' jaws leaving no rail between them, a rounding longer than its
/// facing, facings that meet before the slate's cut), naming the cut's field.
Expected<TableOutline> tableOutline(const Table& table, const std::string& field = "table");

}  // namespace billiard_shot_planner
