#include "haptics/model/model_report.hpp"

#include <stdexcept>
#include <utility>

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "haptics/model/regressor.hpp"

namespace needle::haptics {
namespace {

template <typename M>
nlohmann::json rows(const M& m) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    out.push_back(row);
  }
  return out;
}

template <typename V>
nlohmann::json vec(const V& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

}  // namespace

nlohmann::json model_report(const RobotModel& model, const VecN& q, const VecN& dq, const VecN& ddq) {
  const int n = model.dof();
  if (q.size() != n || dq.size() != n || ddq.size() != n)
    throw std::invalid_argument("robot '" + model.name + "' has " + std::to_string(n) + " joints; q, dq and ddq need " +
                                std::to_string(n) + " values each");
  RobotData data(model);
  update_kinematics(model, data, q, dq);
  update_dynamics(model, data);
  VecN tau(n);
  inverse_dynamics(model, data, parameter_vector(model), ddq, tau);
  const VecN cdq = data.C * dq;
  // A state so large that a result overflows double precision is an error, not a JSON null.
  const std::pair<const char*, bool> finite[] = {{"pose", data.tip.matrix().allFinite()},
                                                 {"J", data.J.allFinite()},
                                                 {"H", data.H.allFinite()},
                                                 {"Cdq", cdq.allFinite()},
                                                 {"g", data.g.allFinite()},
                                                 {"tau_id", tau.allFinite()}};
  for (const auto& [name, ok] : finite)
    if (!ok)
      throw std::range_error("robot '" + model.name + "': " + name +
                             " is not finite at this state (q, dq or ddq too large for double precision)");
  return {{"pose", {{"p", vec(data.tip.translation())}, {"R", rows(data.tip.linear())}}},
          {"J", rows(data.J)},
          {"H", rows(data.H)},
          {"Cdq", vec(cdq)},
          {"g", vec(data.g)},
          {"gravity", vec(model.gravity)},
          {"tau_id", vec(tau)}};
}

}  // namespace needle::haptics
