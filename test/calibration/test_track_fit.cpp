// Track fits on tracks the model itself draws with other constants and a camera's noise (so the truth is known):
// the constants come back within their σ and predict shots the fit never saw, a shot that never meets a cushion
// says nothing of it, and bad tracks are refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "billiard_shot_planner/calibration/track_fit.hpp"
#include "billiard_shot_planner/planning/stroke.hpp"
#include "converging_fit.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double R = 0.0286;
constexpr double CAMERA_SIGMA = 0.002;  // m
constexpr double FRAME = 1.0 / 30.0;    // s

bsp::CuePlacement stroke(double x, double y, double phi_deg, double speed, double b)
{
  const auto cue = bsp::placeStroke({phi_deg * M_PI / 180.0, 5.0 * M_PI / 180.0, speed, 0.0, b}, {x, y}, R);
  EXPECT_TRUE(cue.ok());
  return cue.value();
}

bsp::ShotConfiguration truth()
{
  bsp::ShotConfiguration c;
  c.motion.sliding_friction = 0.2;
  c.motion.rolling_friction = 0.015;
  c.table.cushion.restitution = 0.75;
  return c;
}

/// The cue ball's track at 30 Hz for up to 3 s, each point off by the camera's noise.
bsp::ObservedShot observed(const bsp::CuePlacement& cue, const bsp::ShotConfiguration& c, std::mt19937& rng)
{
  std::normal_distribution<double> noise(0.0, CAMERA_SIGMA);
  const auto outcome = bsp::predictShot(cue, c);
  EXPECT_TRUE(outcome.ok()) << outcome.error().describe();
  bsp::ObservedShot shot{cue, {}, {}};
  const double end = std::min(3.0, outcome->trajectory.duration());
  for (double t = 0.0; t <= end; t += FRAME)
    shot.tracks[bsp::CUE_BALL_ID].push_back(
        {t, outcome->trajectory.at(t).position.head<2>() + Eigen::Vector2d{noise(rng), noise(rng)}});
  return shot;
}

/// Draw, follow and stun shots into the cushions at several angles and speeds.
std::vector<bsp::CuePlacement> shotsIntoCushions()
{
  return {stroke(-0.6, 0.0, 0.0, 2.5, 0.0),   stroke(0.0, -0.3, 75.0, 2.0, 0.4),   stroke(0.5, 0.2, 150.0, 2.2, -0.4),
          stroke(-0.3, 0.3, -40.0, 1.8, 0.2), stroke(0.2, -0.2, 200.0, 2.4, -0.2), stroke(0.8, 0.0, 100.0, 1.5, 0.3)};
}

const std::vector<bsp::FitParameter> MOTION_CONSTANTS = {{"motion.sliding_friction", 0.152479, 0.01, 1.0},
                                                         {"motion.rolling_friction", 0.0209727, 0.001, 0.2},
                                                         {"table.cushion.restitution", 0.85, 0.0, 1.0}};
const double TRUTH[] = {0.2, 0.015, 0.75};

}  // namespace

TEST(TrackFit, RecoversTheConstantsAndPredictsShotsItNeverSaw)
{
  std::mt19937 rng(1);
  std::vector<bsp::ObservedShot> shots;
  for (const bsp::CuePlacement& cue : shotsIntoCushions())
    shots.push_back(observed(cue, truth(), rng));
  const auto fitted = bsp::fitTracks(bsp::ShotConfiguration{}, MOTION_CONSTANTS, shots, CAMERA_SIGMA, convergingFit());
  ASSERT_TRUE(fitted.ok()) << fitted.error().describe();
  const bsp::FitResult& fit = fitted->fit;
  EXPECT_TRUE(fit.converged) << fit.message;
  bsp::ShotConfiguration c;
  for (int i = 0; i < 3; ++i)
  {
    const bsp::FittedParameter& p = fit.parameters[i];
    std::printf("%s: %.5f ± %.5f (truth %g)\n", p.name.c_str(), p.value, p.sigma, TRUTH[i]);
    EXPECT_TRUE(p.identifiable) << p.name;
    // Within three of its standard deviations of the truth, which it knows to better than 5 %.
    EXPECT_NEAR(p.value, TRUTH[i], 3.0 * p.sigma) << p.name;
    EXPECT_LT(p.sigma, 0.05 * TRUTH[i]) << p.name;
    ASSERT_TRUE(bsp::applyOverride(c, p.name, p.value));
  }
  // The camera's noise alone: the tracks' RMS distance to the fitted paths is about √2 σ.
  for (double rms : fitted->shot_rms)
    EXPECT_NEAR(rms, std::sqrt(2.0) * CAMERA_SIGMA, 0.5 * CAMERA_SIGMA);
  // Shots the fit never saw rest where the truth puts them, within 1 cm at the median.
  std::vector<double> misses;
  for (const bsp::CuePlacement& cue :
       {stroke(-0.9, 0.4, 20.0, 2.0, 0.3), stroke(0.9, -0.4, 170.0, 2.6, -0.3), stroke(0.0, 0.0, 45.0, 3.0, 0.0),
        stroke(-0.5, -0.5, 95.0, 1.2, 0.5), stroke(0.3, 0.5, -120.0, 2.8, -0.5)})
  {
    const auto expected = bsp::predictShot(cue, truth()), predicted = bsp::predictShot(cue, c);
    ASSERT_TRUE(expected.ok() && predicted.ok());
    misses.push_back((expected->trajectory.finalState().position - predicted->trajectory.finalState().position).norm());
  }
  std::nth_element(misses.begin(), misses.begin() + 2, misses.end());
  std::printf("held-out rest positions: median miss %.2f mm; %d iterations, %s\n", 1e3 * misses[2], fit.iterations,
              fit.message.c_str());
  EXPECT_LT(misses[2], 0.01);
}

TEST(TrackFit, ItsSigmaCoversTheTruthAsOftenAsItShould)
{
  // Twelve camera noise draws of three shots: |fit − truth| ≤ σ for about 68 % of the 36 estimates (±23 % at three
  // standard deviations of that fraction).
  const std::vector<bsp::CuePlacement> cues = shotsIntoCushions();
  int within = 0, total = 0;
  for (unsigned seed = 10; seed < 22; ++seed)
  {
    std::mt19937 rng(seed);
    std::vector<bsp::ObservedShot> shots;
    for (std::size_t k = 0; k < 3; ++k)
      shots.push_back(observed(cues[k], truth(), rng));
    const auto fitted = bsp::fitTracks(bsp::ShotConfiguration{}, MOTION_CONSTANTS, shots, CAMERA_SIGMA);
    ASSERT_TRUE(fitted.ok()) << fitted.error().describe();
    for (int i = 0; i < 3; ++i, ++total)
      within += std::abs(fitted->fit.parameters[i].value - TRUTH[i]) <= fitted->fit.parameters[i].sigma;
  }
  std::printf("|fit − truth| ≤ σ for %d of %d estimates\n", within, total);
  EXPECT_NEAR(static_cast<double>(within) / total, 0.683, 0.23);
}

/// Cut shots of the cue ball onto the object ball "one" at (0.3, 0), both balls tracked at 30 Hz for up to 2.5 s.
std::vector<bsp::ObservedShot> cutShots(const bsp::ShotConfiguration& c, std::mt19937& rng)
{
  std::normal_distribution<double> noise(0.0, CAMERA_SIGMA);
  std::vector<bsp::ObservedShot> shots;
  // From the left, aimed at the object ball's centre offset sideways by 0, ±0.6 R and ±1.2 R: full to thin cuts.
  for (double offset : {0.0, 0.6 * R, -0.6 * R, 1.2 * R, -1.2 * R})
  {
    const Eigen::Vector2d ball(-0.4, 0.0), aim(0.3, offset);
    const Eigen::Vector2d d = (aim - ball).normalized();
    const bsp::CuePlacement cue = stroke(ball.x(), ball.y(), std::atan2(d.y(), d.x()) * 180.0 / M_PI, 2.0, 0.0);
    bsp::ObservedShot shot{cue, {{"one", {}}}, {}};
    shot.others[0].state.position = Eigen::Vector3d(0.3, 0.0, R);
    const auto outcome = bsp::predictShot(cue, c, shot.others);
    EXPECT_TRUE(outcome.ok()) << outcome.error().describe();
    for (std::size_t b = 0; b < outcome->table.ids.size(); ++b)
    {
      const bsp::BallTrajectory& path = outcome->table.balls[b];
      for (double t = 0.0; t <= std::min(2.5, path.duration()); t += FRAME)
        shot.tracks[outcome->table.ids[b]].push_back(
            {t, path.at(t).position.head<2>() + Eigen::Vector2d{noise(rng), noise(rng)}});
    }
    shots.push_back(shot);
  }
  return shots;
}

TEST(TrackFit, RecoversTheBallBallConstantsFromCutShots)
{
  // The constant friction model, so that the ball–ball friction is one number: 0.08 and e = 0.9 drew the tracks,
  // the fit starts from the defaults (0.05, 0.95).
  bsp::ShotConfiguration start;
  start.ball_contact.friction_model = bsp::BallBallFriction::Constant;
  bsp::ShotConfiguration drawn = start;
  drawn.ball_contact.ball_ball.restitution = 0.9;
  drawn.ball_contact.ball_ball.friction = 0.08;
  std::mt19937 rng(4);
  const auto fitted =
      bsp::fitTracks(start, {{"ball_ball.restitution", 0.95, 0.0, 1.0}, {"ball_ball.friction", 0.05, 0.0, 1.0}},
                     cutShots(drawn, rng), CAMERA_SIGMA, convergingFit());
  ASSERT_TRUE(fitted.ok()) << fitted.error().describe();
  const double truth[] = {0.9, 0.08};
  for (int i = 0; i < 2; ++i)
  {
    const bsp::FittedParameter& p = fitted->fit.parameters[i];
    std::printf("%s: %.5f ± %.5f (truth %g)\n", p.name.c_str(), p.value, p.sigma, truth[i]);
    EXPECT_TRUE(p.identifiable) << p.name;
    EXPECT_NEAR(p.value, truth[i], 3.0 * p.sigma) << p.name;
    EXPECT_LT(p.sigma, 0.1 * truth[i]) << p.name;
  }
}

TEST(TrackFit, AShotThatMeetsNoCushionSaysNothingOfIt)
{
  // A slow stun shot along the table's length, at rest before the far cushion.
  std::mt19937 rng(2);
  const std::vector<bsp::ObservedShot> shots = {observed(stroke(-0.9, 0.0, 0.0, 1.0, 0.0), truth(), rng)};
  const auto fitted = bsp::fitTracks(bsp::ShotConfiguration{}, MOTION_CONSTANTS, shots, CAMERA_SIGMA);
  ASSERT_TRUE(fitted.ok()) << fitted.error().describe();
  const std::vector<bsp::FittedParameter>& p = fitted->fit.parameters;
  EXPECT_TRUE(p[1].identifiable);
  EXPECT_FALSE(p[2].identifiable);
  EXPECT_EQ(p[2].value, 0.85);
  EXPECT_TRUE(std::isinf(p[2].sigma));
  EXPECT_NEAR(p[1].value, 0.015, 3.0 * p[1].sigma);
}

TEST(TrackFit, BadTracksAreRefusedNamingTheObservation)
{
  std::mt19937 rng(3);
  const bsp::ObservedShot good = observed(stroke(-0.6, 0.0, 0.0, 2.0, 0.0), truth(), rng);
  const auto field = [](const std::vector<bsp::ObservedShot>& shots, double sigma = CAMERA_SIGMA)
  {
    const auto fit = bsp::fitTracks(bsp::ShotConfiguration{}, MOTION_CONSTANTS, shots, sigma);
    return fit.ok() ? std::string("accepted") : fit.error().field;
  };
  bsp::ObservedShot bad = good;
  bad.tracks["cue"][5].t = NAN;
  EXPECT_EQ(field({good, bad}), "shots[1].tracks.cue[5].t");
  bad = good;
  bad.tracks["cue"][0].t = -0.1;
  EXPECT_EQ(field({bad}), "shots[0].tracks.cue[0].t");
  bad = good;
  std::swap(bad.tracks["cue"][3], bad.tracks["cue"][4]);
  EXPECT_EQ(field({bad}), "shots[0].tracks.cue[4].t");
  bad = good;
  bad.tracks["cue"][2].position.y() = INFINITY;
  EXPECT_EQ(field({bad}), "shots[0].tracks.cue[2].position");
  bad = good;
  bad.tracks["seven"] = {{0.0, {0.1, 0.1}}};
  EXPECT_EQ(field({bad}), "shots[0].tracks.seven");
  bad = good;
  bad.tracks["cue"].resize(1);
  EXPECT_EQ(field({bad}), "shots");  // 2 observations, 3 parameters
  bad = good;
  bad.cue.tip.z() += 0.2;  // the cue's axis passes over the ball
  EXPECT_EQ(field({bad}).rfind("shots[0]", 0), 0u);
  EXPECT_EQ(field({good}, 0.0), "position_sigma");
  EXPECT_EQ(field({}), "shots");
}

namespace
{
/// Eight cue-ball shots of the calibration issue's study (speeds 1–3 m/s, b within ±0.3, 2 mm of noise) drawn with
/// μ_s 0.19, μ_r 0.013 and the cushion's e 0.74.
std::vector<bsp::ObservedShot> eightTrackedShots(unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-0.9, 0.9), y(-0.4, 0.4), phi(-180.0, 180.0), speed(1.0, 3.0), b(-0.3, 0.3);
  bsp::ShotConfiguration truth;
  truth.motion.sliding_friction = 0.19;
  truth.motion.rolling_friction = 0.013;
  truth.table.cushion.restitution = 0.74;
  std::vector<bsp::ObservedShot> shots;
  while (shots.size() < 8)
  {
    // Drawn one by one: the order in which a call's arguments are evaluated is the compiler's choice.
    const bsp::Stroke drawn{phi(rng) * M_PI / 180.0, 5.0 * M_PI / 180.0, speed(rng), 0.0, b(rng)};
    const Eigen::Vector2d ball{x(rng), y(rng)};
    const auto cue = bsp::placeStroke(drawn, ball, R);
    if (cue.ok())
      shots.push_back(observed(cue.value(), truth, rng));
  }
  return shots;
}

const double EIGHT_SHOTS_TRUTH[] = {0.19, 0.013, 0.74};

/// The three constants from the node's defaults.
std::vector<bsp::FitParameter> motionConstantsFromTheDefaults()
{
  const bsp::ShotConfiguration defaults;
  return {{"motion.sliding_friction", defaults.motion.sliding_friction, 0.01, 1.0},
          {"motion.rolling_friction", defaults.motion.rolling_friction, 0.001, 0.2},
          {"table.cushion.restitution", defaults.table.cushion.restitution, 0.0, 1.0}};
}

void expectTheTruthExplained(const bsp::FitResult& fit)
{
  for (int i = 0; i < 3; ++i)
  {
    const bsp::FittedParameter& p = fit.parameters[i];
    std::printf("%s: %.5f ± %.5f (truth %g)\n", p.name.c_str(), p.value, p.sigma, EIGHT_SHOTS_TRUTH[i]);
    EXPECT_NEAR(p.value, EIGHT_SHOTS_TRUTH[i], 4.0 * p.sigma) << p.name;
  }
  std::printf("chi2 %.1f for %d degrees of freedom: %.3f per degree\n", 2.0 * fit.final_cost, fit.degrees_of_freedom,
              fit.chi2_per_dof);
  EXPECT_EQ(fit.degrees_of_freedom, static_cast<int>(fit.residuals.size()) - 3);
  EXPECT_NEAR(fit.chi2_per_dof, 1.0, 0.15);
  EXPECT_TRUE(fit.explains_data);
}
}  // namespace

// The eight shots of seed 36 fitted from the configuration's defaults with the default options: the truth comes
// back, and the answer reports its degrees of freedom and χ² per degree near 1 — χ² of n − p degrees of freedom has
// mean 1 per degree and σ √(2/(n − p)), 0.04 here.
TEST(TrackFit, AFitReportsItsChiSquarePerDegreeOfFreedom)
{
  const auto fitted = bsp::fitTracks(bsp::ShotConfiguration{}, motionConstantsFromTheDefaults(), eightTrackedShots(36),
                                     CAMERA_SIGMA, convergingFit());
  ASSERT_TRUE(fitted.ok()) << fitted.error().describe();
  expectTheTruthExplained(fitted->fit);
}

// The local minimum the calibration issue reports: of 80 draws of its eight shots, the one of seed 31 takes a single
// local fit from the defaults to μ_s 0.154, μ_r 0.0118, e 0.700 — "converged", with χ² 300 times its degrees of
// freedom. The fit says it does not explain the data, and by default searches on from more starts to the truth.
TEST(TrackFit, ALocalMinimumIsNotAnsweredAsTheFit)
{
  const std::vector<bsp::ObservedShot> shots = eightTrackedShots(31);
  bsp::FitOptions single = convergingFit();
  single.escalate = false;
  const auto stuck =
      bsp::fitTracks(bsp::ShotConfiguration{}, motionConstantsFromTheDefaults(), shots, CAMERA_SIGMA, single);
  ASSERT_TRUE(stuck.ok()) << stuck.error().describe();
  EXPECT_GT(stuck->fit.chi2_per_dof, 10.0);
  EXPECT_FALSE(stuck->fit.explains_data);
  EXPECT_NE(stuck->fit.message.find("not explain"), std::string::npos) << stuck->fit.message;
  EXPECT_GT(std::abs(stuck->fit.parameters[0].value - EIGHT_SHOTS_TRUTH[0]), 0.01);  // the minimum is a wrong one

  const auto searched =
      bsp::fitTracks(bsp::ShotConfiguration{}, motionConstantsFromTheDefaults(), shots, CAMERA_SIGMA, convergingFit());
  ASSERT_TRUE(searched.ok()) << searched.error().describe();
  expectTheTruthExplained(searched->fit);
}
