#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "billiard_shot_planner/motion/table_outline.hpp"
#include "plan_context.hpp"

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
/// Where the line from `from` along unit `axis` meets the rectangle of the rails' lines (the table's playing surface).
Eigen::Vector2d onTheRails(const Eigen::Vector2d& from, const Eigen::Vector2d& axis, const Table& table)
{
  const double half[2] = {0.5 * table.length, 0.5 * table.width};
  double along = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k)
    if (std::abs(axis(k)) > 1e-12)
      along = std::min(along, std::max(0.0, (half[k] - std::abs(from(k))) / std::abs(axis(k))));
  Eigen::Vector2d place = from + (std::isfinite(along) ? along : 0.0) * axis;
  // Exactly on the rails' lines where it reached them, so that "the pocket is on this cushion" holds there.
  for (int k = 0; k < 2; ++k)
    if (std::abs(std::abs(place(k)) - half[k]) < 1e-9)
      place(k) = std::copysign(half[k], place(k));
  return place;
}
}  // namespace

Expected<std::vector<PocketTarget>> pocketTargets(const Table& table, double ball_radius)
{
  std::vector<PocketTarget> targets;
  if (table.pocket_model == PocketModel::Circles)
  {
    for (std::size_t i = 0; i < table.pockets.size(); ++i)
      targets.push_back({pocketId(table.pockets, i),
                         table.pockets[i].centre,
                         table.pockets[i].radius,
                         table.pockets[i].centre,
                         {},
                         0.0,
                         Eigen::Vector2d::Zero()});
    return targets;
  }
  auto outline = tableOutline(table);
  if (!outline)
    return outline.error();
  const double reach = cushionReach(table, ball_radius);
  for (const PocketOpening& opening : outline.value().pockets)
  {
    PocketTarget target{opening.id,
                        opening.mouthMiddle(),
                        std::max(0.5 * opening.mouth() - reach, 0.0),
                        onTheRails(opening.mouthMiddle(), opening.axis, table),
                        outline.value().jawsOf(opening.id),
                        reach,
                        opening.axis};
    targets.push_back(std::move(target));
  }
  return targets;
}

int indexOf(const std::vector<PocketTarget>& pockets, const std::string& id)
{
  for (std::size_t i = 0; i < pockets.size(); ++i)
    if (pockets[i].id == id)
      return static_cast<int>(i);
  return -1;
}

}  // namespace planning
}  // namespace billiard_shot_planner
