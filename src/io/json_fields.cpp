#include "json_fields.hpp"

#include "billiard_shot_planner/shot/configuration_fields.hpp"

#include <algorithm>

namespace billiard_shot_planner
{
namespace json_io
{
Expected<double> number(const json& object, const std::string& key, std::optional<double> fallback)
{
  if (!object.contains(key))
  {
    if (fallback)
      return *fallback;
    return invalidArgument(key, "is required");
  }
  const json& value = object.at(key);
  if (!value.is_number())
    return invalidArgument(key, "must be a number");
  return value.get<double>();
}

Expected<std::vector<double>> numbers(const json& object, const std::string& key)
{
  if (!object.contains(key))
    return invalidArgument(key, "is required");
  const json& value = object.at(key);
  if (!value.is_array())
    return invalidArgument(key, "must be an array of numbers");
  std::vector<double> out;
  for (const json& item : value)
  {
    if (!item.is_number())
      return invalidArgument(key, "must be an array of numbers");
    out.push_back(item.get<double>());
  }
  return out;
}

Expected<SolverOptions> solverOptions(const json& request)
{
  SolverOptions options;
  if (!request.contains("solver"))
    return options;
  const json& solver = request.at("solver");
  if (!solver.is_object())
    return invalidArgument("solver", "must be an object");
  for (auto [key, target] :
       {std::pair{"relative_tolerance", &options.relative_tolerance},
        std::pair{"absolute_tolerance", &options.absolute_tolerance}, std::pair{"max_seconds", &options.max_seconds}})
  {
    auto value = number(solver, key, *target);
    if (!value)
      return invalidArgument(std::string("solver.") + key, value.error().message);
    *target = value.value();
  }
  // Ranges: validate(SolverOptions), which names the field ("solver.absolute_tolerance").
  if (Status status = validate(options, "solver"); !status)
    return status.error();
  auto max_events = number(solver, "max_events", static_cast<double>(options.max_events));
  if (!max_events || !(max_events.value() >= 1.0 && max_events.value() <= 1e9))
    return invalidArgument("solver.max_events", "must be a number in [1, 1e9]");
  options.max_events = static_cast<std::size_t>(max_events.value());
  if (solver.contains("record_samples"))
  {
    if (!solver.at("record_samples").is_boolean())
      return invalidArgument("solver.record_samples", "must be true or false");
    options.record_samples = solver.at("record_samples").get<bool>();
  }
  return options;
}

std::vector<double> toVector(const Eigen::VectorXd& v)
{
  return std::vector<double>(v.data(), v.data() + v.size());
}

Expected<Eigen::Vector3d> vector3(const json& object, const std::string& key, std::optional<Eigen::Vector3d> fallback)
{
  if (!object.contains(key))
  {
    if (fallback)
      return *fallback;
    return invalidArgument(key, "is required");
  }
  auto values = numbers(object, key);
  if (!values)
    return values.error();
  if (values.value().size() != 3)
    return invalidArgument(key, "must be [x, y, z]");
  return Eigen::Vector3d(values.value()[0], values.value()[1], values.value()[2]);
}

Expected<json> object(const json& parent, const std::string& key, bool required)
{
  if (!parent.contains(key))
  {
    if (required)
      return invalidArgument(key, "is required");
    return json::object();
  }
  if (!parent.at(key).is_object())
    return invalidArgument(key, "must be an object");
  return parent.at(key);
}

Status readNumbers(const json& object, std::initializer_list<std::pair<const char*, double*>> fields,
                   const std::string& prefix, Presence presence)
{
  for (auto [name, target] : fields)
  {
    auto value = number(object, name, presence == Presence::Optional ? std::optional<double>(*target) : std::nullopt);
    if (!value)
      return prefix.empty() ? value.error() : nested(prefix, value.error());
    *target = value.value();
  }
  return {};
}

Expected<TableFile> tableFile(const json& request)
{
  if (!request.at("table_file").is_string())
    return invalidArgument("table_file", "must be a path");
  return loadTableFile(request.at("table_file").get<std::string>());
}

Expected<NormalLaw> normalLawFromJson(const json& law, const std::string& prefix, const NormalLaw& base)
{
  if (!law.is_object())
    return invalidArgument(prefix, "must be an object {\"type\": ..., <parameters>}");
  NormalLaw result = base;
  if (law.contains("type"))
  {
    if (!law.at("type").is_string())
      return invalidArgument(prefix + ".type", "must be a string naming the law");
    // Another type starts from its own defaults; the same type keeps the parameters it has, as the configuration's
    // readers do (visitConfiguration).
    if (law.at("type").get<std::string>() != lawType(base))
    {
      auto chosen = lawOfType(law.at("type").get<std::string>(), prefix);
      if (!chosen)
        return chosen.error();
      result = chosen.value();
    }
  }
  Status status;
  visitLawParameters(result,
                     [&](const char* name, double& value)
                     {
                       if (status)
                         status = readNumbers(law, {{name, &value}}, prefix);
                     });
  if (!status)
    return status.error();
  for (const auto& item : law.items())
    if (Status key = requireLawKey(result, item.key(), prefix); !key)
      return unknownField(prefix + "." + item.key(), "a parameter of the law");
  if (Status valid = validate(result, prefix); !valid)
    return valid.error();
  return result;
}

json normalLawJson(NormalLaw law)
{
  json out{{"type", lawType(law)}};
  visitLawParameters(law, [&](const char* name, double& value) { out[name] = value; });
  return out;
}

Status onlyKnownKeys(const json& object, std::initializer_list<const char*> known, const std::string& prefix,
                     std::initializer_list<const char*> also_known)
{
  const auto listed = [](std::initializer_list<const char*> names, const std::string& key)
  { return std::any_of(names.begin(), names.end(), [&](const char* name) { return key == name; }); };
  for (const auto& item : object.items())
    if (!listed(known, item.key()) && !listed(also_known, item.key()))
      return invalidArgument(prefix.empty() ? item.key() : prefix + "." + item.key(), "is not a field here");
  return {};
}

Status readSurfaceContact(const json& fields, const std::string& prefix, SurfaceContact& surface, Presence presence,
                          std::initializer_list<const char*> also_known)
{
  if (Status known = onlyKnownKeys(fields, {"restitution", "friction", "eta2", "law"}, prefix, also_known); !known)
    return known;
  if (Status numbers = readNumbers(
          fields, {{"restitution", &surface.restitution}, {"friction", &surface.friction}, {"eta2", &surface.eta2}},
          prefix, presence);
      !numbers)
    return numbers;
  if (!fields.contains("law"))
    return {};
  auto law = normalLawFromJson(fields.at("law"), prefix + ".law", surface.normal_law);
  if (!law)
    return law.error();
  surface.normal_law = law.value();
  return {};
}

Status checkFrictionModel(const json& ball_ball)
{
  if (!ball_ball.is_object() || !ball_ball.contains("friction_model"))
    return {};
  const json& model = ball_ball.at("friction_model");
  const bool friction = ball_ball.contains("friction");
  if ((model == "alciatore" && !friction) || (model == "constant" && friction))
    return {};
  return invalidArgument("ball_ball.friction_model",
                         "must be \"alciatore\" (without friction) or \"constant\" (with friction)");
}

Error nested(const std::string& prefix, Error error)
{
  error.field = error.field.empty() ? prefix : prefix + "." + error.field;
  return error;
}

json snapshotJson(const ImpactSnapshot& snap)
{
  return json{{"time", snap.time},
              {"impulses", toVector(snap.normal_impulses)},
              {"velocities", toVector(snap.velocity)},
              {"strain_energies", toVector(snap.strain_energies)},
              {"total_energy", snap.total_energy()}};
}

/// The parts of a result that every problem reports the same way.
json commonResultJson(const ImpactResult& result, const std::vector<std::string>& contact_names)
{
  json events = json::array();
  for (const ContactEvent& event : result.events)
  {
    json e = snapshotJson(event.at);
    e["type"] = toString(event.type);
    e["contact"] = event.contact;
    if (event.contact < contact_names.size())
      e["contact_name"] = contact_names[event.contact];
    events.push_back(e);
  }
  json out{{"ends_of_compression", result.ends_of_compression},
           {"converged", result.converged},
           {"events", events},
           {"energy",
            {{"initial", result.initial_kinetic_energy},
             {"final", result.final_kinetic_energy},
             {"lost", result.initial_kinetic_energy - result.final_kinetic_energy}}}};
  if (!result.samples.empty())
  {
    json samples = json::array();
    for (const ImpactSnapshot& snap : result.samples)
      samples.push_back(snapshotJson(snap));
    out["samples"] = samples;
  }
  return out;
}

}  // namespace json_io
}  // namespace billiard_shot_planner
