#pragma once

// The table as the motion meets it: the cushions' noses in pieces a ball's contact search handles in closed form or
// by sampling, and the regions a ball's centre drops into. Both pocket models (Table::pocket_model) are laid out here,
// so that the motion's events, the start's checks and the impacts' contacts read one geometry.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/table.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// A straight nose seen from above: the line outward·x = edge at the cushion's height, `outward` being the unit
/// horizontal normal out of the table.
struct Nose
{
  Eigen::Vector2d outward;
  double edge;

  /// How far `v` (a position's or a velocity's horizontal part) points out of the table, across the nose.
  double outwardPart(const Eigen::Vector3d& v) const { return outward.x() * v.x() + outward.y() * v.y(); }
};

/// The rails' noses as infinite lines, numbered by their place here: 0 at −x, 1 at +x, 2 at −y, 3 at +y.
std::array<Nose, 4> railNoses(const Table& table);

/// One piece of a cushion's nose, at the nose's height: a straight stretch, a circular arc (a jaw's rounded point,
/// the ball meeting it from outside the circle) or a point (a sharp jaw, the free end of a facing).
struct NosePiece
{
  enum class Shape
  {
    Line,
    Arc,
    Point
  };

  Shape shape = Shape::Line;
  /// The cushion segment it belongs to: its index in MotionGeometry::cushion_ids.
  int cushion = -1;
  /// Line: its nose line, and where along `tangent` the piece runs (the circles' rails are infinite).
  Nose line{Eigen::Vector2d::UnitX(), 0.0};
  Eigen::Vector2d tangent = Eigen::Vector2d::UnitY();
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
  /// Arc and Point: the centre (a point's place) and the radius (0 for a point).
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
  /// Arc: the unit direction from its centre to its start, and its signed turn to its end (negative: clockwise).
  Eigen::Vector2d arc_start = Eigen::Vector2d::UnitX();
  double sweep = 0.0;

  /// Whether the nose point nearest a ball's centre at `point` (table plane) lies on this piece: within a line's
  /// extent or an arc's sweep, with a nanometre's overlap where pieces join so that no point falls between them.
  bool covers(const Eigen::Vector2d& point) const;
  /// The horizontal distance from `point` to the piece's nose, positive on the table's side of it.
  double across(const Eigen::Vector2d& point) const;
  /// Whether a ball's centre at `point` (on the cloth) is closer to the nose than `reach` by more than `tolerance`:
  /// the ball overlaps the cushion.
  bool overlaps(const Eigen::Vector2d& point, double reach, double tolerance) const;
  /// The unit horizontal direction out of the table at the nose point nearest `point`.
  Eigen::Vector2d outwardAt(const Eigen::Vector2d& point) const;
};

/// A region a ball's centre drops into: a capture circle, or the slate's cut behind a pocket's shelf.
struct DropRegion
{
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
  std::string pocket;                   ///< the pocket's id ("bottom_side")
  const char* kind = "capture region";  ///< "capture region" or "drop region"

  /// What an error calls it: "pocket bottom_side's capture region" or "… drop region". Composed only then:
  /// the geometry is laid out for every simulation.
  std::string describe() const { return "pocket " + pocket + "'s " + kind; }
};

/// A pocket's throat seen from above: the quadrilateral between its two jaw points and its facings' far ends, where
/// a ball's centre is on the pocket's shelf though beyond the rails' lines.
struct Throat
{
  std::array<Eigen::Vector2d, 4> corners;  ///< counterclockwise

  bool contains(const Eigen::Vector2d& point) const;
};

/// The table's cushions and drop regions as the motion meets them, the pockets' throats and the playing surface's
/// half sizes.
struct MotionGeometry
{
  std::vector<NosePiece> noses;
  std::vector<std::string> cushion_ids;  ///< the cushion segments' ids, which the events name
  std::vector<DropRegion> drops;
  std::vector<Throat> throats;
  double half_length = 0.0;
  double half_width = 0.0;

  /// Whether a ball's centre at `point` is off the table: beyond the rectangle of the rails' noses and in no
  /// pocket's throat.
  bool offTable(const Eigen::Vector3d& point) const;
  /// The id of the cushion segment `piece` belongs to.
  const std::string& cushionId(const NosePiece& piece) const
  {
    return cushion_ids[static_cast<std::size_t>(piece.cushion)];
  }
};

/// The geometry of `table`'s pocket model: under Circles the four rails as infinite lines (numbered as railNoses,
/// named rail.left, rail.right, rail.bottom, rail.top) and the capture circles of Table::pockets; under Jaws
/// tableOutline's segments (its lines and arcs, with a point at each sharp corner that juts into the table and at each
/// free end of a facing) and its pockets' drop regions. Errors: tableOutline's.
Expected<MotionGeometry> motionGeometry(const Table& table);

}  // namespace detail
}  // namespace billiard_shot_planner
