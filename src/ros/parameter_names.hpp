#pragma once

// The node names a configuration field as a ROS parameter ("table/cloth/friction"); the core names it by its path
// in the configuration ("table.cloth.friction"). The translation lives here, at the ROS boundary.
#include <algorithm>
#include <string>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// "table.cloth.friction" → "table/cloth/friction".
inline std::string parameterName(std::string configuration_path)
{
  std::replace(configuration_path.begin(), configuration_path.end(), '.', '/');
  return configuration_path;
}

/// "table/cloth/friction" → "table.cloth.friction".
inline std::string configurationPath(std::string parameter_name)
{
  std::replace(parameter_name.begin(), parameter_name.end(), '/', '.');
  return parameter_name;
}

/// A configuration's error with its field named as the node's parameter.
inline Status namedAsParameter(Status status)
{
  if (status)
    return status;
  Error error = status.error();
  error.field = parameterName(error.field);
  return error;
}

}  // namespace billiard_shot_planner
