// A downstream user of the installed core and io libraries: a level cue through the ball's centre must give the
// central-impact velocity (1 + e) M V / (M + m) along the cue and no spin, the classical answer; a table read from
// the installed config/table_9ft.yaml must keep its length. Exits 0 when both hold.
#include <billiard_shot_planner/io/table_yaml.hpp>
#include <billiard_shot_planner/shot/shot_prediction.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace bsp = billiard_shot_planner;

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: downstream_shot <installed table_9ft.yaml>\n");
    return 2;
  }
  const bsp::ShotConfiguration configuration;
  bsp::CuePlacement cue;
  cue.ball = Eigen::Vector2d(0.0, 0.0);
  cue.tip = Eigen::Vector3d(-configuration.ball_radius, 0.0, configuration.ball_radius);
  cue.direction = Eigen::Vector3d::UnitX();
  cue.speed = 2.0;
  const auto outcome = bsp::predictShot(cue, configuration);
  if (!outcome)
  {
    std::fprintf(stderr, "predictShot: %s\n", outcome.error().describe().c_str());
    return 1;
  }
  const double M = configuration.cue_mass, m = configuration.ball_mass, e = configuration.cue_contact.restitution;
  const double expected = (1.0 + e) * M * cue.speed / (M + m);
  const Eigen::Vector3d v = outcome.value().strike.velocity;
  std::printf("ball velocity %.9f %.9f %.9f (central impact: %.9f)\n", v.x(), v.y(), v.z(), expected);
  const bool central = std::abs(v.x() - expected) < 1e-9 && v.tail<2>().norm() < 1e-9 &&
                       outcome.value().strike.angular_velocity.norm() < 1e-6;
  const auto table = bsp::loadTableYaml(argv[1]);
  if (!table)
  {
    std::fprintf(stderr, "loadTableYaml: %s\n", table.error().describe().c_str());
    return 1;
  }
  std::printf("table length %.4f m\n", table.value().length);
  return central && table.value().length > 2.0 ? 0 : 1;
}
