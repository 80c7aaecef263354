// One compliant contact with friction (docs/impact_model.md, Coulomb friction and tangential compliance): a unit
// sphere (m = 1, r = 1, I = 0.4) hits a fixed table. Reference values and the analytic pure-stick formula:
// docs/validation.md, One compliant contact (an independent time-domain implementation of the same model).
#include <gtest/gtest.h>

#include <cmath>

#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"

namespace bsp = billiard_shot_planner;
using T = bsp::ContactEventType;

namespace
{
struct Case
{
  const char* name;
  Eigen::Vector3d v0, w0;
  double mu, eta2, e;
  Eigen::Vector3d v, w;
  bool starts_slipping;
  std::vector<std::pair<T, double>> log;  // event and the normal impulse I_z at which it happens
};

bsp::BallTableImpactResult solved(const Eigen::Vector3d& v0, const Eigen::Vector3d& w0, double mu, double eta2,
                                  double e)
{
  bsp::BallTableImpact impact;
  impact.velocity = v0;
  impact.angular_velocity = w0;
  impact.table = {e, mu, eta2};
  auto result = bsp::solve(impact);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().describe());
  return result.value();
}

std::vector<std::pair<T, double>> modeLog(const bsp::ImpactResult& r)
{
  std::vector<std::pair<T, double>> log;
  for (const auto& event : r.events)
    log.emplace_back(event.type, event.at.normal_impulses(0));
  return log;
}
}  // namespace

TEST(CompliantContact, SpecCasesAtoE)
{
  const Case cases[] = {
      {"A",
       {0.2, 0, -1},
       {0, 0, 0},
       0.5,
       3,
       1.0,
       {0.087306, 0, 1},
       {0, 0.281735, 0},
       false,
       {{T::EndOfCompression, 1.0}, {T::StickToSlip, 1.99963}, {T::Separation, 2.0}}},
      {"B",
       {0.2, 0, -1},
       {0, 0, 0},
       0.5,
       3,
       0.7,
       {0.087785, 0, 0.7},
       {0, 0.280538, 0},
       false,
       {{T::EndOfCompression, 1.0}, {T::StickToSlip, 1.699583}, {T::Separation, 1.7}}},
      {"C",
       {3, 0, -1},
       {0, 0, 0},
       0.3,
       3,
       0.8,
       {2.46, 0, 0.8},
       {0, 1.35, 0},
       true,
       {{T::EndOfCompression, 1.0}, {T::Separation, 1.8}}},
      {"D",
       {1, 0.5, -1},
       {0, -2, 4},
       0.4,
       2,
       0.6,
       {0.368708, 0.394785, 0.6},
       {-0.263038, -0.421770, 4},
       true,
       {{T::EndOfCompression, 1.0}, {T::Separation, 1.6}}},
      {"E",
       {0.3, -0.2, -1},
       {1.5, 0.4, 0},
       0.25,
       7,
       0.5,
       {0.325408, -0.530300, 0.5},
       {0.674249, 0.336481, 0},
       false,
       {{T::EndOfCompression, 1.0}, {T::StickToSlip, 1.106775}, {T::Separation, 1.5}}},
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const auto r = solved(c.v0, c.w0, c.mu, c.eta2, c.e);
    EXPECT_LT((r.velocity - c.v).cwiseAbs().maxCoeff(), 1e-4) << r.velocity.transpose();
    EXPECT_LT((r.angular_velocity - c.w).cwiseAbs().maxCoeff(), 1e-4) << r.angular_velocity.transpose();
    EXPECT_EQ(r.impact.initially_slipping.front(), c.starts_slipping);
    const auto log = modeLog(r.impact);
    ASSERT_EQ(log.size(), c.log.size());
    for (std::size_t k = 0; k < log.size(); ++k)
    {
      EXPECT_EQ(log[k].first, c.log[k].first) << "event " << k;
      EXPECT_NEAR(log[k].second, c.log[k].second, 1e-4) << "event " << k;
    }
  }
}

TEST(CompliantContact, PureStickMatchesTheAnalyticSolution)
{
  // μ → ∞: the tangential spring oscillates with the tangential effective mass 2m/7 while the normal one lasts
  // (π/2)(1+e) normal time units: u_t,end = v_t0 cos((π/2)(1+e)√(3.5/η²)), v_x,end = v_t0 + (2/7)(u_t,end − v_t0).
  const double v_t0 = 0.3;
  const double table[][3] = {{14, 1, 0.0}, {3.5, 1, -0.3}, {7, 0.6, -0.061469}, {2, 0.8, -0.247812}};
  for (const auto& row : table)
  {
    const double eta2 = row[0], e = row[1];
    const double u_end = v_t0 * std::cos(M_PI / 2.0 * (1.0 + e) * std::sqrt(3.5 / eta2));
    EXPECT_NEAR(u_end, row[2], 1e-6);  // the reference table agrees with the formula
    const auto r = solved({v_t0, 0, -1}, {0, 0, 0}, 1e9, eta2, e);
    const double contact_slip = r.velocity.x() - r.angular_velocity.y();  // v_x − r ω_y at the contact
    EXPECT_NEAR(contact_slip, u_end, 1e-6) << "eta2 " << eta2 << " e " << e;
    EXPECT_NEAR(r.velocity.x(), v_t0 + 2.0 / 7.0 * (u_end - v_t0), 1e-6);
    EXPECT_NEAR(r.velocity.z(), e, 1e-9);
  }
}

TEST(CompliantContact, FrictionlessIsTheNormalImpactAlone)
{
  const auto r = solved({0.7, -0.2, -1.3}, {3, -1, 2}, 0.0, 5.0, 0.6);
  EXPECT_NEAR(r.velocity.z(), 0.6 * 1.3, 1e-10);
  EXPECT_NEAR(r.velocity.x(), 0.7, 1e-12);
  EXPECT_NEAR(r.angular_velocity.x(), 3.0, 1e-12);
  EXPECT_EQ(r.impact.events.size(), 2u);  // end of compression, separation: no tangential events
}

TEST(CompliantContact, EnergyNeverIncreases)
{
  for (double mu : {0.1, 0.3, 1.0})
    for (double eta2 : {1.0, 3.5, 10.0})
    {
      const auto r = solved({0.4, -0.3, -1}, {1, 2, -3}, mu, eta2, 0.8);
      EXPECT_LE(r.impact.final_kinetic_energy, r.impact.initial_kinetic_energy * (1 + 1e-12));
    }
}
