#include "layout.hpp"

#include <pybind11/stl.h>

#include <cmath>

#include "billiard_shot_planner/core/error_fields.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "python_errors.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
/// Any sequence of `size` numbers; the error names `field` and says what was wanted.
std::vector<double> numbers(const py::handle& given, std::size_t size, const std::string& field, const char* what)
{
  std::vector<double> values;
  try
  {
    values = given.cast<std::vector<double>>();
  }
  catch (const py::cast_error&)
  {
    raise(invalidArgument(field, std::string("must be ") + what));
  }
  if (values.size() != size)
    raise(invalidArgument(field, std::string("must be ") + what + ", got " + std::to_string(values.size())));
  for (double value : values)
    if (!std::isfinite(value))
      raise(invalidArgument(field, "contains NaN or infinite values"));
  return values;
}
}  // namespace

std::vector<std::string> Layout::ids() const
{
  std::vector<std::string> all{CUE_BALL_ID};
  for (const TableBall& ball : balls)
    all.push_back(ball.id);
  return all;
}

py::array_t<double> arrayOf(const py::handle& given, int dims, const std::string& field, const std::string& what)
{
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try
  {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
  }
  catch (const py::error_already_set&)
  {
    array = {};
  }
  if (!array || array.ndim() != dims)
    raise(invalidArgument(field, what));
  return array;
}

Eigen::Vector2d point(const py::handle& given, const std::string& field)
{
  const std::vector<double> xy = numbers(given, 2, field, "two numbers (x, y) in m");
  return {xy[0], xy[1]};
}

Eigen::Vector3d vector3(const py::handle& given, const std::string& field)
{
  const std::vector<double> xyz = numbers(given, 3, field, "three numbers");
  return {xyz[0], xyz[1], xyz[2]};
}

std::vector<TableBall> tableBalls(const py::object& balls)
{
  std::vector<TableBall> table;
  if (balls.is_none())
    return table;
  if (!py::isinstance<py::dict>(balls))
    raise(invalidArgument("balls", "must be a dict of ball ids to (x, y) positions in m"));
  for (const auto& [key, value] : balls.cast<py::dict>())
  {
    const std::string id = py::str(key);
    TableBall ball{id, {}};
    ball.state.position.head<2>() = point(value, "balls['" + id + "']");
    table.push_back(ball);
  }
  return table;
}

Layout layoutOf(const py::handle& cue_ball, const py::object& balls)
{
  return {point(cue_ball, "cue_ball"), tableBalls(balls)};
}

Error inPythonTerms(Error error, const std::vector<TableBall>& others)
{
  if (const auto rest = restUnder(error.field, "cue.ball"))
    error.field = "cue_ball" + *rest;
  else if (const auto other = elementOf(error.field, "others"))
  {
    if (other->index < others.size())
      error.field = "balls['" + others[other->index].id + "']" + other->rest;
  }
  else
    error.field = parameterNameOfField(error.field);
  return error;
}

}  // namespace billiard_shot_planner::python
