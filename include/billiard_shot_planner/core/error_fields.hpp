#pragma once

// Reading the path an Error names ("shots[0].others[2].position"), for the front ends that map the core's names of
// a call's input into their own.
#include <cctype>
#include <cstddef>
#include <optional>
#include <string>

namespace billiard_shot_planner
{
/// An element of a list named at the start of a field: "<list>[<index>]<rest>".
struct IndexedField
{
  std::size_t index = 0;
  std::string rest;  ///< what follows the closing bracket (".position", or empty)
};

/// The element of `list` ("others") that `field` ("others[2].position") starts with; none when it names no element
/// of that list (another list, or no decimal index in the brackets).
inline std::optional<IndexedField> elementOf(const std::string& field, const std::string& list)
{
  const std::string open = list + "[";
  if (field.rfind(open, 0) != 0)
    return std::nullopt;
  const std::size_t close = field.find(']', open.size());
  if (close == std::string::npos || close == open.size() || close - open.size() > 9)
    return std::nullopt;
  std::size_t index = 0;
  for (std::size_t i = open.size(); i < close; ++i)
  {
    if (!std::isdigit(static_cast<unsigned char>(field[i])))
      return std::nullopt;
    index = index * 10 + static_cast<std::size_t>(field[i] - '0');
  }
  return IndexedField{index, field.substr(close + 1)};
}

/// What follows `name` in `field` when the field is `name` itself or lies under it ("cue.ball" in "cue.ball.x": ".x";
/// in "cue.ball": empty); none otherwise ("cue.balls" does not lie under "cue.ball").
inline std::optional<std::string> restUnder(const std::string& field, const std::string& name)
{
  if (field.rfind(name, 0) != 0)
    return std::nullopt;
  std::string rest = field.substr(name.size());
  if (!rest.empty() && rest.front() != '.' && rest.front() != '[')
    return std::nullopt;
  return rest;
}

}  // namespace billiard_shot_planner
