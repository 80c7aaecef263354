#include "billiard_shot_planner/motion/table.hpp"
#include <algorithm>
#include <cmath>
#include "billiard_shot_planner/motion/table_outline.hpp"

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
std::vector<Pocket> sixPockets(double length, double width)
{
  const double x = 0.5 * length, y = 0.5 * width;
  return {{{-x, -y}, 0.06}, {{x, -y}, 0.06}, {{-x, y}, 0.06}, {{x, y}, 0.06}, {{0.0, -y}, 0.065}, {{0.0, y}, 0.065}};
}

std::vector<Pocket> defaultPockets(const Table& table)
{
  return table.pocket_layout == PocketLayout::None ? std::vector<Pocket>{} : sixPockets(table.length, table.width);
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
  }
  // The cuts must also fit the table: jaws that leave a rail, facings that stay apart.
  if (auto outline = tableOutline(table, field); !outline)
    return outline.error();
  return {};
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

}  // namespace billiard_shot_planner
