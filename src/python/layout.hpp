#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "billiard_shot_planner/motion/table_simulation.hpp"

namespace billiard_shot_planner::python
{
/// The balls of a call as Python gives them: the cue ball's (x, y) and the others by id (in the dict's order).
struct Layout
{
  Eigen::Vector2d cue_ball = Eigen::Vector2d::Zero();
  std::vector<TableBall> balls;
  /// The balls' ids in the order of the answers: the cue ball first.
  std::vector<std::string> ids() const;
};

/// A float64 array of `dims` dimensions from anything numpy takes (C order); otherwise Error naming `field`, saying
/// `what` it must be.
pybind11::array_t<double> arrayOf(const pybind11::handle& given, int dims, const std::string& field,
                                  const std::string& what);
/// A point on the cloth from any two numbers; the error names `field`.
Eigen::Vector2d point(const pybind11::handle& given, const std::string& field);
/// A vector from any three numbers; the error names `field`.
Eigen::Vector3d vector3(const pybind11::handle& given, const std::string& field);
/// None, or a dict of ball ids to (x, y); errors name "balls" or "balls['<id>']".
std::vector<TableBall> tableBalls(const pybind11::object& balls);
Layout layoutOf(const pybind11::handle& cue_ball, const pybind11::object& balls);

/// A core error of a strike or a shot in the Python call's names: the cue ball ("cue.ball") as "cue_ball", the other
/// balls ("others[1].position") by their ids ("balls['two']"), a configuration's field as its parameter
/// ("table/cloth/friction"); the cue's own fields keep the core's names ("cue.tip", "cue").
Error inPythonTerms(Error error, const std::vector<TableBall>& others);

}  // namespace billiard_shot_planner::python
