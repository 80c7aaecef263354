#include "json_configuration.hpp"

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
  // The ball–ball contact is checked here, as a table shot's: the planner and the fits check the rest.
  if (auto contact = ballContactFromJson(request); !contact)
    return contact.error();
  ShotConfiguration c = configuration.value();
  c.solver = options;
  return c;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
