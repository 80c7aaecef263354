// Asks the shot predictor what a follow shot does and prints the answer: the C++ twin of
// predict_shot_example.py. The cue is level and points along the table's x axis; its tip touches the cue ball
// 1 cm above the ball's centre. Run it beside the node:
//
//   roslaunch billiard_shot_planner predict_shot.launch
//   rosrun billiard_shot_planner predict_shot_example [speed in m/s, default 2.0]
//
// Exits 0 when the node answered the shot, 1 when it refused it (the reason is printed), 2 when no node answered.
#include <billiard_shot_planner/PredictShot.h>
#include <ros/ros.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
constexpr double BALL_RADIUS = 0.0286;  // m, the node's default ball
const std::string SERVICE = "/shot_predictor/predict_shot";

/// A level cue along +x, its tip 1 cm above the centre of a ball at (-0.6, -0.2) in the table frame.
billiard_shot_planner::PredictShot::Request followShot(double speed)
{
  billiard_shot_planner::PredictShot::Request request;
  const double ball_x = -0.6;
  const double ball_y = -0.2;
  const double height = 0.01;  // m above the centre: a follow shot
  request.ball_position.header.frame_id = "table";
  request.ball_position.point.x = ball_x;
  request.ball_position.point.y = ball_y;
  request.ball_position.point.z = BALL_RADIUS;
  request.cue_pose.header.frame_id = "table";
  // The tip sits on the ball's surface: its distance from the centre along -x makes the hit point exact.
  request.cue_pose.pose.position.x = ball_x - std::sqrt(BALL_RADIUS * BALL_RADIUS - height * height);
  request.cue_pose.pose.position.y = ball_y;
  request.cue_pose.pose.position.z = BALL_RADIUS + height;
  request.cue_pose.pose.orientation.w = 1.0;  // the cue frame's x axis along the table's x axis
  request.cue_speed = speed;
  return request;
}

void printAnswer(const billiard_shot_planner::PredictShot::Response& response)
{
  std::printf("success: %s\n", response.success ? "True" : "False");
  if (!response.success)
  {
    std::printf("message: %s\n", response.message.c_str());
    return;
  }
  const auto& v = response.ball_velocity;
  const auto& w = response.ball_angular_velocity;
  std::printf("ball_velocity: %.6f %.6f %.6f\n", v.x, v.y, v.z);
  std::printf("ball_angular_velocity: %.6f %.6f %.6f\n", w.x, w.y, w.z);
  std::printf("states:");
  for (const std::string& state : response.states)
    std::printf(" %s", state.c_str());
  std::printf("\noutcome: %s\n", response.prediction.outcome.c_str());
  const auto& p = response.prediction.final_position;
  std::printf("final_position: %.6f %.6f %.6f\n", p.x, p.y, p.z);
  std::printf("duration: %.6f\n", response.prediction.duration);
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "predict_shot_example", ros::init_options::AnonymousName);
  const double speed = argc > 1 ? std::atof(argv[1]) : 2.0;
  if (!ros::service::waitForService(SERVICE, ros::Duration(30.0)))
  {
    std::fprintf(stderr, "no answer from %s\n", SERVICE.c_str());
    return 2;
  }
  billiard_shot_planner::PredictShot service;
  service.request = followShot(speed);
  if (!ros::service::call(SERVICE, service))
  {
    std::fprintf(stderr, "the call to %s failed\n", SERVICE.c_str());
    return 2;
  }
  printAnswer(service.response);
  return service.response.success ? 0 : 1;
}
