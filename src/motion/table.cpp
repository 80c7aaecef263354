#include "billiard_shot_planner/motion/table.hpp"
#include <algorithm>
#include <cmath>
#include <utility>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
std::vector<Pocket> sixPockets(double length, double width)
{
  const double x = 0.5 * length, y = 0.5 * width;
  return {{{-x, -y}, 0.06, "bottom_left"}, {{x, -y}, 0.06, "bottom_right"},   {{-x, y}, 0.06, "top_left"},
          {{x, y}, 0.06, "top_right"},     {{0.0, -y}, 0.065, "bottom_side"}, {{0.0, y}, 0.065, "top_side"}};
}

int pocketIndex(const std::vector<Pocket>& pockets, const std::string& id)
{
  for (std::size_t i = 0; i < pockets.size(); ++i)
    if (pocketId(pockets, i) == id)
      return static_cast<int>(i);
  return -1;
}

std::string pocketId(const std::vector<Pocket>& pockets, std::size_t index)
{
  return pockets[index].id.empty() ? "pocket" + std::to_string(index) : pockets[index].id;
}

std::vector<Pocket> defaultPockets(const Table& table)
{
  return table.pocket_layout == PocketLayout::None ? std::vector<Pocket>{} : sixPockets(table.length, table.width);
}

bool sameDefaultPockets(const Table& a, const Table& b)
{
  return a.length == b.length && a.width == b.width && a.pocket_layout == b.pocket_layout;
}

double cushionReach(const Table& table, double radius)
{
  const double sin_theta = std::clamp((table.cushion_height - radius) / radius, -1.0, 1.0);
  return radius * std::sqrt(1.0 - sin_theta * sin_theta);
}

Status validate(const PocketCut& cut, const std::string& field)
{
  return firstError({requirePositive(cut.mouth, field + ".mouth"),
                     requireWithin(cut.facing_angle, 90.0, 180.0, field + ".facing_angle",
                                   "degrees between the cushion's nose and its facing"),
                     requireNonNegative(cut.shelf, field + ".shelf"),
                     requireNonNegative(cut.jaw_radius, field + ".jaw_radius"),
                     requirePositive(cut.drop_radius, field + ".drop_radius")});
}

namespace
{
/// The cut of one kind of pocket against its own facings. `axis_to_rail`: the angle between the pocket's axis and its
/// rails (45 deg at a corner, 90 at a side). Each facing leaves its rail at 180 deg − facing_angle and so closes in on
/// the axis by `closing`; at the drop region's middle, `depth` behind the mouth, the facings stand
/// mouth/2 − depth tan(closing) from the axis, and a jaw's rounding takes `tangent` of its facing's depth/cos(closing).
Status validateFacings(const PocketCut& cut, double axis_to_rail, const std::string& field)
{
  const double cut_angle = cut.cutAngle();
  const double closing = axis_to_rail - (M_PI - cut_angle);
  const double depth = cut.shelf + cut.drop_radius;
  if (!(0.5 * cut.mouth - depth * std::tan(closing) > 0.0))
    return invalidArgument(field + ".facing_angle", "makes the pockets' facings meet before the slate's cut (at " +
                                                        formatNumber(depth) + " m behind the mouth)");
  if (!(cut.jaw_radius / std::tan(0.5 * cut_angle) < depth / std::cos(closing)))
    return invalidArgument(field + ".jaw_radius", "is too large for the pockets' facings");
  return {};
}

/// Whether the pockets' cuts fit the table: facings that stay apart, jaws that leave a rail between two pockets (a
/// corner's jaw points stand mouth/sqrt(2) from the corner, a side's mouth/2 from the rail's middle; each rounding
/// takes jaw_radius/tan(facing_angle/2) more of the rail).
Status validatePocketFit(const Table& table, const std::string& field)
{
  if (table.pocket_layout == PocketLayout::None)
  {
    if (!table.pockets.empty())
      return invalidArgument(field + ".pockets", "must be empty on a table without pockets (pocket_layout \"none\")");
    return {};
  }
  const PocketCut &corner = table.corner_pockets, &side = table.side_pockets;
  if (Status status = firstError({validateFacings(corner, 0.25 * M_PI, field + ".corner_pockets"),
                                  validateFacings(side, 0.5 * M_PI, field + ".side_pockets")});
      !status)
    return status;
  const double corner_jaw = corner.mouth / std::sqrt(2.0) + corner.jaw_radius / std::tan(0.5 * corner.cutAngle());
  const double side_jaw = 0.5 * side.mouth + side.jaw_radius / std::tan(0.5 * side.cutAngle());
  if (!(0.5 * table.length - corner_jaw - side_jaw > 0.0))
    return invalidArgument(field + ".side_pockets.mouth",
                           "leaves no cushion on the long rails between the corner and side pockets' jaws");
  if (!(table.width - 2.0 * corner_jaw > 0.0))
    return invalidArgument(field + ".corner_pockets.mouth",
                           "leaves no cushion on the short rails between the corner pockets' jaws");
  return {};
}
}  // namespace

Status validate(const Table& table, const std::string& field)
{
  if (Status status =
          firstError({requirePositive(table.length, field + ".length"), requirePositive(table.width, field + ".width"),
                      requirePositive(table.cushion_height, field + ".cushion_height"),
                      validate(table.cloth, field + ".cloth"), validate(table.cushion, field + ".cushion"),
                      requireStiffnessRatio(table.cushion_stiffness_ratio, field + ".cushion_stiffness_ratio"),
                      validate(table.corner_pockets, field + ".corner_pockets"),
                      validate(table.side_pockets, field + ".side_pockets")});
      !status)
    return status;
  for (std::size_t i = 0; i < table.pockets.size(); ++i)
  {
    const std::string name = field + ".pockets[" + std::to_string(i) + "]";
    if (Status status = firstError({requireFinite(table.pockets[i].centre, name + ".centre"),
                                    requirePositive(table.pockets[i].radius, name + ".radius")});
        !status)
      return status;
    for (std::size_t j = 0; j < i; ++j)
    {
      if (pocketId(table.pockets, j) == pocketId(table.pockets, i))
        return invalidArgument(name + ".id", "\"" + pocketId(table.pockets, i) + "\" names pocket " +
                                                 std::to_string(j) + " too: each pocket needs its own id");
      // A ball's centre in both circles would drop into whichever the search met first.
      if ((table.pockets[i].centre - table.pockets[j].centre).norm() <
          table.pockets[i].radius + table.pockets[j].radius)
        return invalidArgument(name + ".centre", "overlaps pocket " + pocketId(table.pockets, j) +
                                                     "'s capture region: pockets' capture regions must not overlap");
    }
  }
  return validatePocketFit(table, field);
}

Status validateCushionHeight(double cushion_height, double ball_radius, const std::string& field)
{
  const double lowest = MIN_CUSHION_HEIGHT * ball_radius;
  if (!(cushion_height >= lowest))
    return invalidArgument(field,
                           "must be at least (1 - 1/sqrt(2)) = 0.293 of the ball's radius (" + std::to_string(lowest) +
                               " m): a lower nose cannot turn back a ball rolling straight into it, whatever its "
                               "restitution, and sends it over the cushion");
  if (!(cushion_height < 2.0 * ball_radius))
    return invalidArgument(field, "must be below the ball's diameter (" + std::to_string(2.0 * ball_radius) + " m)");
  return {};
}

Status validateForBall(const Table& table, double ball_radius, const std::string& field)
{
  if (Status status = validateCushionHeight(table.cushion_height, ball_radius, field + ".cushion_height"); !status)
    return status;
  if (table.pocket_layout == PocketLayout::None)
    return {};
  for (const auto& [cut, name] :
       {std::pair{&table.corner_pockets, ".corner_pockets"}, {&table.side_pockets, ".side_pockets"}})
    if (!(cut->mouth > 2.0 * ball_radius))
      return invalidArgument(
          field + name + ".mouth",
          "must be wider than a ball (" + std::to_string(2.0 * ball_radius) + " m): no ball could drop through it");
  return {};
}

}  // namespace billiard_shot_planner
