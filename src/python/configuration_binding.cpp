#include "configuration_binding.hpp"

#include <pybind11/stl.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "billiard_shot_planner/io/parameter_file.hpp"
#include "billiard_shot_planner/motion/table_outline.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "python_errors.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
/// The parameter files' top-level keys that are the node's own settings, not the configuration's
/// (config/default.yaml): Configuration.load passes over them.
const std::set<std::string> NODE_SETTINGS{"target_frame", "tf_timeout",       "sample_spacing", "table_state_timeout",
                                          "threads",      "calibration",      "planning",       "cockpit",
                                          "tuning",       "diagnostic_period"};

py::list pocketList(const std::vector<Pocket>& pockets)
{
  py::list list;
  for (std::size_t i = 0; i < pockets.size(); ++i)
    list.append(py::make_tuple(pockets[i].centre.x(), pockets[i].centre.y(), pockets[i].radius, pocketId(pockets, i)));
  return list;
}

/// One pocket from (x, y, radius) or (x, y, radius, id); py::cast_error for anything else.
Pocket pocketOf(const py::tuple& item)
{
  if (item.size() != 3 && item.size() != 4)
    throw py::cast_error("a pocket has 3 or 4 items");
  Pocket pocket{{item[0].cast<double>(), item[1].cast<double>()}, item[2].cast<double>(), ""};
  if (item.size() == 4)
    pocket.id = item[3].cast<std::string>();
  return pocket;
}

/// Writes every field into a dict by its parameter name, in the walk's order: numbers as float, flags as bool,
/// choices as str, the pockets as a list of (x, y, radius, id).
class DictWriter final : public ConfigurationVisitor
{
public:
  void number(const std::string& path, double& value) override { fields[py::str(parameterName(path))] = value; }
  void flag(const std::string& path, bool& value) override { fields[py::str(parameterName(path))] = value; }
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& /*options*/) override
  {
    fields[py::str(parameterName(path))] = value;
  }
  void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& /*table*/) override
  {
    fields[py::str(parameterName(path))] = pocketList(pockets);
  }

  py::dict fields;
};

/// Sets the fields a dict names (by parameter name), checking each value's type; remembers which it used.
class DictReader final : public ConfigurationVisitor
{
public:
  explicit DictReader(const py::dict& fields) : fields_(fields) {}

  void number(const std::string& path, double& value) override
  {
    const py::object given = take(path);
    if (!given)
      return;
    if (!py::isinstance<py::bool_>(given) && !py::isinstance<py::str>(given))
    {
      try
      {
        value = given.cast<double>();
        return;
      }
      catch (const py::cast_error&)
      {
      }
    }
    fail(invalidArgument(parameterName(path), "must be a number"));
  }
  void flag(const std::string& path, bool& value) override
  {
    if (const py::object given = take(path))
    {
      if (py::isinstance<py::bool_>(given))
        value = given.cast<bool>();
      else
        fail(invalidArgument(parameterName(path), "must be True or False"));
    }
  }
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& /*options*/) override
  {
    if (const py::object given = take(path))
    {
      if (py::isinstance<py::str>(given))
        value = given.cast<std::string>();
      else
        fail(invalidArgument(parameterName(path), "must be a str"));
    }
  }
  void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& /*table*/) override
  {
    const py::object given = take(path);
    if (!given)
      return;
    try
    {
      std::vector<Pocket> read;
      for (const py::handle item : given.cast<py::list>())
        read.push_back(pocketOf(item.cast<py::tuple>()));
      pockets = read;
    }
    catch (const py::cast_error&)
    {
      fail(invalidArgument(parameterName(path), "must be a list of (x, y, radius) or (x, y, radius, id)"));
    }
  }
  /// The first key of the dict that no field has.
  Status everyKeyUsed() const
  {
    for (const auto& [key, value] : fields_)
      if (!used_.count(py::str(key)))
        return invalidArgument(py::str(key),
                               "is not a parameter of the configuration (Configuration.names(), "
                               "Configuration.choices())");
    return {};
  }

private:
  py::object take(const std::string& path)
  {
    const std::string name = parameterName(path);
    if (!fields_.contains(name))
      return {};
    used_.insert(name);
    return fields_[py::str(name)];
  }
  py::dict fields_;
  std::set<std::string> used_;
};

/// The value, or its error raised with the field named as the parameter ("table/cloth/friction").
template <class T>
T valueAsParameters(Expected<T> expected)
{
  if (expected)
    return std::move(expected.value());
  Error error = expected.error();
  error.field = parameterName(error.field);
  raise(error);
}

/// The configuration with the dict's fields set, all or none: an error names the parameter.
ShotConfiguration updated(const ShotConfiguration& configuration, const py::dict& fields)
{
  ShotConfiguration changed = configuration;
  DictReader reader(fields);
  Status status = visitConfiguration(changed, reader);
  if (status)
    status = reader.everyKeyUsed();
  if (status)
    status = validate(changed);
  if (!status)
  {
    Error error = status.error();
    error.field = parameterName(error.field);
    raise(error);
  }
  return changed;
}

py::tuple pair(const Eigen::Vector2d& v)
{
  return py::make_tuple(v.x(), v.y());
}

/// The table's outline (docs/tables.md) as plain values: cushions and pockets by id.
py::dict outlineOf(const ShotConfiguration& configuration)
{
  const TableOutline outline = valueOf(tableOutline(configuration.table));
  py::list cushions, pockets;
  for (const NoseSegment& segment : outline.cushions)
  {
    py::dict s;
    s["id"] = segment.id;
    s["shape"] = segment.shape == NoseSegment::Shape::Arc ? "arc" : "line";
    s["start"] = pair(segment.start);
    s["end"] = pair(segment.end);
    if (segment.shape == NoseSegment::Shape::Arc)
    {
      s["centre"] = pair(segment.centre);
      s["radius"] = segment.radius;
      s["sweep"] = segment.sweep;
    }
    cushions.append(s);
  }
  for (const PocketOpening& pocket : outline.pockets)
  {
    py::dict p;
    p["id"] = pocket.id;
    p["jaw_in"] = pair(pocket.jaw_in);
    p["jaw_out"] = pair(pocket.jaw_out);
    p["mouth"] = pocket.mouth();
    p["axis"] = pair(pocket.axis);
    p["drop_centre"] = pair(pocket.drop_centre);
    p["drop_radius"] = pocket.drop_radius;
    pockets.append(p);
  }
  py::dict result;
  result["cushions"] = cushions;
  result["pockets"] = pockets;
  return result;
}

py::dict fieldsOf(ShotConfiguration configuration)
{
  DictWriter writer;
  (void)visitConfiguration(configuration, writer);  // a writer changes no choice: the walk cannot fail
  return writer.fields;
}

py::object get(const ShotConfiguration& configuration, const std::string& name)
{
  py::dict fields = fieldsOf(configuration);
  if (!fields.contains(name))
    raise(invalidArgument(name,
                          "is not a parameter of the configuration (Configuration.names(), "
                          "Configuration.choices())"));
  return fields[py::str(name)];
}

std::vector<std::string> numericNames(ShotConfiguration configuration)
{
  std::vector<std::string> all;
  for (const NamedParameter& parameter : numericParameters(configuration))
    all.push_back(parameterName(parameter.name));
  return all;
}

py::dict choices(const ShotConfiguration& configuration)
{
  py::dict all;
  for (const NamedChoice& choice : configurationChoices(configuration))
    all[py::str(parameterName(choice.name))] = choice.options;
  return all;
}

/// Parameter files read in turn, each over the last, from the defaults.
ShotConfiguration load(const py::args& paths)
{
  ShotConfiguration configuration;
  for (const py::handle& path : paths)
  {
    const std::string file = py::str(path);
    ParameterFile read = valueAsParameters(loadParameterFile(file, configuration));
    for (const std::string& key : read.other_keys)
      if (!NODE_SETTINGS.count(key))
        raise(invalidArgument(key,
                              "is neither a parameter of the configuration nor a setting of the node (" + file + ")"));
    configuration = read.configuration;
  }
  return configuration;
}
}  // namespace

void bindConfiguration(py::module_& module)
{
  py::class_<ShotConfiguration>(
      module, "Configuration",
      R"(Everything physical about a shot but the cue's pose and speed: the cue, the ball, the table and the
motion model. Configuration() has the ROS node's defaults (config/default.yaml). Its fields are read and set by
the node's parameter names: numbers (config["cue_contact/restitution"] = 0.7), flags (config["motion/planar"] =
True), choices (config["table/cushion/law/type"] = "elastic_plastic", then its "table/cushion/law/yield_speed")
and the pockets (config["table/pockets"] = [(x, y, radius, id), ...], the id optional). A value the model refuses raises Error naming
the parameter and leaves the configuration as it was.)")
      .def(py::init<>())
      .def_static("load", &load,
                  R"(The defaults with the node's parameter files read over them in turn (config/default.yaml,
config/paper_masse.yaml, config/cues/hand_held.yaml, ...). The node's own settings in them (target_frame,
planning/..., cockpit/...) are passed over; any other unknown key raises Error naming it.)")
      .def(
          "with_table_file",
          [](const ShotConfiguration& c, const std::string& path)
          { return withTableFile(c, valueAsParameters(loadTableFile(path))); },
          py::arg("path"),
          R"(A copy with a table file's table, balls, ball-ball contact and motion (config/tables/*.yaml), as
impact_solve's "table_file".)")
      .def("__getitem__", &get, py::arg("name"))
      .def(
          "__setitem__",
          [](ShotConfiguration& c, const std::string& name, const py::object& value)
          {
            py::dict fields;
            fields[py::str(name)] = value;
            c = updated(c, fields);
          },
          py::arg("name"), py::arg("value"))
      .def(
          "update", [](ShotConfiguration& c, const py::dict& fields) { c = updated(c, fields); }, py::arg("fields"),
          "Sets several fields at once, all or none (a law's type and its parameters together).")
      .def("to_dict", &fieldsOf, "Every field by its parameter name: numbers, flags, choices and the pockets.")
      .def("__contains__",
           [](const ShotConfiguration& c, const std::string& name) { return fieldsOf(c).contains(name); })
      .def("names", &numericNames, "The numeric parameters' names, as the ROS node's parameters.")
      .def("table_outline", &outlineOf,
           R"(The table's cushions and pockets as its size and pockets' cut lay them out (docs/tables.md):
{"cushions": [{"id", "shape" ("line" or "arc"), "start", "end", and for an arc "centre", "radius", "sweep"}],
"pockets": [{"id", "jaw_in", "jaw_out", "mouth", "axis", "drop_centre", "drop_radius"}]}, in m and rad, the
table frame.)")
      .def("choices", &choices, "Each choice and flag by name, with the values it takes.")
      .def("copy", [](const ShotConfiguration& c) { return c; })
      .def("__copy__", [](const ShotConfiguration& c) { return c; })
      .def(
          "__deepcopy__", [](const ShotConfiguration& c, const py::dict& /*memo*/) { return c; }, py::arg("memo"))
      // Pickled as every field by name (to_dict): a configuration sent to another process (Dask) arrives whole.
      .def(py::pickle([](const ShotConfiguration& c) { return fieldsOf(c); },
                      [](const py::dict& fields) { return updated(ShotConfiguration{}, fields); }))
      .def("__repr__", [](ShotConfiguration& c)
           { return "<Configuration of " + std::to_string(numericParameters(c).size()) + " numeric parameters>"; });
}

}  // namespace billiard_shot_planner::python
