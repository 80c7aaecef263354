#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "billiard_shot_planner/planning/stroke.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// Gaussian execution noise of a robot's stroke, one standard deviation per stroke parameter. Defaults: FastFiz's
/// noise at level 1 (σ_φ = 0.125°, σ_θ = 0.1°, σ_V = 0.075 m/s, σ_a = σ_b = 0.5 mm).
struct ExecutionNoise
{
  double phi = 0.125 * M_PI / 180.0;  ///< rad
  double theta = 0.1 * M_PI / 180.0;  ///< rad
  double speed = 0.075;               ///< m/s
  double a = 0.5e-3;                  ///< m, of the hit point across the cue
  double b = 0.5e-3;                  ///< m, of the hit point up
};

/// The stroke a robot plays when it means `nominal`: independent Gaussian errors of the noise's σ, in the order φ,
/// θ, V, a, b (the offsets' σ in metres, turned into radii of a ball of `radius`). `random`: a standard engine.
template <class Random>
Stroke noisyStroke(const Stroke& nominal, const ExecutionNoise& noise, double radius, Random& random)
{
  std::normal_distribution<double> gauss(0.0, 1.0);
  Stroke stroke = nominal;
  stroke.phi += noise.phi * gauss(random);
  stroke.theta += noise.theta * gauss(random);
  stroke.speed += noise.speed * gauss(random);
  stroke.a += noise.a / radius * gauss(random);
  stroke.b += noise.b / radius * gauss(random);
  return stroke;
}

/// What the robot can do. The cue is a cylinder behind the tip that must touch no other ball and pass above the
/// rails where it crosses them.
struct RobotLimits
{
  double min_theta = 0.0;                ///< rad, the lowest cue elevation
  double max_theta = 30.0 * M_PI / 180;  ///< rad
  double min_speed = 0.5;                ///< m/s, of the cue
  double max_speed = 6.0;                ///< m/s
  double max_offset = 0.5;               ///< ball radii: the largest tip offset √(a² + b²) before a miscue
  double cue_length = 1.0;               ///< m of cue behind the tip that must be clear
  double cue_radius = 0.0065;            ///< m (a 13 mm shaft)
  double rail_height = 0.045;            ///< m above the cloth: the rails' top, which the cue must pass above
};

/// A circle on the cloth where the cue ball should come to rest (position play).
struct CueRegion
{
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.1;  ///< m
};

/// Game rules a pot must also satisfy.
struct PlanRules
{
  bool target_first = false;  ///< the cue ball's first contact must be the target
  bool only_target = false;   ///< no ball but the target may drop
};

/// How far a plan has come, for a caller that reports progress.
struct PlanProgress
{
  int evaluations = 0;            ///< shots simulated so far
  int shots_that_pot = 0;         ///< refined shots that pot without noise
  double best_probability = 0.0;  ///< the best pot probability estimated so far
};

/// Optional calls out of a running plan: `progress` after each refined candidate and each round of rollouts, and
/// `stop`, asked as often, which ends the plan early with the best found so far (a preempted action goal).
struct PlanHooks
{
  std::function<void(const PlanProgress&)> progress;
  std::function<bool()> stop;
};

/// What to plan: a pot means that the target drops (in `pocket`, when one is named) and the cue ball does not (and
/// the cue ball stops in `cue_region`, when one is given, and the rules hold).
struct PlanRequest
{
  std::vector<TableBall> balls;  ///< every ball on the table, at rest, the cue ball among them
  std::string cue_ball = CUE_BALL_ID;
  std::string target;  ///< the ball to pot; empty: any object ball
  std::string pocket;  ///< the id of the pocket to pot in (Table::pockets); empty: any
  RobotLimits limits;
  ExecutionNoise noise;
  std::optional<CueRegion> cue_region;
  PlanRules rules;
  double budget = 0.5;  ///< s of wall-clock time
  unsigned seed = 1;    ///< of the noisy rollouts: the same request and seed give the same plan
  int rollouts = 200;   ///< noisy rollouts of each shot that pots, to estimate its probability
  int threads = 0;      ///< rollouts in parallel; 0: one per hardware thread
  PlanHooks hooks;
};

/// How the cue ball reaches the target.
enum class CueBallPath
{
  Straight,  ///< along the cloth, straight (the ghost ball's aim)
  Kick,      ///< off one cushion first
  Masse,     ///< curving around a ball in the way (an elevated cue hitting off the centre)
  Jump,      ///< over a ball in the way (an elevated cue drives the ball into the cloth, which throws it up)
};

/// "straight", "kick", "masse", "jump".
const char* toString(CueBallPath path);

/// A shot and how likely it is to pot under the noise.
struct PlannedShot
{
  Stroke stroke;
  CuePlacement cue;  ///< the same shot as a cue pose and speed (as ~predict_shot takes it)
  std::string target;
  std::string pocket;        ///< the pocket's id
  std::string bank_cushion;  ///< the id of the rail the target banks off ("rail.top"); empty: straight in
  CueBallPath cue_ball_path = CueBallPath::Straight;
  /// m: how far inside its pocket's capture circle the target passes in the noise-free shot (negative: by how much
  /// it misses)
  double margin = 0.0;
  double success_probability = 0.0;
  double confidence_low = 0.0, confidence_high = 0.0;  ///< Wilson's 95 % interval
  int rollouts = 0;
  /// Where the target ended in each rollout (pocketed balls where they dropped): the spread of the outcomes.
  std::vector<Eigen::Vector2d> target_end_points;
};

struct ShotPlan
{
  bool found = false;  ///< a shot that pots without noise was found
  /// The shot with the highest pot probability; when none pots, the attempt that came closest, and `explanation`
  /// says why none was found.
  PlannedShot best;
  std::string explanation;
  ShotOutcome outcome;                    ///< the noise-free prediction of `best`
  std::vector<PlannedShot> alternatives;  ///< the next best shots, best first
  int evaluations = 0;                    ///< shots simulated
  double seconds = 0.0;
};

/// Whether the cue placed at `cue` (a cylinder of limits.cue_radius along limits.cue_length behind its tip) keeps a
/// margin from every ball of `others` and passes that margin above the rails (limits.rail_height) where it crosses
/// them: `margin` plus `margin_per_metre` times the distance from the tip (a turn of the cue about its tip moves it
/// in proportion). The cue ball, which the tip touches, is not among `others`.
bool cueClears(const CuePlacement& cue, const std::vector<TableBall>& others, const Table& table,
               const RobotLimits& limits, double ball_radius, double margin = 0.0, double margin_per_metre = 0.0);

/// Relative tolerance of the engine in the planner's rollouts (unless the configuration's is looser); the absolute one
/// is a hundredth of it, at most the engine's LOOSEST_ABSOLUTE_TOLERANCE. Far below the execution noise (a 0.5 mm
/// offset changes the ball's velocity by 1e-2 relative): on 200 of the plan benchmark's shots the final positions stay
/// within 4.2e-5 m of the default's (test_planning_tolerance.cpp checks 0.5 mm), the planner picks the shots it picks
/// at 1e-8, and a rollout costs about 1.4× less (bench/NOTES.md, Issue 37).
constexpr double PLANNING_TOLERANCE = 1e-5;

/// Checks of the parts a node reads from its parameters; errors name the field ("limits.speed", "noise.phi").
Status validate(const RobotLimits& limits);
Status validate(const ExecutionNoise& noise);

/// Checks the request against the configuration; errors name the field ("target", "limits.speed", "noise.phi",
/// "balls[2].position", …).
Status validate(const PlanRequest& request, const ShotConfiguration& configuration);

/// Plans a pot (docs/planning.md): candidate shots from the ghost ball for every target and pocket, straight in and
/// off one cushion, refined by NLopt's Sbplx on the target's margin in its pocket, then ranked by their pot probability
/// from noisy rollouts. Ends within the budget (the first shot evaluated is always finished). Pure function of its
/// arguments; thread-safe.
Expected<ShotPlan> planShot(const PlanRequest& request, const ShotConfiguration& configuration);

}  // namespace billiard_shot_planner
