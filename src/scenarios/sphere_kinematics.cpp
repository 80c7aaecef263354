#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
Status validate(const SurfaceContact& surface, const std::string& field)
{
  return firstError({requireUnitInterval(surface.restitution, field + ".restitution"),
                     requireNonNegative(surface.friction, field + ".friction"),
                     requirePositive(surface.eta2, field + ".eta2"), validate(surface.normal_law, field + ".law")});
}

}  // namespace billiard_shot_planner
