#include "request_fields.hpp"

#include <string>
#include <utility>

#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
bool startsWith(const std::string& text, const std::string& prefix)
{
  return text.rfind(prefix, 0) == 0;
}

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

/// "others[k]…": the k-th other ball's entry in the table, or the field as it is when k is not one.
std::string otherBallField(const std::string& field, const std::vector<std::size_t>& origins)
{
  const std::size_t close = field.find(']');
  if (close == std::string::npos)
    return field;
  const std::size_t k = std::stoul(field.substr(7, close - 7));
  return k < origins.size() ? tableBall(origins[k]) + field.substr(close + 1) : field;
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
  if (startsWith(error.field, "cue.ball"))
    error.field = cueBallField(error.field.substr(8), origins.cue_ball);
  else if (startsWith(error.field, "others["))
    error.field = otherBallField(error.field, origins.others);
  else
    error.field = parameterNameOfField(error.field);
  return error;
}

}  // namespace billiard_shot_planner
