#pragma once

#include <pybind11/pybind11.h>

namespace billiard_shot_planner::python
{
/// Strokes, their conventions, the strike and the whole shot: Stroke, from_pooltool/to_pooltool,
/// from_fastfiz/to_fastfiz, strike(), predict_shot() and the results (Strike, Shot, BallPath, Event).
void bindShots(pybind11::module_& module);

}  // namespace billiard_shot_planner::python
