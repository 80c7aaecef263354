// The impact_solve program: JSON in, JSON out, exit code 2 with a message on bad input.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
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
