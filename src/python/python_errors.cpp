#include "python_errors.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

void registerErrors(py::module_& module)
{
  py::object error = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "billiard_shot_planner._core.Error",
      "A call refused its input or could not finish. `code` names the kind (invalid_argument, "
      "invalid_shot, time_limit_exceeded, ...), `field` the input at fault (may be empty).",
      PyExc_ValueError, nullptr));
  module.attr("Error") = error;
}

namespace
{
/// Text as a Python str whatever its bytes: a message may quote a file that is not UTF-8 (a YAML parser's error
/// echoes the bytes it stopped at), and the error must still be an Error, not a UnicodeDecodeError.
py::str text(const std::string& bytes)
{
  return py::reinterpret_steal<py::str>(
      PyUnicode_DecodeUTF8(bytes.data(), static_cast<Py_ssize_t>(bytes.size()), "replace"));
}
}  // namespace

py::object errorObject(const Error& error)
{
  py::object exception = py::module_::import("billiard_shot_planner._core").attr("Error")(text(error.describe()));
  exception.attr("code") = toString(error.code);
  exception.attr("field") = text(error.field);
  return exception;
}

void raise(const Error& error)
{
  py::object exception = errorObject(error);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(exception.ptr())), exception.ptr());
  throw py::error_already_set();
}

void check(const Status& status)
{
  if (!status)
    raise(status.error());
}

}  // namespace billiard_shot_planner::python
