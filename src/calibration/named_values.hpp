#pragma once

// The unknowns of a fit as named values of a model that lists them itself: `visit_values(model, visit)` calls
// visit(name, double&) for every value it has (the cushion rebound and rolling collision fits).
#include <string>
#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// Every name the model lists, in its order.
template <class Model, class VisitValues>
std::vector<std::string> namedValues(Model model, VisitValues&& visit_values)
{
  std::vector<std::string> names;
  visit_values(model, [&](const std::string& name, double& /*value*/) { names.push_back(name); });
  return names;
}

/// Sets the named values of `model`. Error: InvalidArgument naming the first name the model does not list, with
/// `unknown` as its message.
template <class Model, class VisitValues>
Status applyNamedValues(const std::vector<std::string>& names, const std::vector<double>& values, Model& model,
                        VisitValues&& visit_values, const char* unknown)
{
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    bool found = false;
    visit_values(model,
                 [&](const std::string& name, double& value)
                 {
                   if (name == names[i])
                   {
                     value = values[i];
                     found = true;
                   }
                 });
    if (!found)
      return invalidArgument(names[i], unknown);
  }
  return {};
}

/// "rebounds[3]": an element of a list, as errors name it.
inline std::string indexedField(const std::string& name, std::size_t i)
{
  return name + "[" + std::to_string(i) + "]";
}

/// The parameters' names and starts, in their order.
inline std::vector<std::string> parameterNames(const std::vector<FitParameter>& parameters)
{
  std::vector<std::string> names;
  names.reserve(parameters.size());
  for (const FitParameter& parameter : parameters)
    names.push_back(parameter.name);
  return names;
}

inline std::vector<double> parameterStarts(const std::vector<FitParameter>& parameters)
{
  std::vector<double> starts;
  starts.reserve(parameters.size());
  for (const FitParameter& parameter : parameters)
    starts.push_back(parameter.start);
  return starts;
}

}  // namespace billiard_shot_planner
