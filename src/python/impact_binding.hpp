#pragma once

#include <pybind11/pybind11.h>

namespace billiard_shot_planner::python
{
/// multiple_impact and ImpactResult: the engine itself, a multiple impact from a mass matrix, velocities and contacts.
void bindImpacts(pybind11::module_& module);

}  // namespace billiard_shot_planner::python
