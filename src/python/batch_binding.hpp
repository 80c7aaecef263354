#pragma once

#include <pybind11/pybind11.h>

namespace billiard_shot_planner::python
{
/// Batches: simulate_many() and strike_many(), many strokes on one layout, spread over the machine's cores with the
/// GIL released.
void bindBatches(pybind11::module_& module);

}  // namespace billiard_shot_planner::python
