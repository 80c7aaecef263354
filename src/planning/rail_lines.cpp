#include "rail_lines.hpp"

namespace billiard_shot_planner
{
namespace planning
{
std::array<RailLine, 4> railLines(const Table& table, double radius)
{
  const double reach = cushionReach(table, radius);
  std::array<RailLine, 4> rails;
  for (std::size_t k = 0; k < rails.size(); ++k)
  {
    RailLine& rail = rails[k];
    rail.id = RAIL_IDS[k];
    rail.axis = static_cast<int>(k / 2);
    rail.side = k % 2 == 0 ? -1.0 : 1.0;
    rail.half = 0.5 * (rail.axis == 0 ? table.length : table.width);
    rail.line = rail.side * (rail.half - reach);
  }
  return rails;
}

}  // namespace planning
}  // namespace billiard_shot_planner
