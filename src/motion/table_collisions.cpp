#include "table_collisions.hpp"

namespace billiard_shot_planner
{
namespace detail
{
Expected<std::vector<BallState>> resolveBallImpact(const std::vector<BallState>& /*touching*/, const Ball& /*ball*/,
                                                   const Table& /*table*/, const BallContactSettings& /*contact*/,
                                                   const SolverOptions& /*options*/)
{
  return Error{ErrorCode::InvalidArgument, "balls", "ball–ball impacts are not available yet"};
}
}  // namespace detail
}  // namespace billiard_shot_planner
