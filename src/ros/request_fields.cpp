#include "request_fields.hpp"

#include <string>
#include <utility>

#include "billiard_shot_planner/core/error_fields.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
std::string tableBall(std::size_t index)
{
  return "table.balls[" + std::to_string(index) + "]";
}

/// "cue.ball…": the cue ball's place, from the table or from ball_position.
std::string cueBallField(const std::string& rest, const std::optional<std::size_t>& index)
{
  if (index)
    return tableBall(*index) + (rest.empty() ? ".position" : rest);
  return "ball_position" + rest;
}

}  // namespace

Error inRequestTerms(Error error, const BallOrigins& origins)
{
  static const std::pair<const char*, const char*> cue_fields[] = {{"cue.tip", "cue_pose.position"},
                                                                   {"cue.direction", "cue_pose.orientation"},
                                                                   {"cue.speed", "cue_speed"},
                                                                   {"cue", "cue_pose"}};
  for (const auto& [core, request] : cue_fields)
    if (error.field == core)
    {
      error.field = request;
      return error;
    }
  if (const auto rest = restUnder(error.field, "cue.ball"))
    error.field = cueBallField(*rest, origins.cue_ball);
  else if (const auto other = elementOf(error.field, "others"))
  {
    if (other->index < origins.others.size())
      error.field = tableBall(origins.others[other->index]) + other->rest;
  }
  else
    error.field = parameterNameOfField(error.field);
  return error;
}

}  // namespace billiard_shot_planner
