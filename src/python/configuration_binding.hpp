#pragma once

#include <pybind11/pybind11.h>

namespace billiard_shot_planner::python
{
/// billiard_shot_planner.Configuration: ShotConfiguration with its parameters by the node's names.
void bindConfiguration(pybind11::module_& module);

}  // namespace billiard_shot_planner::python
