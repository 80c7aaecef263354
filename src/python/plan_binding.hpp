#pragma once

#include <pybind11/pybind11.h>

namespace billiard_shot_planner::python
{
/// The planner: plan_shot() with its Noise and Limits, answering a Plan of PlannedShots.
void bindPlanning(pybind11::module_& module);

}  // namespace billiard_shot_planner::python
