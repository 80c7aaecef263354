#pragma once

// The node names a configuration field as a ROS parameter ("table/cloth/friction"); the core names it by its path
// in the configuration ("table.cloth.friction"). The translation lives here, at the ROS boundary.
#include <string>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace billiard_shot_planner
{
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
