#include "impact_binding.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"
#include "layout.hpp"
#include "python_errors.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
/// The engine's result as Python sees it: arrays and plain lists.
struct ImpactAnswer
{
  Eigen::VectorXd velocity;
  Eigen::VectorXd normal_impulses;
  Eigen::MatrixX2d tangential_impulses;
  std::vector<int> ends_of_compression;
  std::vector<bool> initially_slipping;
  std::vector<std::vector<std::string>> states;                      ///< each state's active contacts by name
  std::vector<std::tuple<std::string, std::string, double>> events;  ///< (type, contact, normalised time)
  double initial_kinetic_energy = 0.0;
  double final_kinetic_energy = 0.0;
  bool converged = false;
};

ImpactAnswer answerOf(const ImpactResult& result, const std::vector<Contact>& contacts)
{
  ImpactAnswer answer;
  answer.velocity = result.velocity;
  const auto n = static_cast<Eigen::Index>(result.impulses.size());
  answer.normal_impulses.resize(n);
  answer.tangential_impulses.resize(n, 2);
  for (Eigen::Index k = 0; k < n; ++k)
  {
    answer.normal_impulses(k) = result.impulses[static_cast<std::size_t>(k)].normal;
    answer.tangential_impulses.row(k) = result.impulses[static_cast<std::size_t>(k)].tangential.transpose();
  }
  answer.ends_of_compression = result.ends_of_compression;
  answer.initially_slipping = result.initially_slipping;
  for (const ImpactState& state : result.states)
  {
    std::vector<std::string> active;
    for (std::size_t k : state.active)
      active.push_back(contacts[k].name);
    answer.states.push_back(active);
  }
  for (const ContactEvent& event : result.events)
    answer.events.emplace_back(toString(event.type), contacts[event.contact].name, event.at.time);
  answer.initial_kinetic_energy = result.initial_kinetic_energy;
  answer.final_kinetic_energy = result.final_kinetic_energy;
  answer.converged = result.converged;
  return answer;
}

Eigen::MatrixXd matrixOf(const py::handle& given, const std::string& field, const char* what)
{
  const py::array_t<double> array = arrayOf(given, 2, field, what);
  const auto m = array.unchecked<2>();
  Eigen::MatrixXd matrix(m.shape(0), m.shape(1));
  for (py::ssize_t i = 0; i < m.shape(0); ++i)
    for (py::ssize_t j = 0; j < m.shape(1); ++j)
      matrix(i, j) = m(i, j);
  return matrix;
}

Eigen::VectorXd vectorOf(const py::handle& given, const std::string& field, const char* what)
{
  const py::array_t<double> array = arrayOf(given, 1, field, what);
  const auto v = array.unchecked<1>();
  Eigen::VectorXd vector(v.shape(0));
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    vector(i) = v(i);
  return vector;
}

double numberOf(const py::dict& fields, const char* key, double fallback, const std::string& field)
{
  if (!fields.contains(key))
    return fallback;
  const py::object value = fields[key];
  if (py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value))
    raise(invalidArgument(field + "." + key, "must be a number"));
  try
  {
    return value.cast<double>();
  }
  catch (const py::cast_error&)
  {
    raise(invalidArgument(field + "." + key, "must be a number"));
  }
}

/// "normal_law": {"type": "elastic_plastic", "yield_speed": 1.2}, or absent for the constant law.
NormalLaw normalLawOf(const py::dict& fields, const std::string& field)
{
  if (!fields.contains("normal_law"))
    return {};
  if (!py::isinstance<py::dict>(fields["normal_law"]))
    raise(invalidArgument(field + ".normal_law", "must be a dict {\"type\": <name>, <parameters>}"));
  const auto given = fields["normal_law"].cast<py::dict>();
  const std::string law_field = field + ".normal_law";
  if (!given.contains("type") || !py::isinstance<py::str>(given["type"]))
    raise(invalidArgument(law_field + ".type", "is required: " + std::to_string(lawTypes().size()) + " types"));
  NormalLaw law = valueOf(lawOfType(given["type"].cast<std::string>(), law_field));
  for (const auto& [key, value] : given)
    check(requireLawKey(law, py::str(key), law_field));
  visitLawParameters(law, [&](const char* name, double& value) { value = numberOf(given, name, value, law_field); });
  return law;
}

const char* const CONTACT_KEYS[] = {"name",      "normal",   "tangent", "restitution",
                                    "stiffness", "friction", "eta2",    "normal_law"};

Contact contactOf(const py::handle& given, std::size_t i, Eigen::Index dofs)
{
  const std::string field = "contacts[" + std::to_string(i) + "]";
  if (!py::isinstance<py::dict>(given))
    raise(invalidArgument(field, "must be a dict with \"normal\" and the law's constants"));
  const py::dict fields = py::reinterpret_borrow<py::dict>(given);
  for (const auto& [key, value] : fields)
  {
    std::string name = py::str(key);
    if (std::none_of(std::begin(CONTACT_KEYS), std::end(CONTACT_KEYS),
                     [&](const char* known) { return name == known; }))
      raise(invalidArgument(name.insert(0, field + "."),
                            "is not a field of a contact (name, normal, tangent, restitution, "
                            "stiffness, friction, eta2, normal_law)"));
  }
  Contact contact;
  contact.name = fields.contains("name") ? std::string(py::str(fields["name"])) : "contact" + std::to_string(i);
  if (!fields.contains("normal"))
    raise(invalidArgument(field + ".normal", "is required: the row of the normal relative velocity"));
  contact.normal = vectorOf(fields["normal"], field + ".normal", "must be a 1-D array").transpose();
  contact.law.restitution = numberOf(fields, "restitution", contact.law.restitution, field);
  contact.law.stiffness = numberOf(fields, "stiffness", contact.law.stiffness, field);
  contact.law.friction = numberOf(fields, "friction", contact.law.friction, field);
  contact.law.eta2 = numberOf(fields, "eta2", contact.law.eta2, field);
  contact.law.normal_law = normalLawOf(fields, field);
  if (fields.contains("tangent"))
  {
    const Eigen::MatrixXd tangent = matrixOf(fields["tangent"], field + ".tangent", "must be a (2, d) array");
    if (tangent.rows() != 2 || tangent.cols() != dofs)
      raise(invalidArgument(field + ".tangent", "must be a (2, d) array, d the mass matrix's size"));
    contact.tangent = tangent;
  }
  else if (contact.law.friction > 0.0)
    raise(invalidArgument(field + ".tangent", "is required when friction > 0: the rows (t1, t2)"));
  return contact;
}

/// The core's names of a contact's law ("contacts[1].law.restitution") as the contact's dict names them.
Error inCallTerms(Error error)
{
  const std::size_t at = error.field.find("].law.");
  if (error.field.rfind("contacts[", 0) == 0 && at != std::string::npos)
    error.field.erase(at + 1, 4);
  return error;
}

ImpactAnswer multipleImpact(const py::handle& mass_matrix, const py::handle& velocity, const py::list& contacts,
                            double relative_tolerance, double absolute_tolerance, double max_seconds)
{
  ImpactProblem problem;
  problem.mass_matrix = matrixOf(mass_matrix, "mass_matrix", "must be a (d, d) array");
  problem.velocity = vectorOf(velocity, "velocity", "must be a 1-D array");
  for (std::size_t i = 0; i < contacts.size(); ++i)
    problem.contacts.push_back(contactOf(contacts[i], i, problem.mass_matrix.rows()));
  SolverOptions options;
  options.relative_tolerance = relative_tolerance;
  options.absolute_tolerance = absolute_tolerance;
  options.max_seconds = max_seconds;
  Expected<ImpactResult> result = Error{};
  {
    py::gil_scoped_release release;
    result = solveMultipleImpact(problem, options);
  }
  if (!result)
    raise(inCallTerms(result.error()));
  return answerOf(result.value(), problem.contacts);
}
}  // namespace

void bindImpacts(py::module_& module)
{
  py::class_<ImpactAnswer>(module, "ImpactResult", "A multiple impact's outcome (the engine's ImpactResult).")
      .def_readonly("velocity", &ImpactAnswer::velocity, "The generalised velocity after the impact.")
      .def_readonly("normal_impulses", &ImpactAnswer::normal_impulses, "(n,): each contact's, on its body A.")
      .def_readonly("tangential_impulses", &ImpactAnswer::tangential_impulses, "(n, 2): along each contact's t1, t2.")
      .def_readonly("ends_of_compression", &ImpactAnswer::ends_of_compression)
      .def_readonly("initially_slipping", &ImpactAnswer::initially_slipping)
      .def_readonly("states", &ImpactAnswer::states,
                    "The state transition diagram's sequence: each state's active contacts by name, the last empty.")
      .def_readonly("events", &ImpactAnswer::events,
                    "Every contact event: (type, contact, time in the solver's normalised unit).")
      .def_readonly("initial_kinetic_energy", &ImpactAnswer::initial_kinetic_energy)
      .def_readonly("final_kinetic_energy", &ImpactAnswer::final_kinetic_energy)
      .def_readonly("converged", &ImpactAnswer::converged,
                    "A contact chattered and the answer is the sequence's limit.");

  module.def("multiple_impact", &multipleImpact, py::arg("mass_matrix"), py::arg("velocity"), py::arg("contacts"),
             py::arg("relative_tolerance") = 1e-12, py::arg("absolute_tolerance") = 1e-14,
             py::arg("max_seconds") = 10.0,
             R"(The engine itself: one simultaneous multiple impact of a system with generalised velocity u (d entries),
its (d, d) mass matrix and its contacts, each a dict: "normal" (d,): the row giving the contact's normal relative
velocity (negative: approach), "tangent" (2, d) when it has friction, "restitution" (energetic e, default 1),
"stiffness" (default 1; only ratios matter), "friction" (Coulomb mu, default 0), "eta2" (normal over tangential
stiffness, default 1), "normal_law" ({"type": "elastic_plastic", "yield_speed": ...}; default constant) and a
"name". Errors name the field ("contacts[1].restitution", "mass_matrix"). The GIL is released while it solves.)");
}

}  // namespace billiard_shot_planner::python
