// The compiled part of the Python package billiard_shot_planner (src/billiard_shot_planner/__init__.py imports it):
// bindings of the ROS-free core with pybind11. docs/python.md says what it offers.
#include <pybind11/pybind11.h>

#include "batch_binding.hpp"
#include "configuration_binding.hpp"
#include "fit_binding.hpp"
#include "impact_binding.hpp"
#include "plan_binding.hpp"
#include "python_errors.hpp"
#include "shot_binding.hpp"

PYBIND11_MODULE(_core, module)
{
  module.doc() = "billiard_shot_planner's core: strikes and shots by the integrated multiple-impact model.";
  billiard_shot_planner::python::registerErrors(module);
  billiard_shot_planner::python::bindConfiguration(module);
  billiard_shot_planner::python::bindShots(module);
  billiard_shot_planner::python::bindBatches(module);
  billiard_shot_planner::python::bindPlanning(module);
  billiard_shot_planner::python::bindFits(module);
  billiard_shot_planner::python::bindImpacts(module);
}
