// A stroke as the JSON problems take it: "cue": {"phi_deg", "theta_deg", "speed", "a", "b", "convention"}.
#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/planning/stroke_conventions.hpp"
#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
namespace
{
constexpr double DEGREE = M_PI / 180.0;
}  // namespace

Expected<Stroke> strokeFromJson(const json& cue, const std::string& prefix, double ball_radius)
{
  if (Status known = onlyKnownKeys(cue, {"phi_deg", "theta_deg", "speed", "a", "b", "convention"}, prefix); !known)
    return known.error();
  double phi = 0.0, theta = 0.0, speed = 0.0, a = 0.0, b = 0.0;
  if (Status status = firstError({readNumbers(cue, {{"phi_deg", &phi}, {"speed", &speed}}, prefix, Presence::Required),
                                  readNumbers(cue, {{"theta_deg", &theta}, {"a", &a}, {"b", &b}}, prefix)});
      !status)
    return status.error();
  const std::string convention = cue.contains("convention") && cue.at("convention").is_string()
                                     ? cue.at("convention").get<std::string>()
                                     : (cue.contains("convention") ? "?" : "");
  if (convention == "pooltool")
    return fromPooltool({speed, phi, theta, a, b});
  if (convention == "fastfiz")
    return fromFastFiz({a, b, theta, phi, speed}, ball_radius);
  if (!convention.empty())
    return invalidArgument(prefix + ".convention",
                           "must be \"pooltool\" or \"fastfiz\" (absent: this package's, docs/stroke_conventions.md)");
  return Stroke{phi * DEGREE, theta * DEGREE, speed, a, b};
}

}  // namespace json_io
}  // namespace billiard_shot_planner
