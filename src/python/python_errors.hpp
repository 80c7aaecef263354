#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner::python
{
/// Registers billiard_shot_planner.Error, a ValueError whose `code` ("invalid_argument", "invalid_shot", …) and
/// `field` (the core's path, "cue_contact/friction" in the parameters' names) say what went wrong where.
void registerErrors(pybind11::module_& module);

/// The core's error as a billiard_shot_planner.Error object (not raised: a batch's rows carry theirs).
pybind11::object errorObject(const Error& error);

/// Raises the core's error as billiard_shot_planner.Error.
[[noreturn]] void raise(const Error& error);

/// The value, or the error raised.
template <class T>
T valueOf(Expected<T> expected)
{
  if (!expected)
    raise(expected.error());
  return std::move(expected.value());
}

/// Nothing, or the error raised.
void check(const Status& status);

}  // namespace billiard_shot_planner::python
