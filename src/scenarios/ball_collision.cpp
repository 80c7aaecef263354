#include "billiard_shot_planner/scenarios/ball_collision.hpp"

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"

namespace billiard_shot_planner
{
namespace
{
using Rows = Eigen::Matrix<double, 3, 6>;

std::string ballField(std::size_t i, const char* field)
{
  return "balls[" + std::to_string(i) + "]." + field;
}

Eigen::Vector3d centre(const BallCollision& c, std::size_t i)
{
  return {c.balls[i].position.x(), c.balls[i].position.y(), c.ball_radius + c.balls[i].height};
}

bool onCloth(const BallCollision& c, std::size_t i)
{
  return c.balls[i].height <= c.touching_tolerance;
}

Eigen::Matrix<double, 6, 1> ballVelocity(const CollidingBall& ball)
{
  return (Eigen::Matrix<double, 6, 1>() << ball.velocity, ball.angular_velocity).finished();
}

Status checkBall(const CollidingBall& ball, std::size_t i, double radius)
{
  return firstError({requireFinite(ball.position, ballField(i, "position")),
                     requireFinite(ball.velocity, ballField(i, "velocity")),
                     requireFinite(ball.angular_velocity, ballField(i, "angular_velocity")),
                     requirePlausibleSpeed(ball.velocity.norm(), ballField(i, "velocity")),
                     requirePlausibleSpeed(ball.angular_velocity.norm() * radius, ballField(i, "angular_velocity")),
                     requireNonNegative(ball.height, ballField(i, "height"))});
}

Status checkOverlaps(const BallCollision& c)
{
  const double closest = 2.0 * c.ball_radius - c.touching_tolerance;
  for (std::size_t a = 1; a < c.balls.size(); ++a)
    for (std::size_t b = 0; b < a; ++b)
    {
      const double distance = (centre(c, a) - centre(c, b)).norm();
      if (distance < closest)
        return invalidArgument(ballField(a, "position"),
                               "overlaps balls[" + std::to_string(b) + "]: the centres are " + formatNumber(distance) +
                                   " m apart, less than 2 ball_radius − touching_tolerance = " + formatNumber(closest) +
                                   " m");
    }
  return {};
}

/// Rows of the velocity of ball a's surface relative to ball b's at their contact point, in the contact frame
/// with the normal from b's centre to a's: one 3×6 block on each ball's (v, ω).
std::pair<Rows, Rows> pairRows(const BallCollision& c, const TouchingPair& pair)
{
  const Eigen::Vector3d normal = (centre(c, pair.a) - centre(c, pair.b)).normalized();
  const Eigen::Matrix3d frame = contactFrame(normal);
  return {pointVelocityRows(frame, -c.ball_radius * normal), -pointVelocityRows(frame, c.ball_radius * normal)};
}

double pairFriction(const BallCollision& c, const TouchingPair& pair)
{
  if (c.friction_model == BallBallFriction::Constant)
    return c.ball_ball.friction;
  const auto [rows_a, rows_b] = pairRows(c, pair);
  const Eigen::Vector3d relative = rows_a * ballVelocity(c.balls[pair.a]) + rows_b * ballVelocity(c.balls[pair.b]);
  return alciatoreFriction(relative.head<2>().norm());
}

/// The balls as free solid spheres: 6 coordinates (v, ω) each.
ImpactProblem ballsProblem(const BallCollision& c)
{
  const auto n = static_cast<Eigen::Index>(c.balls.size());
  const double inertia = 0.4 * c.ball_mass * c.ball_radius * c.ball_radius;
  Eigen::VectorXd masses(6 * n);
  ImpactProblem problem;
  problem.velocity.resize(6 * n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    masses.segment<6>(6 * i) << c.ball_mass, c.ball_mass, c.ball_mass, inertia, inertia, inertia;
    problem.velocity.segment<6>(6 * i) = ballVelocity(c.balls[static_cast<std::size_t>(i)]);
  }
  problem.mass_matrix = masses.asDiagonal();
  return problem;
}

Contact pairContact(const BallCollision& c, const TouchingPair& pair, Eigen::Index coordinates)
{
  const auto [rows_a, rows_b] = pairRows(c, pair);
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(3, coordinates);
  rows.block<3, 6>(0, 6 * static_cast<Eigen::Index>(pair.a)) = rows_a;
  rows.block<3, 6>(0, 6 * static_cast<Eigen::Index>(pair.b)) = rows_b;
  SurfaceContact surface = c.ball_ball;
  surface.friction = pair.friction;
  const std::string name = ballName(c, pair.b) + "-" + ballName(c, pair.a);
  return makeContact(name.c_str(), rows, contactLaw(surface, 1.0));
}

Contact clothContact(const BallCollision& c, std::size_t ball, Eigen::Index coordinates)
{
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(3, coordinates);
  rows.block<3, 6>(0, 6 * static_cast<Eigen::Index>(ball)) = clothContactRows(c.ball_radius);
  const std::string name = ballName(c, ball) + "-cloth";
  return makeContact(name.c_str(), rows, contactLaw(c.cloth, c.stiffness_ratio));
}

Contact cushionContact(const BallCollision& c, const CushionTouch& touch, Eigen::Index coordinates)
{
  // The ball is body A, the fixed cushion B: the contact point is at −R n̂ from the centre.
  const Eigen::Vector3d normal = touch.normal.normalized();
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(3, coordinates);
  rows.block<3, 6>(0, 6 * static_cast<Eigen::Index>(touch.ball)) =
      pointVelocityRows(contactFrame(normal), -c.ball_radius * normal);
  const std::string name = ballName(c, touch.ball) + "-" + touch.id;
  return makeContact(name.c_str(), rows, contactLaw(c.cushion, c.stiffness_ratio * c.cushion_stiffness_ratio));
}

Status checkCushions(const BallCollision& c)
{
  for (std::size_t k = 0; k < c.cushions.size(); ++k)
  {
    const std::string field = "cushions[" + std::to_string(k) + "]";
    if (c.cushions[k].ball >= c.balls.size())
      return invalidArgument(field + ".ball", "names no ball: there are " + std::to_string(c.balls.size()));
    if (Status status = requireFinite(c.cushions[k].normal, field + ".normal"); !status)
      return status;
    if (!(c.cushions[k].normal.norm() > 0.0))
      return invalidArgument(field + ".normal", "must not be zero");
  }
  return firstError(
      {validate(c.cushion, "cushion"), requireStiffnessRatio(c.cushion_stiffness_ratio, "cushion_stiffness_ratio")});
}

bool anyContactApproaches(const ImpactProblem& problem)
{
  for (const Contact& contact : problem.contacts)
    if (contact.normal.dot(problem.velocity) < 0.0)
      return true;
  return false;
}

/// The bodies and their contacts, nothing checked but the fields.
BallCollisionBodies assembleBodies(const BallCollision& c)
{
  BallCollisionBodies bodies{ballsProblem(c), touchingPairs(c), {}};
  ImpactProblem& problem = bodies.problem;
  const Eigen::Index coordinates = problem.velocity.size();
  for (const TouchingPair& pair : bodies.pairs)
    problem.contacts.push_back(pairContact(c, pair, coordinates));
  for (std::size_t i = 0; i < c.balls.size(); ++i)
  {
    const bool on_cloth = onCloth(c, i);
    bodies.cloth_contacts.push_back(on_cloth ? problem.contacts.size() : BallCollisionResult::NO_CLOTH_CONTACT);
    if (on_cloth)
      problem.contacts.push_back(clothContact(c, i, coordinates));
  }
  for (const CushionTouch& touch : c.cushions)
    problem.contacts.push_back(cushionContact(c, touch, coordinates));
  return bodies;
}

Expected<BallCollisionBodies> configure(const BallCollision& c)
{
  if (Status status = validate(c); !status)
    return status.error();
  BallCollisionBodies bodies = assembleBodies(c);
  if (bodies.pairs.empty())
    return Error{ErrorKind::NoApproachingContact, "balls",
                 "no two balls touch (centres within 2 ball_radius + touching_tolerance): there is no collision"};
  if (!anyContactApproaches(bodies.problem))
    return Error{ErrorKind::NoApproachingContact, "balls",
                 "no touching pair approaches and no ball moves into the cloth or a cushion: there is no collision"};
  return bodies;
}
}  // namespace

std::string ballName(const BallCollision& c, std::size_t i)
{
  return c.balls[i].id.empty() ? "ball" + std::to_string(i) : c.balls[i].id;
}

Status validate(const BallCollision& c)
{
  if (c.balls.empty() || (c.balls.size() < 2 && c.cushions.empty()))
    return invalidArgument("balls", "a collision needs at least two balls, or a ball and a cushion, got " +
                                        std::to_string(c.balls.size()) + " ball(s)");
  if (Status status =
          firstError({requirePositive(c.ball_mass, "ball_mass"), requirePositive(c.ball_radius, "ball_radius"),
                      validate(c.ball_ball, "ball_ball"), validate(c.cloth, "cloth"),
                      requireStiffnessRatio(c.stiffness_ratio, "stiffness_ratio")});
      !status)
    return status;
  if (Status status = requireWithin(c.touching_tolerance, 0.0, 0.01 * c.ball_radius, "touching_tolerance",
                                    "a gap small against the ball: at most 0.01 ball_radius");
      !status)
    return status;
  for (std::size_t i = 0; i < c.balls.size(); ++i)
    if (Status status = checkBall(c.balls[i], i, c.ball_radius); !status)
      return status;
  if (Status status = checkCushions(c); !status)
    return status;
  return checkOverlaps(c);
}

std::vector<TouchingPair> touchingPairs(const BallCollision& c)
{
  const double farthest = 2.0 * c.ball_radius + c.touching_tolerance;
  std::vector<TouchingPair> pairs;
  for (std::size_t a = 1; a < c.balls.size(); ++a)
    for (std::size_t b = 0; b < a; ++b)
      if ((centre(c, a) - centre(c, b)).norm() <= farthest)
      {
        TouchingPair pair{b, a, 0.0};
        pair.friction = pairFriction(c, pair);
        pairs.push_back(pair);
      }
  return pairs;
}

Expected<BallCollisionBodies> collisionBodies(const BallCollision& collision)
{
  if (Status status = validate(collision); !status)
    return status.error();
  return assembleBodies(collision);
}

Expected<ImpactProblem> makeImpactProblem(const BallCollision& collision)
{
  auto configuration = configure(collision);
  if (!configuration)
    return configuration.error();
  return std::move(configuration).value().problem;
}

Expected<BallCollisionResult> solve(const BallCollision& collision, const SolverOptions& options)
{
  auto configuration = configure(collision);
  if (!configuration)
    return configuration.error();
  auto solved = solveMultipleImpact(configuration.value().problem, options);
  if (!solved)
    return solved.error();
  BallCollisionResult result;
  result.impact = std::move(solved).value();
  result.pairs = configuration.value().pairs;
  for (const Contact& contact : configuration.value().problem.contacts)
    result.contact_names.push_back(contact.name);
  result.cloth_contacts = configuration.value().cloth_contacts;
  for (std::size_t i = 0; i < collision.balls.size(); ++i)
  {
    const auto at = static_cast<Eigen::Index>(6 * i);
    result.balls.push_back({result.impact.velocity.segment<3>(at), result.impact.velocity.segment<3>(at + 3)});
  }
  return result;
}

}  // namespace billiard_shot_planner
