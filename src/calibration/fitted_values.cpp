#include "fitted_values.hpp"

#include <algorithm>

namespace billiard_shot_planner
{
bool isOwn(const std::string& name, const std::vector<std::string>& own)
{
  return std::find(own.begin(), own.end(), name) != own.end();
}

Expected<std::vector<std::string>> checkedNames(const ShotConfiguration& configuration,
                                                const std::vector<FitParameter>& parameters,
                                                const std::vector<std::string>& own)
{
  std::vector<std::string> names;
  for (const FitParameter& parameter : parameters)
  {
    names.push_back(parameter.name);
    ShotConfiguration trial = configuration;
    if (isOwn(parameter.name, own))
      continue;
    if (Status status = applyOverride(trial, parameter.name, parameter.start); !status)
      return status.error();
  }
  return names;
}

Status applyValues(ShotConfiguration& configuration, const std::vector<std::string>& names,
                   const std::vector<double>& values, const std::vector<std::string>& own)
{
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!isOwn(names[i], own))
      if (Status status = applyOverride(configuration, names[i], values[i]); !status)
        return status;
  return {};
}

}  // namespace billiard_shot_planner
