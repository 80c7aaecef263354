#include "fit_binding.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "billiard_shot_planner/calibration/fit_parameter_bounds.hpp"
#include "billiard_shot_planner/calibration/track_fit.hpp"
#include "billiard_shot_planner/core/error_fields.hpp"
#include "billiard_shot_planner/io/calibration_overlay.hpp"
#include "billiard_shot_planner/planning/stroke.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "layout.hpp"
#include "python_errors.hpp"

namespace billiard_shot_planner::python
{
namespace py = pybind11;

namespace
{
/// A shot's "stroke" (a Stroke) or "cue" (a Cue), at its "cue_ball"; errors name `field`.
CuePlacement executedCue(const py::dict& shot, const ShotConfiguration& configuration, const std::string& field)
{
  const py::object given = shot.contains("cue_ball") ? py::object(shot["cue_ball"]) : py::object(py::none());
  const Eigen::Vector2d cue_ball = point(given, field + "cue_ball");
  if (shot.contains("stroke") == shot.contains("cue"))
    raise(invalidArgument(field + "stroke", "give the shot a \"stroke\" (a Stroke) or a \"cue\" (a Cue), not both"));
  try
  {
    if (shot.contains("stroke"))
      return valueOf(placeStroke(shot["stroke"].cast<Stroke>(), cue_ball, configuration.ball_radius));
    CuePlacement cue = shot["cue"].cast<CuePlacement>();
    cue.ball = cue_ball;
    return cue;
  }
  catch (const py::cast_error&)
  {
    raise(invalidArgument(field + (shot.contains("stroke") ? "stroke" : "cue"), "must be a Stroke or a Cue"));
  }
}

/// A track as an (N, 3) array of t, x, y; errors name `field`.
std::vector<TrackPoint> trackOf(const py::handle& given, const std::string& field)
{
  const char* const what = "must be an array of shape (N, 3): t, x, y";
  const py::array_t<double> array = arrayOf(given, 2, field, what);
  if (array.shape(1) != 3)
    raise(invalidArgument(field, what));
  std::vector<TrackPoint> track;
  auto rows = array.unchecked<2>();
  for (py::ssize_t i = 0; i < rows.shape(0); ++i)
    track.push_back({rows(i, 0), {rows(i, 1), rows(i, 2)}});
  return track;
}

/// One observed shot from its dict: "stroke" or "cue", "cue_ball", "balls", "tracks" ({id: (N, 3) array}).
ObservedShot observedShot(const py::handle& given, const ShotConfiguration& configuration, const std::string& field)
{
  if (!py::isinstance<py::dict>(given))
    raise(invalidArgument(field, "must be a dict with \"stroke\" or \"cue\", \"cue_ball\", \"balls\", \"tracks\""));
  const py::dict shot = py::reinterpret_borrow<py::dict>(given);
  for (const auto& [key, value] : shot)
  {
    const std::string name = py::str(key);
    if (name != "stroke" && name != "cue" && name != "cue_ball" && name != "balls" && name != "tracks")
      raise(invalidArgument(field + name, "is not a field of an observed shot (stroke, cue, cue_ball, balls, tracks)"));
  }
  ObservedShot observed;
  observed.cue = executedCue(shot, configuration, field);
  observed.others = tableBalls(shot.contains("balls") ? py::object(shot["balls"]) : py::object(py::none()));
  if (!shot.contains("tracks") || !py::isinstance<py::dict>(shot["tracks"]))
    raise(invalidArgument(field + "tracks", "must be a dict of ball ids to (N, 3) arrays of t, x, y"));
  for (const auto& [id, track] : py::reinterpret_borrow<py::dict>(shot["tracks"]))
  {
    const std::string name = py::str(id);
    std::string track_field = field;
    track_field += "tracks." + name;
    observed.tracks[name] = trackOf(track, track_field);
  }
  return observed;
}

/// A fit's error in the call's names: a shot's input as that shot's dict names it ("shots[0].balls['two']"), a
/// parameter as the parameters are named.
Error inCallTerms(Error error, const std::vector<ObservedShot>& shots)
{
  const auto shot = elementOf(error.field, "shots");
  if (!shot || shot->rest.size() < 2 || shot->rest.front() != '.')
    return inPythonTerms(error, {});
  if (shot->index >= shots.size())
    return error;
  error.field = shot->rest.substr(1);
  error = inPythonTerms(error, shots[shot->index].others);
  error.field = "shots[" + std::to_string(shot->index) + "]." + error.field;
  return error;
}

FitOptions fitOptions(int starts, double max_seconds, int threads, double robust_loss_sigmas)
{
  FitOptions options;
  options.starts = starts;
  options.max_seconds = max_seconds;
  options.threads = threads;
  options.robust_loss_sigmas = robust_loss_sigmas;
  if (Status status = validate(options); !status)
    raise(status.error());  // the core's names are the keyword arguments'
  return options;
}

/// The fit's parameter names with their error named as the caller's ("table/cushion/restitution").
TrackFit fitTracksFromPython(const py::list& shots, const std::vector<std::string>& parameters,
                             const ShotConfiguration& configuration, double position_sigma, int starts,
                             double max_seconds, int threads, double robust_loss_sigmas)
{
  std::vector<FitParameter> unknowns;
  for (std::size_t i = 0; i < parameters.size(); ++i)
    unknowns.push_back(valueOf(
        fitParameterFor(configuration, configurationPath(parameters[i]), "parameters[" + std::to_string(i) + "]")));
  std::vector<ObservedShot> observed;
  for (std::size_t i = 0; i < shots.size(); ++i)
    observed.push_back(observedShot(shots[i], configuration, "shots[" + std::to_string(i) + "]."));
  const FitOptions options = fitOptions(starts, max_seconds, threads, robust_loss_sigmas);
  Expected<TrackFit> fit = Error{};
  {
    py::gil_scoped_release release;
    fit = fitTracks(configuration, unknowns, observed, position_sigma, options);
  }
  if (!fit)
    raise(inCallTerms(fit.error(), observed));
  for (FittedParameter& parameter : fit.value().fit.parameters)
    parameter.name = parameterName(parameter.name);
  return fit.value();
}
}  // namespace

void bindFits(py::module_& module)
{
  py::class_<FittedParameter>(module, "FittedParameter", "One fitted constant with its standard deviation.")
      .def_readonly("name", &FittedParameter::name)
      .def_readonly("value", &FittedParameter::value)
      .def_readonly("sigma", &FittedParameter::sigma,
                    "From the fit's curvature (scaled by sqrt(chi2/dof) when the fit does not explain the data); "
                    "inf when not identifiable.")
      .def_readonly("identifiable", &FittedParameter::identifiable)
      .def_readonly("at_bound", &FittedParameter::at_bound)
      .def("__repr__",
           [](const FittedParameter& p) {
             return "<FittedParameter " + p.name + " = " + std::to_string(p.value) + " ± " + std::to_string(p.sigma) +
                    ">";
           });

  py::class_<FitResult>(module, "FitResult", "A least-squares fit: the constants, their spread and how well they fit.")
      .def_readonly("parameters", &FitResult::parameters)
      .def_readonly("correlation", &FitResult::correlation)
      .def_readonly("residuals", &FitResult::residuals, "At the best point, in standard deviations.")
      .def_readonly("initial_cost", &FitResult::initial_cost)
      .def_readonly("final_cost", &FitResult::final_cost)
      .def_readonly("degrees_of_freedom", &FitResult::degrees_of_freedom)
      .def_readonly("chi2_per_dof", &FitResult::chi2_per_dof)
      .def_readonly("explains_data", &FitResult::explains_data)
      .def_readonly("converged", &FitResult::converged)
      .def_readonly("message", &FitResult::message)
      .def_readonly("iterations", &FitResult::iterations)
      .def_property_readonly(
          "values",
          [](const FitResult& fit)
          {
            py::dict values;
            for (const FittedParameter& p : fit.parameters)
              values[py::str(p.name)] = p.value;
            return values;
          },
          "The fitted values by name.")
      .def(
          "overlay_yaml",
          [](FitResult fit, const std::string& origin)
          {
            for (FittedParameter& p : fit.parameters)
              p.name = configurationPath(p.name);
            return calibrationOverlayYaml(fit, origin);
          },
          py::arg("origin") = "fitted from Python",
          "The identifiable constants as a parameter file for the node (and Configuration.load).");

  py::class_<TrackFit>(module, "TrackFit")
      .def_readonly("fit", &TrackFit::fit)
      .def_readonly("shot_rms", &TrackFit::shot_rms, "Per shot, the RMS distance of the tracks from the fit, m.");

  module.def("fit_tracks", &fitTracksFromPython, py::arg("shots"), py::arg("parameters"),
             py::arg("configuration") = ShotConfiguration{}, py::arg("position_sigma") = 0.005, py::arg("starts") = 1,
             py::arg("max_seconds") = 60.0, py::arg("threads") = 1, py::arg("robust_loss_sigmas") = 0.0,
             R"(Fits the named parameters of the configuration ("motion/sliding_friction", "table/cushion/restitution")
to the tracks of executed shots, as the node's ~fit_calibration does: each shot a dict with "stroke" (a Stroke) or
"cue" (a Cue), "cue_ball" (x, y), "balls" ({id: (x, y)}) and "tracks" ({id: array (N, 3) of t, x, y}; "cue" is the
cue ball). position_sigma (m) is a track point's standard deviation. The GIL is released while it fits.)");
}

}  // namespace billiard_shot_planner::python
