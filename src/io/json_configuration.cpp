#include "json_configuration.hpp"

#include "billiard_shot_planner/core/validation.hpp"
#include "json_configuration_reader.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
Expected<ShotConfiguration> configurationOf(const json& request, const SolverOptions& options)
{
  auto configuration = requestConfiguration(request);
  if (!configuration)
    return configuration.error();
  ShotConfiguration c = configuration.value();
  // The ball–ball contact is checked here, as a table shot's: the planner and the fits check the rest.
  if (Status status =
          firstError({validate(c.ball_contact.ball_ball, "ball_ball"),
                      requireStiffnessRatio(c.ball_contact.stiffness_ratio, "ball_ball.cloth_stiffness_ratio")});
      !status)
    return status.error();
  c.solver = options;
  return c;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
