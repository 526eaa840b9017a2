#include "linearize/simulation_setup.hpp"

#include <fmt/format.h>

#include "linearize/point_validity.hpp"
#include "src/base/error.hpp"

namespace whirl {

void applyInitialCondition(const Model& m, OperatingPoint& p, std::string name, double value, const std::string& key) {
  bool offset = false, rate = false;
  if (!name.empty() && name.back() == '+') {
    offset = true;
    name.pop_back();
    while (!name.empty() && name.back() == ' ') name.pop_back();
  }
  std::string dof = name;
  if (!m.findDof(dof) && name.size() > 5 && name.compare(name.size() - 5, 5, " rate") == 0) {
    rate = true;
    dof = name.substr(0, name.size() - 5);
  }
  const auto i = m.findDof(dof);
  if (!i) {
    std::string known;
    for (int k : m.activeDofs()) known += (known.empty() ? "" : ", ") + m.dofs[k].name;
    throw InputError(key + ": '" + name + "': no such coordinate (active: " + known + ")");
  }
  if (m.dofs[*i].frozen) throw InputError(key + ": '" + dof + "': a frozen coordinate follows its prescribed motion");
  double& x = rate ? p.qd(*i) : p.q(*i);
  x = offset ? x + value : value;
}

int simulationInput(const Model& m, const std::string& name, const std::string& key) {
  const auto i = m.findInput(name);
  if (!i) {
    std::string known;
    for (const Input& in : m.inputs) known += (known.empty() ? "" : ", ") + in.name;
    throw InputError(key + ": '" + name + "': no such input (inputs: " + (known.empty() ? "none" : known) + ")");
  }
  return *i;
}

int drivenCoordinate(const Model& m, const std::string& name, const std::string& key) {
  const auto i = m.findDof(name);
  if (!i || m.dofs[*i].frozen) throw InputError(key + ": '" + name + "': no such active coordinate");
  return *i;
}

std::optional<std::string> invalidMotion(const Model& m, const Simulation& sim) {
  for (size_t k = 0; k < sim.time.size(); ++k) {
    OperatingPoint at;  // no solved coordinates: only the geometry is checked
    at.q = sim.q.row(static_cast<Eigen::Index>(k)).transpose();
    const std::vector<std::string> problems = checkPointValidity(m, at);
    if (!problems.empty())
      return "t = " + fmt::format("{:g}", sim.time[k]) +
             " s: the motion leaves the model's range of validity: " + problems.front();
  }
  return std::nullopt;
}

std::function<bool(double, const VecX&)> stopAtInvalidMotion(const Model& m) {
  return [&m](double, const VecX& q) {
    OperatingPoint at;  // no solved coordinates: only the geometry is checked, as invalidMotion does
    at.q = q;
    return !checkPointValidity(m, at).empty();
  };
}

WindStart windStart(const Model& m, double wind, const RoscoController* controller) {
  TrimOptions trim;
  trim.controller = controller;
  WindStart w;
  w.steady = trimAtWindSpeed(m, wind, trim);
  OperatingCondition cond = w.steady.condition;
  cond.generator_torque = w.steady.generator_torque;
  w.start = solveOperatingPoint(m, initialPoint(m, cond));
  return w;
}

}  // namespace whirl
