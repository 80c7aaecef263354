#pragma once

#include <pybind11/pybind11.h>

namespace billiard_shot_planner::python
{
/// fit_tracks and FitResult: the node's calibration (the configuration fitted to tracked shots) from Python.
void bindFits(pybind11::module_& module);

}  // namespace billiard_shot_planner::python
