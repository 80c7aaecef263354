#include "billiard_shot_planner/impact/laws/normal_law.hpp"

#include <utility>

namespace billiard_shot_planner
{
namespace
{
template <std::size_t... I>
std::vector<std::string> typesOf(std::index_sequence<I...> /*alternatives*/)
{
  return {std::variant_alternative_t<I, NormalLaw>::TYPE...};
}

template <std::size_t I = 0>
Expected<NormalLaw> defaultLawOfType(const std::string& type, const std::string& field)
{
  if constexpr (I == std::variant_size_v<NormalLaw>)
  {
    std::string known;
    for (const std::string& name : lawTypes())
      known += (known.empty() ? "" : ", ") + name;
    return invalidArgument(field + ".type", "unknown law \"" + type + "\" (the laws are: " + known + ")");
  }
  else
  {
    using Law = std::variant_alternative_t<I, NormalLaw>;
    if (type == Law::TYPE)
      return NormalLaw{Law{}};
    return defaultLawOfType<I + 1>(type, field);
  }
}

}  // namespace

const char* lawType(const NormalLaw& law)
{
  return std::visit([](const auto& alternative) { return std::decay_t<decltype(alternative)>::TYPE; }, law);
}

bool isLinear(const NormalLaw& law)
{
  return std::visit([](const auto& alternative) { return decltype(alternative.spring())::LINEAR; }, law);
}

std::vector<std::string> lawTypes()
{
  return typesOf(std::make_index_sequence<std::variant_size_v<NormalLaw>>{});
}

Expected<NormalLaw> lawOfType(const std::string& type, const std::string& field)
{
  return defaultLawOfType(type, field);
}

Status validate(const NormalLaw& law, const std::string& field)
{
  return std::visit([&](const auto& alternative) { return alternative.validate(field); }, law);
}

Status requireLawKey(const NormalLaw& law, const std::string& key, const std::string& field)
{
  bool known = key == "type";
  NormalLaw copy = law;
  visitLawParameters(copy, [&](const char* name, double& /*value*/) { known = known || key == name; });
  if (known)
    return {};
  std::string message = "is not a parameter of the law \"";
  message += lawType(law);
  message += '"';
  return invalidArgument(field + "." + key, message);
}

double restitutionOf(const NormalLaw& law, double low_speed_restitution, double impact_speed)
{
  return std::visit(
      [&](const auto& alternative) { return alternative.restitution(low_speed_restitution, impact_speed); }, law);
}

}  // namespace billiard_shot_planner
