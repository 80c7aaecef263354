// masse_fit: fits the strike's unknown constants to the paper's measured massé shot (§9.2, state (56)) and prints
// how close the best fit comes — v and ω right after the strike, and the ball's path 1.5 s later beside the paths of
// (56) and of the paper's own prediction (57) — with the fitted values and their uncertainties
// (docs/validation.md, The massé shot fitted to its measurement).
//
//   masse_fit [starts]    (default 32 starting points per fit)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "billiard_shot_planner/calibration/strike_fit.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double R = 0.0286;
const Eigen::Vector2d BALL(0.0, 0.0);  // the centre of a table wide enough that no cushion is reached
constexpr double PATH_TIME = 1.5;

/// The paper's set-up with the corrected ball (docs/validation.md), its motion planar as the paper's.
bsp::ShotConfiguration paperConfiguration()
{
  bsp::ShotConfiguration c;
  c.cue_mass = 0.5018;
  c.cue_end_mass = bsp::CUE_HELD_ON_AXIS;
  c.ball_mass = 0.17;
  c.ball_radius = R;
  c.cue_contact = {0.656532, 0.7, 7.0};
  c.table.cloth = {0.51625, 0.152479, 10.0};
  c.stiffness_ratio = 0.8;
  c.table.length = 8.0;
  c.table.width = 8.0;
  c.table.pockets.clear();
  c.motion.sliding_friction = 0.152479;
  c.motion.rolling_friction = 0.0209727;
  c.motion.planar = true;
  return c;
}

/// The printed strike: the cue held on its axis at the hit normal n̂, along the literal ĉ, at 3.089095 m/s.
bsp::CuePlacement paperCue()
{
  const Eigen::Vector3d normal = Eigen::Vector3d(0.480151, -0.102889, 0.871131).normalized();
  bsp::CuePlacement cue;
  cue.ball = BALL;
  cue.tip = Eigen::Vector3d(BALL.x(), BALL.y(), R) + R * normal;
  cue.direction = Eigen::Vector3d(-0.2761, -0.1388, -0.9511).normalized();
  cue.speed = 3.089095;
  return cue;
}

/// The ball's planar position PATH_TIME after a strike that leaves it with (v, ω) in the plane.
Eigen::Vector2d positionAfter(const Eigen::Vector2d& v, const Eigen::Vector2d& w, const bsp::ShotConfiguration& c)
{
  bsp::BallState start;
  start.position = Eigen::Vector3d(BALL.x(), BALL.y(), R);
  start.velocity = Eigen::Vector3d(v.x(), v.y(), 0.0);
  start.angular_velocity = Eigen::Vector3d(w.x(), w.y(), 0.0);
  const auto path = bsp::predictTrajectory(start, {c.ball_mass, R}, c.table, c.motion);
  if (!path)
  {
    std::printf("path: %s\n", path.error().describe().c_str());
    std::exit(1);
  }
  return path->at(PATH_TIME).position.head<2>();
}

const Eigen::Vector2d MEASURED_V(-1.67063, -0.274431), MEASURED_W(28.4584, 79.1561);
const Eigen::Vector2d PREDICTED_V(-1.67629, -0.075349), PREDICTED_W(40.3064, 83.6145);

void printOutcome(const char* title, const std::vector<std::string>& names, const std::vector<double>& values,
                  const bsp::ShotConfiguration& base)
{
  bsp::ShotConfiguration c = base;
  bsp::CuePlacement cue = paperCue();
  if (bsp::Status status = bsp::applyFitted(names, values, c, cue); !status)
  {
    std::printf("%s: %s\n", title, status.error().describe().c_str());
    return;
  }
  const auto struck = bsp::strikeBall(cue, c);
  if (!struck)
  {
    std::printf("%s: %s\n", title, struck.error().describe().c_str());
    return;
  }
  const Eigen::Vector2d v = struck->velocity.head<2>(), w = struck->angular_velocity.head<2>();
  const Eigen::Vector2d measured = positionAfter(MEASURED_V, MEASURED_W, base);
  std::printf("%-28s v = (%8.4f, %8.4f)  ω = (%8.3f, %8.3f)  path at %.1f s off (56) by %.3f m  sequence", title, v.x(),
              v.y(), w.x(), w.y(), PATH_TIME, (positionAfter(v, w, base) - measured).norm());
  for (const std::string& state : struck->states)
    std::printf(" %s", state.c_str());
  std::printf("\n");
}

void fitAndPrint(const char* title, const std::vector<bsp::FitParameter>& parameters, int starts,
                 bool hold_undetermined = true)
{
  const bsp::ShotConfiguration base = paperConfiguration();
  bsp::ObservedStrike seen;
  seen.cue = paperCue();
  seen.velocity = MEASURED_V;
  seen.angular_velocity = MEASURED_W;
  seen.velocity_sigma = 0.05;
  seen.angular_velocity_sigma = 2.0;
  bsp::FitOptions options;
  options.starts = starts;
  if (!hold_undetermined)
    options.identifiable_relative_sigma = std::numeric_limits<double>::infinity();
  const auto fit = bsp::fitStrikes(base, parameters, {seen}, options);
  std::printf("\n== %s\n", title);
  if (!fit)
  {
    std::printf("refused: %s\n", fit.error().describe().c_str());
    return;
  }
  std::vector<std::string> names;
  std::vector<double> values;
  for (const bsp::FittedParameter& p : fit->parameters)
  {
    names.push_back(p.name);
    values.push_back(p.value);
    const bool angle = p.name == bsp::CUE_YAW || p.name == bsp::CUE_PITCH;
    const double unit = angle ? 180.0 / M_PI : 1.0;
    std::printf("  %-22s %10.4f ± %-10.4g%s%s%s\n", p.name.c_str(), p.value * unit, p.sigma * unit, angle ? " deg" : "",
                p.identifiable ? "" : "  (not identifiable: held at its start)", p.at_bound ? "  (at a bound)" : "");
  }
  std::printf("  χ² = %.4g over %d residuals (σ_v = 0.05 m/s, σ_ω = 2 rad/s assumed); %s\n", 2.0 * fit->final_cost,
              static_cast<int>(fit->residuals.size()), fit->message.c_str());
  printOutcome("fitted", names, values, base);
}
}  // namespace

int main(int argc, char** argv)
{
  const int starts = argc > 1 ? std::atoi(argv[1]) : 32;
  const bsp::ShotConfiguration base = paperConfiguration();
  std::printf("The paper's massé shot (§9.2) against its measurement (56): v = (%.5f, %.5f), ω = (%.4f, %.4f)\n",
              MEASURED_V.x(), MEASURED_V.y(), MEASURED_W.x(), MEASURED_W.y());
  const Eigen::Vector2d measured = positionAfter(MEASURED_V, MEASURED_W, base);
  std::printf("(56)'s path at %.1f s: (%.3f, %.3f) from the ball's start; (57)'s is off it by %.3f m\n", PATH_TIME,
              measured.x() - BALL.x(), measured.y() - BALL.y(),
              (positionAfter(PREDICTED_V, PREDICTED_W, base) - measured).norm());
  printOutcome("printed constants", {}, {}, base);

  const std::vector<bsp::FitParameter> constants = {{"cue_contact.eta2", 7.0, 0.5, 50.0},
                                                    {"table.cloth.eta2", 10.0, 0.5, 50.0},
                                                    {"stiffness_ratio", 0.8, 0.05, 20.0},
                                                    {"cue_contact.friction", 0.7, 0.1, 2.0}};
  fitAndPrint("Fit 1: η² of both contacts, the stiffness ratio and the tip's friction", constants, starts);
  fitAndPrint("Fit 1, every constant fitted however loosely the measurement holds it", constants, starts, false);
  const double five_degrees = 5.0 * M_PI / 180.0;
  const std::vector<bsp::FitParameter> direction = {{bsp::CUE_YAW, 0.0, -five_degrees, five_degrees},
                                                    {bsp::CUE_PITCH, 0.0, -five_degrees, five_degrees}};
  fitAndPrint("Fit 2: the cue's direction alone, within 5° of the printed one", direction, starts);
  std::vector<bsp::FitParameter> both = {constants[0], constants[1]};
  both.insert(both.end(), direction.begin(), direction.end());
  fitAndPrint("Fit 3: the cue's direction and η² of both contacts", both, starts);
  fitAndPrint("Fit 3, every parameter fitted however loosely the measurement holds it", both, starts, false);
  return 0;
}
