// The impact_solve program: JSON in, JSON out, exit code 2 with a message on bad input.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include "billiard_shot_planner/scenarios/cue_strike.hpp"

namespace bsp = billiard_shot_planner;
#include <yaml-cpp/yaml.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace
{
struct SolverRun
{
  int exit_code;
  std::string output;
};

SolverRun runSolver(const std::string& input)
{
  const std::string path = testing::TempDir() + "impact_solve_input.json";
  std::ofstream(path) << input;
  const std::string command = std::string(IMPACT_SOLVE_PATH) + " < " + path + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe))
    output += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), output};
}
}  // namespace

TEST(ImpactSolve, BallBallTableFromTheIssue)
{
  const SolverRun run = runSolver(
      R"({"problem": "ball_ball_table", "m1": 1, "m2": 1.1547, "stiffness_ratio": 1, "e1": 0.9, "e2": 0.7, "v0": -1})");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  EXPECT_EQ(out["states"], (std::vector<std::string>{"S1", "S2", "S1", "S3", "S4"}));
  EXPECT_NEAR(out["v1"].get<double>(), 0.61395, 2e-4);  // m2 = 1.1547 is 2/√3 to 5 digits
  EXPECT_NEAR(out["v2"].get<double>(), 0.20972, 2e-4);
  EXPECT_EQ(out["ends_of_compression"], (std::vector<int>{2, 1}));
  EXPECT_EQ(out["converged"], false);
  EXPECT_TRUE(out.contains("I1"));
  EXPECT_TRUE(out.contains("I2"));
}

TEST(ImpactSolve, Chain)
{
  const SolverRun run = runSolver(
      R"({"problem": "chain", "masses": [1, 1, 1], "velocities": [1, 0, 0], "stiffness": [1, 1], "restitution": [1, 1], "wall": false})");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  const auto v = out["velocities"].get<std::vector<double>>();
  ASSERT_EQ(v.size(), 3u);
  EXPECT_NEAR(v[0] + v[1] + v[2], 1.0, 1e-12);
  EXPECT_NEAR(0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 0.5, 1e-9);
  EXPECT_EQ(out["impulses"].size(), 2u);
  EXPECT_EQ(out["states"][0], (std::vector<int>{0, 1}));
}

TEST(ImpactSolve, BadInputExitsWithTwoAndAMessage)
{
  const char* cases[][2] = {
      {"not json", "not valid JSON"},
      {R"({"problem": "ball_ball_table", "m2": 1, "stiffness_ratio": 1, "e1": 1.5, "e2": 0.7})", "e1"},
      {R"({"problem": "ball_ball_table", "m2": "heavy", "stiffness_ratio": 1, "e1": 1, "e2": 0.7})", "m2"},
      {R"({"problem": "ball_ball_table", "stiffness_ratio": 1, "e1": 1, "e2": 0.7})", "m2"},
      {R"({"problem": "ball_ball_table", "m2": 1, "stiffness_ratio": 1, "e1": 1, "e2": 1, "v0": 1})", "v0"},
      {R"({"problem": "chain", "masses": [1, 1], "velocities": [1], "stiffness": [1], "restitution": [1]})",
       "velocities"},
      {R"({"problem": "teleport"})", "unknown problem"},
      {R"([1, 2])", "JSON object"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find(c[1]), std::string::npos) << c[0] << "\n" << run.output;
  }
}

TEST(ImpactSolve, CueStrikeFromTheIssue)
{
  const std::string shot =
      R"({"problem": "cue_strike", "cue_mass": 0.5018, "cue_direction": [0.2761, -0.1388, -0.9511],
          "cue_speed": 3.089095, "ball_mass": 0.1701, "ball_radius": 0.0286,
          "hit_normal": [0.480151, -0.102889, 0.871131],
          "cue_contact": {"restitution": 0.656532, "friction": 0.7, "eta2": 7},
          "table_contact": {"restitution": 0.51625, "friction": 0.152479, "eta2": 10}, "stiffness_ratio": 0.8,
          "cue_end_mass": "inf"})";
  const SolverRun run = runSolver(shot);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  EXPECT_EQ(out["states"], (std::vector<std::string>{"S1", "S3", "S4"}));
  // The program answers what the library computes for the same strike.
  bsp::CueStrike strike;
  strike.cue_mass = 0.5018;
  strike.cue_end_mass = bsp::CUE_HELD_ON_AXIS;
  strike.cue_direction = {0.2761, -0.1388, -0.9511};
  strike.cue_speed = 3.089095;
  strike.ball_mass = 0.1701;
  strike.ball_radius = 0.0286;
  strike.hit_normal = {0.480151, -0.102889, 0.871131};
  strike.cue_contact = {0.656532, 0.7, 7};
  strike.table_contact = {0.51625, 0.152479, 10};
  strike.stiffness_ratio = 0.8;
  const auto expected = bsp::solve(strike).value();
  const auto v = out["v"].get<std::vector<double>>();
  const auto w = out["omega"].get<std::vector<double>>();
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(v[k], expected.velocity(k), 1e-12);
    EXPECT_NEAR(w[k], expected.angular_velocity(k), 1e-10);
  }
  // docs/validation.md, The massé shot: its first row is for m = 0.17; the 0.06 % heavier ball moves v by < 1e-3.
  EXPECT_NEAR(v[0], -1.42587, 1e-3);
  EXPECT_NEAR(v[1], 0.24610, 1e-3);
  EXPECT_NEAR(v[2], 0.45511, 1e-3);
  EXPECT_EQ(out["omega"].size(), 3u);
  EXPECT_EQ(out["impulse_cue"].size(), 3u);
  EXPECT_EQ(out["impulse_table"].size(), 3u);
  EXPECT_TRUE(out["cue_velocity"].is_number());
  EXPECT_EQ(out["miscue"], false);
  EXPECT_EQ(out["leaves_cloth"], true);
  EXPECT_FALSE(out["events"].empty());
  EXPECT_TRUE(out["events"][0].contains("contact_name"));
  // The same strike with a hand-held cue's tip (the default end mass) is another strike.
  auto held = nlohmann::json::parse(shot);
  held.erase("cue_end_mass");
  const SolverRun hand_held = runSolver(held.dump());
  ASSERT_EQ(hand_held.exit_code, 0) << hand_held.output;
  EXPECT_GT(std::abs(nlohmann::json::parse(hand_held.output)["v"][0].get<double>() - v[0]), 1e-3);
}

namespace
{
/// A level stroke of a hand-held cue given as {phi_deg, theta_deg, speed, a, b}.
std::string stroke(const std::string& cue, const std::string& more = "")
{
  return R"({"problem": "cue_strike", "cue_mass": 0.54, "ball_mass": 0.17, "ball_radius": 0.028575,
             "cue_contact": {"restitution": 0.75, "friction": 0.7, "eta2": 1.2},
             "table_contact": {"restitution": 0.5, "friction": 0.2, "eta2": 10}, "stiffness_ratio": 0.8,
             "cue": )" +
         cue + more + "}";
}
}  // namespace

TEST(ImpactSolve, CueStrikeAsAStroke)
{
  // Level through the centre: the central impact of cue and ball, v = (1 + e) M V / (M + m).
  const SolverRun centre = runSolver(stroke(R"({"phi_deg": 90, "speed": 2})"));
  ASSERT_EQ(centre.exit_code, 0) << centre.output;
  const auto c = nlohmann::json::parse(centre.output);
  EXPECT_NEAR(c["v"][1].get<double>(), 1.75 * 0.54 * 2 / (0.54 + 0.17), 1e-12);
  EXPECT_NEAR(c["v"][0].get<double>(), 0.0, 1e-12);
  EXPECT_EQ(c["states"], (std::vector<std::string>{"S3", "S4"}));
  EXPECT_EQ(c["leaves_cloth"], false);
  // Draw, 5° down, right english: backspin, counter-clockwise side spin, and the tip's velocity reported.
  const SolverRun draw = runSolver(
      stroke(R"({"phi_deg": 0, "theta_deg": 5, "speed": 2, "a": 0.2, "b": -0.3})", R"(, "cue_end_mass": 0.0057)"));
  ASSERT_EQ(draw.exit_code, 0) << draw.output;
  const auto d = nlohmann::json::parse(draw.output);
  EXPECT_LT(d["omega"][1].get<double>(), 0.0);
  EXPECT_GT(d["omega"][2].get<double>(), 0.0);
  EXPECT_GT(d["v"][1].get<double>(), 0.0);  // squirt away from the english
  EXPECT_EQ(d["tip_velocity"].size(), 3u);
  // The same stroke as a whole shot: the strike, then the path on the table.
  auto shot = nlohmann::json::parse(stroke(R"({"phi_deg": 0, "theta_deg": 5, "speed": 2, "a": 0.2, "b": -0.3})"));
  shot["problem"] = "shot";
  shot["ball_position"] = {-0.5, 0.0};
  const SolverRun whole = runSolver(shot.dump());
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const auto w = nlohmann::json::parse(whole.output);
  EXPECT_EQ(w["strike"]["v"], d["v"]);
  EXPECT_FALSE(w["trajectory"]["events"].empty());
}

// A strike that omits its constants takes the node's: those of config/default.yaml, read here from the file and
// spelled out in a second request whose answer must be the same; a contact's constants are taken one by one.
TEST(ImpactSolve, OmittedConstantsAreTheNodesDefaults)
{
  const YAML::Node node = YAML::LoadFile(std::string(CONFIG_DIR) + "/default.yaml");
  const auto contact = [](const YAML::Node& c, double friction)
  {
    return nlohmann::json{
        {"restitution", c["restitution"].as<double>()}, {"friction", friction}, {"eta2", c["eta2"].as<double>()}};
  };
  const nlohmann::json cue = {{"phi_deg", 0}, {"theta_deg", 5}, {"speed", 2}, {"a", 0.2}, {"b", -0.3}};
  nlohmann::json omitted = {{"problem", "cue_strike"}, {"cue", cue}, {"cue_contact", {{"friction", 0.5}}}};
  nlohmann::json spelled = omitted;
  spelled["cue_mass"] = node["cue_mass"].as<double>();
  spelled["cue_end_mass"] = node["cue_end_mass"].as<double>();
  spelled["ball_mass"] = node["ball_mass"].as<double>();
  spelled["ball_radius"] = node["ball_radius"].as<double>();
  spelled["stiffness_ratio"] = node["stiffness_ratio"].as<double>();
  spelled["cue_contact"] = contact(node["cue_contact"], 0.5);
  spelled["table_contact"] = contact(node["table"]["cloth"], node["table"]["cloth"]["friction"].as<double>());
  const SolverRun short_form = runSolver(omitted.dump()), long_form = runSolver(spelled.dump());
  ASSERT_EQ(short_form.exit_code, 0) << short_form.output;
  ASSERT_EQ(long_form.exit_code, 0) << long_form.output;
  const auto a = nlohmann::json::parse(short_form.output), b = nlohmann::json::parse(long_form.output);
  EXPECT_EQ(a["v"], b["v"]);
  EXPECT_EQ(a["omega"], b["omega"]);
  spelled["cue_contact"]["friction"] = 0.7;  // the default tip's friction changes the answer: the 0.5 was read
  EXPECT_NE(nlohmann::json::parse(runSolver(spelled.dump()).output)["omega"], a["omega"]);
}

// The same stroke in pooltool's and FastFiz's numbers ("convention"): this package's φ 30°, θ 5°, a 0.2, b −0.3 is
// pooltool's phi 120° with a −0.2 and FastFiz's phi −60° with a and b in millimetres (docs/stroke_conventions.md).
TEST(ImpactSolve, AStrokeInPooltoolsOrFastFizsConventionIsTheSameStroke)
{
  const auto answer = [](const std::string& cue)
  {
    const SolverRun run = runSolver(stroke(cue));
    EXPECT_EQ(run.exit_code, 0) << cue << "\n" << run.output;
    return run.exit_code == 0 ? nlohmann::json::parse(run.output) : nlohmann::json();
  };
  const auto ours = answer(R"({"phi_deg": 30, "theta_deg": 5, "speed": 2, "a": 0.2, "b": -0.3})");
  const double mm = 0.028575e3;
  for (const std::string& cue :
       {std::string(R"({"convention": "pooltool", "phi_deg": 120, "theta_deg": 5, "speed": 2, "a": -0.2, "b": -0.3})"),
        R"({"convention": "fastfiz", "phi_deg": -60, "theta_deg": 5, "speed": 2, "a": )" + std::to_string(0.2 * mm) +
            R"(, "b": )" + std::to_string(-0.3 * mm) + "}"})
  {
    const auto theirs = answer(cue);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(theirs["v"][i].get<double>(), ours["v"][i].get<double>(), 1e-9) << cue;
      EXPECT_NEAR(theirs["omega"][i].get<double>(), ours["omega"][i].get<double>(), 1e-7) << cue;
    }
  }
  for (const auto& [cue, field] :
       {std::pair{R"({"convention": "snooker", "phi_deg": 0, "speed": 2})", "cue.convention"},
        std::pair{R"({"phi_deg": 0, "speed": 2, "english": 0.2})", "english"}})
  {
    const SolverRun run = runSolver(stroke(cue));
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(field), std::string::npos) << run.output;
  }
}

TEST(ImpactSolve, BadStrokesExitWithTwoNamingTheField)
{
  const std::string cases[][2] = {
      {stroke(R"({"phi_deg": 0, "speed": 2, "a": 0.8, "b": 0.7})"), "cue.a"},
      {stroke(R"({"phi_deg": 0, "speed": 2, "theta_deg": 120})"), "cue.theta_deg"},
      {stroke(R"({"phi_deg": 0, "speed": 2, "theta_deg": 80, "b": -0.5})"), "cannot reach"},
      {stroke(R"({"speed": 2})"), "cue.phi_deg"},
      {stroke(R"({"phi_deg": 0, "speed": -1})"), "cue_speed"},
      {stroke(R"({"phi_deg": 0, "speed": 2})", R"(, "cue_direction": [1, 0, 0])"), "cue_direction"},
      {stroke(R"({"phi_deg": 0, "speed": 2})", R"(, "cue_end_mass": -0.01)"), "cue_end_mass"},
      {stroke(R"({"phi_deg": 0, "speed": 2})", R"(, "cue_end_mass": "heavy")"), "cue_end_mass"},
      {stroke(R"("straight")"), "cue"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find(c[1]), std::string::npos) << c[0] << "\n" << run.output;
  }
}

TEST(ImpactSolve, CueStrikeFromTheCueAxis)
{
  // A slightly elevated cue aimed 1 cm above the centre: a follow shot.
  const std::string shot =
      R"({"problem": "cue_strike", "cue_mass": 0.5, "cue_direction": [1, 0, -0.05], "cue_speed": 2,
          "ball_mass": 0.17, "ball_radius": 0.0286, "cue_axis_point": [-0.1, 0, 0.0436],
          "ball_centre": [0, 0, 0.0286],
          "cue_contact": {"restitution": 0.7, "friction": 0.6, "eta2": 7},
          "table_contact": {"restitution": 0.5, "friction": 0.2, "eta2": 10}, "stiffness_ratio": 1})";
  const SolverRun run = runSolver(shot);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  const auto n = out["hit_normal"].get<std::vector<double>>();
  EXPECT_GT(n[2], 0.0);                           // above the equator
  EXPECT_LT(n[0], 0.0);                           // on the side facing the cue
  EXPECT_GT(out["v"][0].get<double>(), 0.0);      // the ball goes forward
  EXPECT_GT(out["omega"][1].get<double>(), 0.0);  // topspin: rolling along +x turns about ẑ × x̂ = +ŷ
}

TEST(ImpactSolve, InvalidShotsExitWithTwo)
{
  const char* cases[][2] = {
      {R"({"problem": "cue_strike", "cue_mass": 0.5, "cue_direction": [0, 0, 1], "cue_speed": 2, "ball_mass": 0.17,
           "ball_radius": 0.0286, "hit_normal": [0, 0, 1], "cue_contact": {"restitution": 0.7, "friction": 0.6,
           "eta2": 7}, "table_contact": {"restitution": 0.5, "friction": 0.2, "eta2": 10}, "stiffness_ratio": 1})",
       "does not approach"},
      {R"({"problem": "cue_strike", "cue_mass": 0.5, "cue_direction": [0, 0, -1], "cue_speed": 2, "ball_mass": 0.17,
           "ball_radius": 0.0286, "hit_normal": [0, 0, 1], "cue_contact": {"restitution": 0.7, "friction": 0.6,
           "eta2": -1}, "table_contact": {"restitution": 0.5, "friction": 0.2, "eta2": 10}, "stiffness_ratio": 1})",
       "cue_contact.eta2"},
      {R"({"problem": "cue_strike", "cue_mass": 0.5, "cue_direction": [1, 0, -0.1], "cue_speed": 2,
           "ball_mass": 0.17, "ball_radius": 0.0286, "cue_axis_point": [-0.1, 0.2, 0.0286],
           "cue_contact": {"restitution": 0.7, "friction": 0.6, "eta2": 7},
           "table_contact": {"restitution": 0.5, "friction": 0.2, "eta2": 10}, "stiffness_ratio": 1})",
       "misses the ball"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find(c[1]), std::string::npos) << c[0] << "\n" << run.output;
  }
}

TEST(ImpactSolve, BallMotionAndShot)
{
  const SolverRun motion = runSolver(
      R"({"problem": "ball_motion", "position": [0, 0], "v": [-1.67629, -0.075349, 0.637937],
          "omega": [40.3064, 83.6145, -15.4927], "ball_radius": 0.0286, "planar": true,
          "table": {"length": 10, "width": 10, "pockets": []}})");
  ASSERT_EQ(motion.exit_code, 0) << motion.output;
  const auto m = nlohmann::json::parse(motion.output);
  EXPECT_EQ(m["outcome"], "rest");
  // docs/validation.md, Motion after the massé shot.
  EXPECT_NEAR(m["rest_position"][0].get<double>(), -2.00179, 1e-5);
  EXPECT_NEAR(m["rest_position"][1].get<double>(), -1.02020, 1e-5);
  EXPECT_EQ(m["events"][1]["type"], "slide_to_roll");
  EXPECT_GT(m["samples"].size(), 100u);

  const SolverRun shot = runSolver(
      R"({"problem": "shot", "ball_position": [0.3, 0.2], "cue_mass": 0.5018,
          "cue_direction": [-0.2761, -0.1388, -0.9511], "cue_speed": 3.089095, "ball_mass": 0.17,
          "ball_radius": 0.0286, "hit_normal": [0.480151, -0.102889, 0.871131],
          "cue_contact": {"restitution": 0.656532, "friction": 0.7, "eta2": 7},
          "table_contact": {"restitution": 0.51625, "friction": 0.152479, "eta2": 10}, "stiffness_ratio": 0.8,
          "cue_end_mass": "inf", "table_file": ")" +
      std::string(CONFIG_DIR) + R"(/table_9ft.yaml"})");
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  const auto s = nlohmann::json::parse(shot.output);
  EXPECT_EQ(s["strike"]["states"], (std::vector<std::string>{"S1", "S2", "S4"}));
  EXPECT_EQ(s["trajectory"]["events"][1]["type"], "landing");
}

TEST(ImpactSolve, BallMotionBadInput)
{
  const char* cases[][2] = {
      {R"({"problem": "ball_motion", "position": [5, 0], "v": [1, 0, 0], "omega": [0, 0, 0]})", "off the table"},
      {R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0],
           "sliding_friction": -1})",
       "sliding_friction"},
      {R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0],
           "rolling_model": "magic"})",
       "rolling_model"},
      {R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0], "omega": [0, 0, 0]})", "v"},
      {R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0],
           "table_file": "/nonexistent.yaml"})",
       "cannot open"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find(c[1]), std::string::npos) << c[0] << "\n" << run.output;
  }
}

TEST(ImpactSolve, ContactLawsAreChosenByTypeAndBadOnesNameTheirField)
{
  // A ball dropped on a frictionless cloth with the elastic–plastic law: e = e0 · e_T(v), Thornton 1997, eq. 39,
  // at x = v_y / v = 0.5: √(6√3/5) · √(1 − 0.25/6) · [0.5 / (0.5 + 2√(6/5 − 0.05))]^¼ = 0.93063.
  const SolverRun drop = runSolver(
      R"({"problem": "ball_table", "mass": 0.17, "radius": 0.0286, "velocity": [0, 0, -2],
          "table": {"restitution": 0.9, "friction": 0, "eta2": 1,
                    "law": {"type": "elastic_plastic", "yield_speed": 1.0}}})");
  ASSERT_EQ(drop.exit_code, 0) << drop.output;
  EXPECT_NEAR(nlohmann::json::parse(drop.output)["v"][2].get<double>(), 2.0 * 0.9 * 0.93063, 2e-4) << drop.output;

  const char* cases[][2] = {
      {R"({"problem": "ball_table", "mass": 0.17, "radius": 0.0286, "velocity": [0, 0, -2],
           "table": {"restitution": 0.9, "friction": 0, "eta2": 1, "law": {"type": "hertz_typo"}}})",
       "table.law.type"},
      {R"({"problem": "ball_table", "mass": 0.17, "radius": 0.0286, "velocity": [0, 0, -2],
           "table": {"restitution": 0.9, "friction": 0, "eta2": 1, "law": {"type": "elastic_plastic",
                     "yield_speed": -1}}})",
       "table.law.yield_speed"},
      {R"({"problem": "ball_table", "mass": 0.17, "radius": 0.0286, "velocity": [0, 0, -2],
           "table": {"restitution": 0.9, "friction": 0, "eta2": 1, "law": {"type": "constant", "yield_speed": 1}}})",
       "table.law.yield_speed"},
      {R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0],
           "table": {"cushion": {"law": {"yield_speed": 1}}}})",
       "invalid_argument: table.cushion.law.yield_speed: is not a parameter of the law"},
      {R"({"problem": "ball_table", "mass": 0.17, "radius": 0.0286, "velocity": [0, 0, -2],
           "table": {"restitution": 0.9, "friction": 0, "eta2": 1, "lawz": {"type": "constant"}}})",
       "table.lawz"},
      {R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0],
           "table": {"lenght": 3}})",
       "table.lenght"},
      {R"({"problem": "ball_ball", "balls": [{"position": [0, 0], "v": [1, 0, 0]}, {"position": [0.0572, 0]}],
           "cloth": {"friction": 0.2, "friction_model": "constant"}})",
       "cloth.friction_model"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find(c[1]), std::string::npos) << c[0] << "\n" << run.output;
  }
}

TEST(ImpactSolve, ATableFileGivesItsClothsMotionAndRefusesUnknownFields)
{
  // The snooker file's sliding friction 0.212: a stun shot at 1 m/s rolls after t = 2v/(7 μ g) = 0.137381 s at 5/7 v.
  const SolverRun stun = runSolver(
      R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0], "ball_radius": 0.02625,
          "table_file": ")" +
      std::string(CONFIG_DIR) + R"(/tables/snooker_mathavan.yaml"})");
  ASSERT_EQ(stun.exit_code, 0) << stun.output;
  const auto rolls = nlohmann::json::parse(stun.output)["events"][1];
  EXPECT_EQ(rolls["type"], "slide_to_roll");
  EXPECT_NEAR(rolls["t"].get<double>(), 2.0 / (7.0 * 0.212 * 9.81), 1e-9);
  EXPECT_NEAR(rolls["v"][0].get<double>(), 5.0 / 7.0, 1e-9);
}

// A request's configuration is read by the one list of fields (docs/cli.md): a table file gives every problem that
// strikes the ball its cloth, as the same constants spelt out in the request do.
TEST(ImpactSolve, ATableFilesClothIsTheStrikesAsIfSpeltOut)
{
  const std::string strike = R"({"problem": "cue_strike", "ball_radius": 0.02625, "ball_mass": 0.1406,
      "cue": {"phi_deg": 0, "theta_deg": 10, "speed": 3, "a": 0.3, "b": -0.3}, )";
  const SolverRun from_file =
      runSolver(strike + R"("table_file": ")" + std::string(CONFIG_DIR) + R"(/tables/snooker_mathavan.yaml"})");
  // The snooker file's cloth (config/tables/snooker_mathavan.yaml).
  const SolverRun spelt =
      runSolver(strike + R"("table_contact": {"restitution": 0.51625, "friction": 0.212, "eta2": 10.0}})");
  const SolverRun pool = runSolver(strike + "\"stiffness_ratio\": 0.8}");
  ASSERT_EQ(from_file.exit_code, 0) << from_file.output;
  ASSERT_EQ(spelt.exit_code, 0) << spelt.output;
  ASSERT_EQ(pool.exit_code, 0) << pool.output;
  const auto a = nlohmann::json::parse(from_file.output), b = nlohmann::json::parse(spelt.output);
  EXPECT_EQ(a["v"], b["v"]);
  EXPECT_EQ(a["omega"], b["omega"]);
  // The pool cloth (friction 0.152479) answers otherwise: the file's cloth was used.
  EXPECT_NE(nlohmann::json::parse(pool.output)["v"], a["v"]);
}

// ball_ball and ball_table take a table file's constants (config/tables/snooker_mathavan.yaml) as the same
// constants spelt out in the request.
TEST(ImpactSolve, ATableFilesContactsAreTheCollisionsAsIfSpeltOut)
{
  const std::string file = R"("table_file": ")" + std::string(CONFIG_DIR) + R"(/tables/snooker_mathavan.yaml")";
  const std::string snooker_cloth = R"({"restitution": 0.51625, "friction": 0.212, "eta2": 10.0})";
  const std::string collision = R"({"problem": "ball_ball", "ball_radius": 0.02625, "ball_mass": 0.1406,
      "balls": [{"position": [0, 0], "v": [1.5, 0, 0], "omega": [0, 40, 0]}, {"position": [0.0454663337, 0.02625]}], )";  // half-ball: R√3, R
  const std::string drop = R"({"problem": "ball_table", "mass": 0.1406, "radius": 0.02625,
      "velocity": [0.5, 0, -1.5], "angular_velocity": [0, 0, 0], )";
  const std::pair<std::string, std::string> cases[] = {
      {collision + file + "}", collision +
                                   R"("ball_ball": {"restitution": 0.966, "friction": 0.070, "eta2": 1.2}, "cloth": )" +
                                   snooker_cloth + R"(, "stiffness_ratio": 0.1})"},
      {drop + file + "}", drop + R"("table": )" + snooker_cloth + "}"},
  };
  for (const auto& [from_file, spelt] : cases)
  {
    const SolverRun a = runSolver(from_file), b = runSolver(spelt);
    ASSERT_EQ(a.exit_code, 0) << a.output;
    ASSERT_EQ(b.exit_code, 0) << b.output;
    const auto x = nlohmann::json::parse(a.output), y = nlohmann::json::parse(b.output);
    EXPECT_EQ(x.contains("balls") ? x["balls"] : x["v"], y.contains("balls") ? y["balls"] : y["v"]) << from_file;
  }
  // The file's cloth stands under the request's own "table" fields: a friction given replaces only the friction.
  const SolverRun over = runSolver(drop + file + R"(, "table": {"friction": 0.1}})");
  const SolverRun spelt_over = runSolver(drop + R"("table": {"restitution": 0.51625, "friction": 0.1, "eta2": 10.0}})");
  ASSERT_EQ(over.exit_code, 0) << over.output;
  EXPECT_EQ(nlohmann::json::parse(over.output)["v"], nlohmann::json::parse(spelt_over.output)["v"]);
}

// A field a problem does not read is refused, not ignored: the answer would be computed without it.
TEST(ImpactSolve, AFieldTheProblemDoesNotReadIsRefused)
{
  const std::string motion = R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0], )";
  const std::string cases[][2] = {
      {motion + R"("sliding_fricton": 0.2})", "sliding_fricton"},
      {motion + R"("cushion": {"restitution": 0.8}})", "cushion"},  // the cushion is the table's: table.cushion
      {R"({"problem": "ball_ball_table", "m2": 1, "stiffness_ratio": 1, "e1": 0.9, "e2": 0.7, "table_file": "x"})",
       "table_file"},
      {stroke(R"({"phi_deg": 0, "speed": 2})", R"(, "balls": [])"), "balls"},
      {R"({"problem": "plan_shot", "balls": [{"id": "cue", "position": [0, 0]}], "sample_spacing": 0.01})",
       "sample_spacing"},
      {R"({"problem": "calibrate", "shots": [], "fit": [], "cue_ball": "cue"})", "cue_ball"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find("invalid_argument: " + c[1] + ": is not a field of the problem"), std::string::npos)
        << c[0] << "\n"
        << run.output;
  }
}

// Inputs a review found mishandled: each is refused naming its field, or read as documented.
TEST(ImpactSolve, ConfigurationInputsAtTheEdgesAreRefusedOrRead)
{
  // Input nested 300 000 deep: refused before any reader copies it (a copy recurses once per level).
  for (const auto& [place, closing] : {std::pair{R"("cue_contact": {"law": {"type": )", "}}}"},
                                       std::pair{R"("table": {"cloth": {"law": {"x": )", "}}}}"}})
  {
    std::string deep = R"({"problem": "cue_strike", "cue": {"phi_deg": 0, "speed": 2}, )" + std::string(place);
    deep += std::string(300000, '[') + std::string(300000, ']') + closing;
    const SolverRun nested = runSolver(deep);
    EXPECT_EQ(nested.exit_code, 2) << nested.output.substr(0, 200);
    EXPECT_NE(nested.output.find("nests deeper than"), std::string::npos) << nested.output.substr(0, 200);
    EXPECT_LT(nested.output.size(), 400u);
  }
  const std::string strike = R"({"problem": "cue_strike", "cue": {"phi_deg": 0, "speed": 2}, )";
  const std::string snooker = R"("table_file": ")" + std::string(CONFIG_DIR) + R"(/tables/snooker_mathavan.yaml")";

  const std::string motion = R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0], )";
  const std::string drop = R"({"problem": "ball_table", "mass": 0.17, "radius": 0.0286, "velocity": [0, 0, -2], )";
  // A half-ball hit with spin: the throw's friction presses the balls into the cloth, whose stiffness then matters.
  const std::string collision = R"({"problem": "ball_ball", "balls": [{"position": [0, 0], "v": [1, 0, 0],
      "omega": [0, 35, 10]}, {"position": [0.0495366531, 0.0286]}], )";
  const std::string cases[][2] = {
      {motion + R"("table": {"cloth.friction": 0.5}})", "table.cloth.friction"},  // a key is a name, not a path
      {motion + R"("table_contact": {"friction": 0.5}})", "table_contact"},       // the strike's cloth: no strike here
      {motion + R"("cue_mass": 0.5})", "cue_mass"},
      {drop + R"("table": {"restitution": 0.9, "friction": 0, "eta2": 1, "law": {"yield_speed": 1}}})",
       "table.law.yield_speed"},  // under the constant law, as in every other problem
      {collision + R"("stiffness_ratio": 0.5, "ball_ball": {"cloth_stiffness_ratio": 0.5}})", "stiffness_ratio"},
      {collision + R"("ball_ball": {"cloth_stiffness_ratio": -1}})", "ball_ball.cloth_stiffness_ratio"},
      {strike + R"("cue_contact": {"law": {"type": [[1]]}}})", "cue_contact.law.type"},  // a type is a name
      {strike + R"("table": {"length": -5}})", "table.length"},  // a strike reads only the table's cloth
      {strike + R"("table_file": "/"})", "table_file"},          // a directory
      {strike + R"("table_file": "/dev/zero"})", "table_file"},  // a device without end
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find("invalid_argument: " + c[1] + ":"), std::string::npos) << c[0] << "\n" << run.output;
  }
  // table_contact's constants stand one by one over the table file's cloth (restitution 0.51625, friction 0.212).
  const SolverRun over_file = runSolver(strike + snooker + R"(, "table_contact": {"eta2": 8}})");
  const SolverRun spelt =
      runSolver(strike + R"("table_contact": {"restitution": 0.51625, "friction": 0.212, "eta2": 8}})");
  ASSERT_EQ(over_file.exit_code, 0) << over_file.output;
  ASSERT_EQ(spelt.exit_code, 0) << spelt.output;
  EXPECT_EQ(nlohmann::json::parse(over_file.output)["v"], nlohmann::json::parse(spelt.output)["v"]);
  // ball_ball's "cloth_stiffness_ratio" is the top-level "stiffness_ratio" given in the contact, as table files give
  // it.
  const SolverRun top = runSolver(collision + R"("stiffness_ratio": 0.5})");
  const SolverRun in_contact = runSolver(collision + R"("ball_ball": {"cloth_stiffness_ratio": 0.5}})");
  const SolverRun other = runSolver(collision + R"("stiffness_ratio": 5})");
  ASSERT_EQ(top.exit_code, 0) << top.output;
  ASSERT_EQ(in_contact.exit_code, 0) << in_contact.output;
  ASSERT_EQ(other.exit_code, 0) << other.output;
  EXPECT_EQ(nlohmann::json::parse(top.output)["balls"], nlohmann::json::parse(in_contact.output)["balls"]);
  EXPECT_NE(nlohmann::json::parse(top.output)["balls"], nlohmann::json::parse(other.output)["balls"]);
}

TEST(ImpactSolve, AConfigurationSectionOfTheWrongKindIsRefused)
{
  const std::string motion = R"({"problem": "ball_motion", "position": [0, 0], "v": [1, 0, 0], "omega": [0, 0, 0], )";
  const std::string cases[][2] = {
      {motion + R"("table": 3})", "table"},
      {motion + R"("table": {"cloth": [0.5, 0.2]}})", "table.cloth"},
      {motion + R"("planar": "yes"})", "planar"},
      {motion + R"("table": {"pockets": [{"centre": [0, 0, 1], "radius": 0.05}]}})", "table.pockets[0].centre"},
      {motion + R"("table": {"pockets": [{"centre": [0, 0]}]}})", "table.pockets[0].radius"},
      {motion + R"("table": {"pockets": [{"id": 4, "centre": [0, 0], "radius": 0.05}]}})", "table.pockets[0].id"},
      {motion + R"("table": {"corner_pockets": {"mouth": 0.05}}})", "table.corner_pockets.mouth"},  // below 2R
      {motion + R"("table": {"pockets": [{"centre": [0, 0], "radius": 0.05}, {"centre": [0.09, 0], "radius": 0.05}]}})",
       "table.pockets[1].centre"},  // overlapping capture regions
      {motion + R"("table": {"pockets": [{"id": "a", "centre": [0, 0], "radius": 0.05},
                                         {"id": "a", "centre": [1, 0], "radius": 0.05}]}})",
       "table.pockets[1].id"},
      {stroke(R"({"phi_deg": 0, "speed": 2})", R"(, "cue_contact": {"law": "elastic_plastic"})"), "cue_contact.law"},
      {stroke(R"({"phi_deg": 0, "speed": 2})", R"(, "cue_end_mass": "heavy")"), "cue_end_mass"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find("invalid_argument: " + c[1] + ":"), std::string::npos) << c[0] << "\n" << run.output;
  }
}

TEST(ImpactSolve, MeaninglessInputIsRefusedNotSolved)
{
  // Finite but absurd values must be refused: solved, they could come back as null (NaN) with exit 0, run out of
  // memory, or let energy rise.
  const std::string motion = R"({"problem": "ball_motion", "position": [0, 0], "omega": [0, 0, 0], )";
  const std::string cases[][2] = {
      {motion + R"("v": [1e308, 0, 0]})", "v"},
      {motion + R"("v": [1, 0, 0], "max_time": 1e12, "spinning_friction": 1e-12})", "max_time"},
      {motion + R"("v": [1, 0, 0], "table": {"cushion_stiffness_ratio": 2.19e-6}})", "cushion_stiffness_ratio"},
      {motion + R"("v": [1, 0, 0], "solver": {"absolute_tolerance": 1e-300}})", "solver.absolute_tolerance"},
      {motion + R"("v": [1, 0, 0], "solver": {"absolute_tolerance": 0.009}})", "solver.absolute_tolerance"},
      {motion + R"("v": [1, 0, 0], "solver": {"max_seconds": 1e9}})", "solver.max_seconds"},
      {stroke(R"({"phi_deg": 0, "speed": 1.797e308})"), "cue_speed"},
      {stroke(R"({"phi_deg": 0, "speed": 2})", R"(, "stiffness_ratio": 1e-6)"), "stiffness_ratio"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find(c[1]), std::string::npos) << c[0] << "\n" << run.output;
  }
}

TEST(ImpactSolve, WorkAndOutputAreBounded)
{
  // A spin that hardly decays, for the longest trajectory, sampled at the finest spacing: at most
  // BallTrajectory::MAX_SAMPLES spaced samples (plus the events), not 6 million.
  const SolverRun spin = runSolver(
      R"({"problem": "ball_motion", "position": [0, 0], "v": [0, 0, 0], "omega": [0, 0, 1],
          "spinning_friction": 1e-12, "max_time": 600, "sample_spacing": 1e-4})");
  ASSERT_EQ(spin.exit_code, 0) << spin.output;
  const auto s = nlohmann::json::parse(spin.output);
  EXPECT_EQ(s["outcome"], "time_limit");
  EXPECT_LE(s["samples"].size(), 20000u + s["events"].size());
  // A chain of 30 balls with masses over six decades collides for 30 000–150 000 events: it ends within its
  // wall-clock budget, solved or with time_limit_exceeded (exit 1), never after seconds of work.
  nlohmann::json chain{{"problem", "chain"}, {"wall", false}, {"solver", {{"max_seconds", 0.2}}}};
  std::vector<double> masses, velocities(30, 0.0), stiffness(29, 1.0), restitution(29, 0.9);
  for (int k = 0; k < 30; ++k)
    masses.push_back(k % 2 == 0 ? 1e3 : 1e-3);
  velocities[0] = 1.0;
  chain["masses"] = masses;
  chain["velocities"] = velocities;
  chain["stiffness"] = stiffness;
  chain["restitution"] = restitution;
  const SolverRun run = runSolver(chain.dump());
  if (run.exit_code != 0)
  {
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("time_limit_exceeded"), std::string::npos) << run.output;
  }
}

TEST(ImpactSolve, BallBallHeadOnStunShot)
{
  // Equal balls, the cue ball sliding without spin at 2 m/s into a resting ball: (1 ± e)/2 · V, the cloth idle.
  const SolverRun run = runSolver(
      R"({"problem": "ball_ball", "balls": [{"position": [0, 0], "v": [2, 0, 0], "omega": [0, 0, 0]},
                                            {"position": [0.0572, 0]}],
          "ball_ball": {"restitution": 0.9, "friction": 0.06, "eta2": 1.2},
          "cloth": {"restitution": 0.5, "friction": 0.2, "eta2": 10},
          "ball_mass": 0.17, "ball_radius": 0.0286, "stiffness_ratio": 0.1})");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  ASSERT_EQ(out["balls"].size(), 2u);
  EXPECT_NEAR(out["balls"][0]["v"][0].get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(out["balls"][1]["v"][0].get<double>(), 1.9, 1e-9);
  ASSERT_EQ(out["contacts"].size(), 3u);  // the pair, then each ball's cloth
  EXPECT_EQ(out["contacts"][0]["name"], "ball0-ball1");
  EXPECT_EQ(out["contacts"][0]["friction"], 0.06);
  EXPECT_NEAR(out["contacts"][0]["impulse"]["normal"].get<double>(), 0.17 * 1.9, 1e-9);
  EXPECT_EQ(out["contacts"][2]["name"], "ball1-cloth");
  EXPECT_EQ(out["states"].front(), (std::vector<int>{0}));
  EXPECT_TRUE(out["states"].back().empty());
  EXPECT_NEAR(out["energy"]["lost"].get<double>(), 0.5 * 0.17 * 4.0 * (1.0 - 0.81) / 2.0, 1e-9);
  EXPECT_FALSE(out["events"].empty());
}

TEST(ImpactSolve, BallBallCutShotWithAlciatoreFriction)
{
  // A half-ball stun hit at 1 m/s with the defaults and Alciatore's μ(v) at the slip speed V sin 30°: the pair's
  // friction is reported, and the object ball is thrown by atan(min(μ, 2 tan φ/(7(1 + e)))) (the rigid limit, which
  // the compliant contact meets where it slips throughout, as here).
  const double cut = M_PI / 6.0;
  nlohmann::json request{
      {"problem", "ball_ball"},
      {"balls",
       {{{"position", {0, 0}}, {"v", {1, 0, 0}}}, {{"position", {0.0572 * std::cos(cut), 0.0572 * std::sin(cut)}}}}},
      {"ball_ball", {{"friction_model", "alciatore"}}}};
  const SolverRun run = runSolver(request.dump());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  const double mu = 9.951e-3 + 0.108 * std::exp(-1.088 * 0.5);
  EXPECT_NEAR(out["contacts"][0]["friction"].get<double>(), mu, 1e-12);
  const auto v = out["balls"][1]["v"].get<std::vector<double>>();
  const double along = v[0] * std::cos(cut) + v[1] * std::sin(cut);
  const double across = v[0] * std::sin(cut) - v[1] * std::cos(cut);
  EXPECT_NEAR(std::atan2(across, along), std::atan(std::min(mu, 2.0 * std::tan(cut) / (7.0 * 1.95))), 1e-9);
}

TEST(ImpactSolve, BallBallBadInputNamesTheField)
{
  const std::string two = R"("balls": [{"position": [0, 0], "v": [1, 0, 0]}, {"position": [0.0572, 0]}])";
  const std::string cases[][2] = {
      {R"({"problem": "ball_ball", "balls": [{"position": [0, 0], "v": [1, 0, 0]}]})", "balls"},
      {R"({"problem": "ball_ball"})", "balls"},
      {R"({"problem": "ball_ball", "balls": [{"position": [0, 0]}, {"position": [0.05, 0], "v": [-1, 0, 0]}]})",
       "balls[1].position"},
      {R"({"problem": "ball_ball", "balls": [{"position": [0, 0, 0]}, {"position": [0.0572, 0]}]})",
       "balls[0].position"},
      {R"({"problem": "ball_ball", "balls": [{"position": [0, 0], "v": [1, 0]}, {"position": [0.0572, 0]}]})",
       "balls[0].v"},
      {R"({"problem": "ball_ball", "balls": [{"position": [0, 0], "omega": [1e9, 0, 0]}, {"position": [0.0572, 0]}]})",
       "balls[0].omega"},
      {R"({"problem": "ball_ball", )" + two + R"(, "ball_ball": {"eta2": -1}})", "ball_ball.eta2"},
      {R"({"problem": "ball_ball", )" + two + R"(, "ball_ball": {"friction": 0.1, "friction_model": "alciatore"}})",
       "ball_ball.friction_model"},
      {R"({"problem": "ball_ball", )" + two + R"(, "cloth": {"friction": "high"}})", "cloth.friction"},
      {R"({"problem": "ball_ball", )" + two + R"(, "stiffness_ratio": 1e-5})", "stiffness_ratio"},
      {R"({"problem": "ball_ball", "balls": [{"position": [0, 0], "v": [1, 0, 0]}, {"position": [0.1, 0]}]})",
       "no two balls touch"},
  };
  for (const auto& c : cases)
  {
    const SolverRun run = runSolver(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0] << "\n" << run.output;
    EXPECT_NE(run.output.find(c[1]), std::string::npos) << c[0] << "\n" << run.output;
  }
}

namespace
{
/// A table_shot along the diagonal towards the (+x, +y) corner pocket: cue ball at 0.1 (2, 1), object ball "one"
/// at 0.4 (2, 1), both on the line through the pocket's centre 0.635 (2, 1); a level centre hit at 2 m/s.
nlohmann::json straightInShot()
{
  auto shot = nlohmann::json::parse(stroke(R"({"phi_deg": 26.56505117707799, "theta_deg": 0, "speed": 2})"));
  shot["problem"] = "table_shot";
  shot["balls"] =
      nlohmann::json::parse(R"([{"id": "cue", "position": [0.2, 0.1]}, {"id": "one", "position": [0.8, 0.4]}])");
  return shot;
}
}  // namespace

// A straight-in shot: the cue ball's first contact is the object ball, which leaves along the line of centres
// (no throw without cut or side spin: it stays on the diagonal to 1e-9 m until the pocket's jaw) and drops in the
// corner pocket.
TEST(ImpactSolve, TableShotPotsAStraightInBall)
{
  const SolverRun run = runSolver(straightInShot().dump());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  EXPECT_EQ(out["first_contact"], "one");
  ASSERT_FALSE(out["collisions"].empty());
  EXPECT_EQ(out["collisions"][0]["balls"], (std::vector<std::string>{"cue", "one"}));
  const auto& one = out["balls"][1];
  EXPECT_EQ(one["id"], "one");
  EXPECT_EQ(one["outcome"], "pocketed");
  const auto pocketed = std::find_if(out["pocketed"].begin(), out["pocketed"].end(),
                                     [](const nlohmann::json& p) { return p["id"] == "one"; });
  ASSERT_NE(pocketed, out["pocketed"].end());
  for (const auto& event : one["events"])
  {
    if (event["type"] == "cushion_hit")
      break;  // the pocket's jaw: the corner's cushions reach into its capture circle
    const double x = event["position"][0].get<double>(), y = event["position"][1].get<double>();
    EXPECT_NEAR(y, 0.5 * x, 1e-9) << event["type"];
  }
  EXPECT_TRUE(out["strike"].contains("v"));
  EXPECT_GT(out["duration"].get<double>(), 0.0);
  EXPECT_FALSE(one.contains("samples"));
}

// The same shot with the cue ball frozen to the object ball (2R apart on the diagonal): the strike is one impact with
// the ball it touches, and the answer's strike names its contacts, the ball it moved and the touching pair; the lone
// shot's strike has only the cue's and the cloth's contacts.
TEST(ImpactSolve, TableShotStrikesAFrozenBallWithTheCueBall)
{
  auto frozen = straightInShot();
  const double two_r = 2.0 * 0.028575;  // the stroke's ball_radius
  frozen["balls"][1]["position"] = {0.2 + two_r * 2.0 / std::sqrt(5.0), 0.1 + two_r / std::sqrt(5.0)};
  const SolverRun run = runSolver(frozen.dump());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto strike = nlohmann::json::parse(run.output)["strike"];
  std::vector<std::string> names;
  for (const auto& contact : strike["contacts"])
    names.push_back(contact["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"tip-cue", "cue-one", "cue-cloth", "one-cloth"}));
  ASSERT_EQ(strike["other_balls"].size(), 1u);
  EXPECT_EQ(strike["other_balls"][0]["id"], "one");
  EXPECT_GT(strike["other_balls"][0]["v"][0].get<double>(), 0.0);
  EXPECT_EQ(strike["touching"], nlohmann::json::parse(R"([["cue", "one"]])"));
  const auto lone = nlohmann::json::parse(runSolver(straightInShot().dump()).output)["strike"];
  ASSERT_EQ(lone["contacts"].size(), 2u);
  EXPECT_EQ(lone["contacts"][0]["name"], "cue-ball");
  EXPECT_TRUE(lone["other_balls"].empty());
  EXPECT_TRUE(lone["touching"].empty());
}

// With "samples": true every ball is sampled at the same instants k·sample_spacing (plus its own events).
TEST(ImpactSolve, TableShotSamplesEveryBallAtTheSameTimes)
{
  auto shot = straightInShot();
  shot["samples"] = true;
  shot["sample_spacing"] = 0.05;
  const SolverRun run = runSolver(shot.dump());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  for (const auto& ball : out["balls"])
  {
    std::vector<double> times;
    for (const auto& sample : ball["samples"])
      times.push_back(sample["t"].get<double>());
    for (double t = 0.0; t < out["duration"].get<double>(); t += 0.05)
      EXPECT_TRUE(std::any_of(times.begin(), times.end(), [&](double s) { return std::abs(s - t) < 1e-9; }))
          << ball["id"] << " t " << t;
  }
}

TEST(ImpactSolve, TableShotBadInputNamesTheBall)
{
  auto expectField = [](nlohmann::json shot, const std::string& field)
  {
    const SolverRun run = runSolver(shot.dump());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(field), std::string::npos) << run.output;
  };
  auto duplicate = straightInShot();
  duplicate["balls"][1]["id"] = "cue";
  expectField(duplicate, "balls[1].id");
  auto overlap = straightInShot();
  overlap["balls"][1]["position"] = {0.21, 0.1};
  expectField(overlap, "balls[1].position");
  auto pocket = straightInShot();
  pocket["balls"][1]["position"] = {1.26, 0.63};
  expectField(pocket, "balls[1].position");
  auto unknown = straightInShot();
  unknown["cue_ball"] = "white";
  expectField(unknown, "cue_ball");
  auto nan = straightInShot();
  nan["balls"][1]["position"] = {"x", 0.4};
  expectField(nan, "balls[1].position");
  auto no_id = straightInShot();
  no_id["balls"][1].erase("id");
  expectField(no_id, "balls[1].id");
  auto friction = straightInShot();
  friction["ball_ball"] = {{"friction_model", "magic"}};
  expectField(friction, "ball_ball.friction_model");
}

namespace
{
/// plan_shot on the straight-in layout of straightInShot, with a third ball elsewhere.
nlohmann::json planRequest()
{
  auto request = straightInShot();
  request.erase("cue");
  request["problem"] = "plan_shot";
  request["balls"].push_back({{"id", "two"}, {"position", {-0.5, -0.3}}});
  request["budget_ms"] = 2000;
  request["seed"] = 7;
  return request;
}
}  // namespace

// The plan pots: replayed as a table_shot from the answer's own cue, the target drops in the answer's pocket and
// the cue ball stays on the table; the answer carries every field other tools read.
TEST(ImpactSolve, PlanShotAnswersAShotThatPotsWhenReplayed)
{
  const SolverRun run = runSolver(planRequest().dump());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto plan = nlohmann::json::parse(run.output);
  ASSERT_TRUE(plan["found"].get<bool>());
  for (const char* key : {"target", "pocket", "cue", "cue_pose", "success_probability", "confidence_interval",
                          "evaluations", "time_ms", "outcome", "alternatives"})
    EXPECT_TRUE(plan.contains(key)) << key;
  const double p = plan["success_probability"].get<double>();
  EXPECT_GE(p, plan["confidence_interval"][0].get<double>());
  EXPECT_LE(p, plan["confidence_interval"][1].get<double>());
  auto replay = straightInShot();
  replay["balls"].push_back({{"id", "two"}, {"position", {-0.5, -0.3}}});
  replay["cue"] = plan["cue"];
  const SolverRun shot = runSolver(replay.dump());
  ASSERT_EQ(shot.exit_code, 0) << shot.output;
  const auto out = nlohmann::json::parse(shot.output);
  const std::string target = plan["target"];
  for (const auto& ball : out["balls"])
  {
    if (ball["id"] == target)
    {
      EXPECT_EQ(ball["pocket"], plan["pocket"]);
    }
    if (ball["id"] == "cue")
    {
      EXPECT_NE(ball["outcome"], "pocketed");
    }
  }
}

TEST(ImpactSolve, PlanShotBadInputNamesTheField)
{
  auto expectField = [](nlohmann::json request, const std::string& field)
  {
    const SolverRun run = runSolver(request.dump());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(field), std::string::npos) << run.output;
  };
  auto target = planRequest();
  target["target"] = "seven";
  expectField(target, "target");
  auto pocket = planRequest();
  pocket["pocket"] = "pocket9";
  expectField(pocket, "pocket");
  pocket["pocket"] = 3;  // an index, as before the pockets had ids
  expectField(pocket, "pocket");
  auto speed = planRequest();
  speed["limits"] = {{"speed", {3, 2}}};
  expectField(speed, "limits.speed");
  auto theta = planRequest();
  theta["limits"] = {{"theta_deg", {10, 95}}};
  expectField(theta, "limits.theta_deg");
  auto noise = planRequest();
  noise["noise"] = {{"phi_deg", -0.1}};
  expectField(noise, "noise.phi_deg");
  auto budget = planRequest();
  budget["budget_ms"] = 0;
  expectField(budget, "budget_ms");
  auto in_pocket = planRequest();
  in_pocket["balls"][0]["position"] = {1.26, 0.63};
  expectField(in_pocket, "balls[0].position");
  auto nan = planRequest();
  nan["balls"][1]["position"] = {"x", 0.4};
  expectField(nan, "balls[1].position");
  auto seed = planRequest();
  seed["seed"] = -1;
  expectField(seed, "seed");
}

namespace
{
/// A table_shot of the white ball alone, tracked at 30 Hz from its samples for up to 3 s: [[t, x, y], …].
nlohmann::json trackedShot(const nlohmann::json& cue, const std::vector<double>& position, double sliding_friction)
{
  auto shot = nlohmann::json::parse(stroke(cue.dump()));
  shot["problem"] = "table_shot";
  shot["balls"] = {{{"id", "white"}, {"position", position}}};
  shot["cue_ball"] = "white";
  shot["sliding_friction"] = sliding_friction;
  shot["rolling_friction"] = 0.015;
  shot["samples"] = true;
  shot["sample_spacing"] = 1.0 / 30.0;
  const SolverRun run = runSolver(shot.dump());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  nlohmann::json track = nlohmann::json::array();
  for (const auto& sample : out["balls"][0]["samples"])
    if (sample["t"].get<double>() <= 3.0)
      track.push_back({sample["t"], sample["position"][0], sample["position"][1]});
  return {{"balls", shot["balls"]}, {"cue_ball", "white"}, {"cue", cue}, {"tracks", {{"white", track}}}};
}

nlohmann::json calibrateRequest()
{
  auto request = nlohmann::json::parse(stroke("{}"));
  request.erase("cue");
  request["problem"] = "calibrate";
  request["shots"] = {trackedShot({{"phi_deg", 10}, {"theta_deg", 5}, {"speed", 2.0}, {"b", 0.3}}, {-0.6, 0.0}, 0.2),
                      trackedShot({{"phi_deg", 100}, {"theta_deg", 5}, {"speed", 1.8}, {"b", -0.3}}, {0.3, -0.3}, 0.2)};
  request["fit"] = {"motion/sliding_friction", "motion/rolling_friction"};
  return request;
}
}  // namespace

// Tracks sampled by table_shot under μ_s = 0.2, μ_r = 0.015 (not the defaults): calibrate recovers both from the
// defaults, and its overlay is a parameter file that says so.
TEST(ImpactSolve, CalibrateRecoversTheFrictionThatDrewTableShotTracks)
{
  const SolverRun run = runSolver(calibrateRequest().dump());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto out = nlohmann::json::parse(run.output);
  EXPECT_TRUE(out["converged"].get<bool>()) << out["message"];
  const auto& sliding = out["parameters"]["motion/sliding_friction"];
  const auto& rolling = out["parameters"]["motion/rolling_friction"];
  EXPECT_TRUE(sliding["identifiable"].get<bool>());
  EXPECT_NEAR(sliding["value"].get<double>(), 0.2, 1e-6);
  EXPECT_NEAR(rolling["value"].get<double>(), 0.015, 1e-6);
  EXPECT_GT(sliding["sigma"].get<double>(), 0.0);
  ASSERT_EQ(out["residuals"].size(), 2u);
  for (const auto& rms : out["residuals"])
    EXPECT_LT(rms.get<double>(), 1e-6);  // noise-free tracks: the fitted paths go through them
  EXPECT_EQ(out["correlation"].size(), 2u);
  const YAML::Node overlay = YAML::Load(out["overlay_yaml"].get<std::string>());
  // Ten significant digits.
  EXPECT_NEAR(overlay["motion"]["sliding_friction"].as<double>(), sliding["value"].get<double>(), 1e-10);
}

TEST(ImpactSolve, CalibrateBadInputNamesTheObservation)
{
  auto expectField = [](nlohmann::json request, const std::string& field)
  {
    const SolverRun run = runSolver(request.dump());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(field), std::string::npos) << field << ": " << run.output;
  };
  const nlohmann::json good = calibrateRequest();
  auto bad = good;
  bad["shots"][1]["tracks"]["white"][4][0] = -1.0;
  expectField(bad, "shots[1].tracks.white[4].t");
  bad = good;
  std::swap(bad["shots"][0]["tracks"]["white"][2], bad["shots"][0]["tracks"]["white"][3]);
  expectField(bad, "shots[0].tracks.white[3].t");
  bad = good;
  bad["shots"][0]["tracks"]["white"][2] = {0.1, "x", 0.2};
  expectField(bad, "shots[0].tracks.white[2]");
  bad = good;
  bad["shots"][0]["tracks"]["seven"] = nlohmann::json::array({{0.0, 0.1, 0.1}});
  expectField(bad, "shots[0].tracks.seven");
  bad = good;
  bad["shots"][0].erase("cue");
  expectField(bad, "shots[0].cue");
  bad = good;
  // A ball listed before the cue ball overlapping it: the core's others[0] is the request's balls[0].
  bad["shots"][0]["balls"] = {{{"id", "seven"}, {"position", {-0.6, 0.03}}}, good["shots"][0]["balls"][0]};
  expectField(bad, "shots[0].balls[0].position");
  bad = good;
  bad["fit"] = {"motion/colour"};
  expectField(bad, "fit[0]");
  bad = good;
  bad["fit"] = nlohmann::json::array({{{"name", "motion/sliding_friction"}, {"lower", 0.5}, {"upper", 0.1}}});
  expectField(bad, "motion/sliding_friction");
  bad = good;
  bad["position_noise"] = 0.0;
  expectField(bad, "position_noise");
  bad = good;
  bad["shots"] = nlohmann::json::array({good["shots"][0]});
  bad["shots"][0]["tracks"]["white"] = nlohmann::json::array({{0.0, -0.6, 0.0}});
  bad["fit"] = {"motion/sliding_friction", "motion/rolling_friction", "table/cushion/restitution"};
  expectField(bad, "shots");
  bad = good;
  bad["budget_ms"] = -1;
  expectField(bad, "budget_ms");
  // The core's bounds of the fit's options (validate(FitOptions)), named in the request's terms.
  for (const auto& [key, value] : {std::pair{"starts", 2.5}, std::pair{"starts", 10001.0}, std::pair{"threads", 65.0},
                                   std::pair{"robust_loss_sigmas", -1.0}, std::pair{"budget_ms", 3.6e6 + 1}})
  {
    bad = good;
    bad[key] = value;
    const SolverRun run = runSolver(bad.dump());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(std::string("invalid_argument: ") + key + ":"), std::string::npos) << run.output;
  }
}

TEST(ImpactSolve, UnderTheJawsAHopFromAPocketsMouthMeetsTheJawNotTheInsideOfTheRail)
{
  // Balls struck from a corner pocket's mouth, on the touching lines of both rails, hop along a rail. Each first
  // meets the jaw's point it runs at (the rail's line beyond its end, touched at the start, is no contact and hides
  // none): the one along the right rail comes back onto the table and rests there; the one jumped off the bottom
  // rail's jaw flies over the right rail later and leaves the table, rather than dropping in the side pocket's
  // region from 27 cm up beyond the rails.
  const double x = 1.2424890021991204, y = 0.6074890021991205;
  auto shot = [](double px, double py, const nlohmann::json& cue, const nlohmann::json& table)
  {
    nlohmann::json request = nlohmann::json::parse(
        R"({"problem": "table_shot", "cue_mass": 0.54, "ball_mass": 0.17, "ball_radius": 0.028575,
            "cue_contact": {"restitution": 0.75, "friction": 0.7, "eta2": 1.2},
            "table_contact": {"restitution": 0.5, "friction": 0.2, "eta2": 10}, "stiffness_ratio": 0.8})");
    request["balls"] = {{{"id", "cue"}, {"position", {px, py}}}};
    request["cue"] = cue;
    request["table"] = table;
    const SolverRun run = runSolver(request.dump());
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return run.exit_code == 0 ? nlohmann::json::parse(run.output)["balls"][0] : nlohmann::json{};
  };
  const auto along_rail =
      shot(x, y, {{"phi_deg", -89.874013}, {"theta_deg", 8.714}, {"speed", 6}}, {{"pocket_model", "jaws"}});
  ASSERT_GE(along_rail["events"].size(), 2u);
  EXPECT_EQ(along_rail["events"][1]["type"], "cushion_hit");
  EXPECT_EQ(along_rail["events"][1]["cushion"], "pocket.top_right.jaw.right.point");
  EXPECT_EQ(along_rail["outcome"], "rest");
  const auto jumped =
      shot(-x, -y, {{"phi_deg", -4.964226}, {"theta_deg", 40.3314}, {"speed", 7.7796}, {"a", 0.1893}, {"b", 0.2156}},
           {{"pocket_model", "jaws"}, {"cushion", {{"restitution", 0.6673}, {"friction", 0.1086}}}});
  ASSERT_GE(jumped["events"].size(), 2u);
  EXPECT_EQ(jumped["events"][1]["type"], "cushion_hit");
  EXPECT_EQ(jumped["events"][1]["cushion"], "pocket.bottom_left.jaw.bottom.point");
  EXPECT_EQ(jumped["outcome"], "off_table");
}
