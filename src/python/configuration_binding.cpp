#include "configuration_binding.hpp"

#include <pybind11/stl.h>

#include <algorithm>

#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "python_errors.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
/// The parameter `name` ("cue_contact/friction") of `configuration`, or nullptr.
double* findParameter(ShotConfiguration& configuration, const std::string& name)
{
  for (const NamedParameter& parameter : numericParameters(configuration))
    if (parameterName(parameter.name) == name)
      return parameter.value;
  return nullptr;
}

double get(ShotConfiguration& configuration, const std::string& name)
{
  const double* value = findParameter(configuration, name);
  if (!value)
    raise(invalidArgument(name, "is not a numeric parameter (Configuration.names() lists them)"));
  return *value;
}

void set(ShotConfiguration& configuration, const std::string& name, double value)
{
  std::string path = name;
  std::replace(path.begin(), path.end(), '/', '.');
  if (Status status = applyOverride(configuration, path, value); !status)
  {
    Error error = status.error();
    error.field = parameterName(error.field);
    raise(error);
  }
}

std::vector<std::string> names(ShotConfiguration& configuration)
{
  std::vector<std::string> all;
  for (const NamedParameter& parameter : numericParameters(configuration))
    all.push_back(parameterName(parameter.name));
  return all;
}
}  // namespace

void bindConfiguration(py::module_& module)
{
  py::class_<ShotConfiguration>(
      module, "Configuration",
      R"(Everything physical about a shot but the cue's pose and speed: the cue, the ball, the table and the
motion model. Configuration() has the ROS node's defaults (config/default.yaml). Its numeric parameters are read
and set by the node's parameter names, config["cue_contact/restitution"]; a value the model refuses raises Error
naming the parameter and leaves the configuration as it was.)")
      .def(py::init<>())
      .def("__getitem__", &get, py::arg("name"))
      .def("__setitem__", &set, py::arg("name"), py::arg("value"))
      .def("__contains__",
           [](ShotConfiguration& c, const std::string& name) { return findParameter(c, name) != nullptr; })
      .def("names", &names, "The numeric parameters' names, as the ROS node's parameters.")
      .def("copy", [](const ShotConfiguration& c) { return c; })
      .def("__copy__", [](const ShotConfiguration& c) { return c; })
      .def(
          "__deepcopy__", [](const ShotConfiguration& c, const py::dict& /*memo*/) { return c; }, py::arg("memo"))
      // Pickled as its numeric parameters by name: every choice a Python caller can make is one of them (the
      // contact laws' kinds are the defaults'), so a configuration sent to another process (Dask) arrives whole.
      .def(py::pickle(
          [](ShotConfiguration& c)
          {
            py::dict state;
            for (const NamedParameter& parameter : numericParameters(c))
              state[py::str(parameterName(parameter.name))] = *parameter.value;
            return state;
          },
          [](const py::dict& state)
          {
            ShotConfiguration c;
            for (const auto& [name, value] : state)
              set(c, py::str(name), value.cast<double>());
            return c;
          }))
      .def("__repr__", [](ShotConfiguration& c)
           { return "<Configuration of " + std::to_string(numericParameters(c).size()) + " numeric parameters>"; });
}

}  // namespace billiard_shot_planner::python
