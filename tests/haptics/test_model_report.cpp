// The JSON of `needle-sim model`: exactly its documented keys, internally consistent.
#include <gtest/gtest.h>

#include "haptics/model/model_report.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

Eigen::MatrixXd matrix(const nlohmann::json& j) {
  Eigen::MatrixXd m(j.size(), j[0].size());
  for (size_t r = 0; r < j.size(); ++r)
    for (size_t c = 0; c < j[r].size(); ++c) m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = j[r][c];
  return m;
}

Eigen::VectorXd vector(const nlohmann::json& j) {
  const auto v = j.get<std::vector<double>>();
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

TEST(ModelReport, HasTheIssueKeysAndConsistentValues) {
  const RobotModel model = test::master_robot();
  VecN q(5), dq(5), ddq(5);
  q << 0.1, 0.6, -1.4, 0.2, 0.5;
  dq << 0.3, -0.2, 0.5, 1.0, -0.7;
  ddq << 1.0, 2.0, -1.0, 0.5, 0.0;
  const nlohmann::json r = model_report(model, q, dq, ddq);
  for (const char* key : {"pose", "J", "H", "Cdq", "g", "gravity", "tau_id"}) EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_EQ(r.size(), 7u) << "exactly the issue's keys";
  EXPECT_EQ(r["pose"].size(), 2u);
  EXPECT_TRUE(r["pose"].contains("p"));
  EXPECT_TRUE(r["pose"].contains("R"));
  EXPECT_EQ(r["J"].size(), 6u);
  EXPECT_EQ(r["J"][0].size(), 5u);
  EXPECT_EQ(vector(r["gravity"]), Eigen::Vector3d(0, 0, -9.81));
  // tau_id (Newton-Euler) equals H q̈ + C q̇ + D q̇ + g assembled from the printed parts.
  const Eigen::VectorXd expected = matrix(r["H"]) * Eigen::VectorXd(ddq) + vector(r["Cdq"]) +
                                   Eigen::VectorXd(model.damping().cwiseProduct(dq)) + vector(r["g"]);
  EXPECT_LT((vector(r["tau_id"]) - expected).norm(), 1e-12);
  EXPECT_NEAR(matrix(r["pose"]["R"]).determinant(), 1.0, 1e-12);
  EXPECT_THROW(model_report(model, VecN::Zero(4), dq, ddq), std::invalid_argument);
}

}  // namespace
}  // namespace needle::haptics
