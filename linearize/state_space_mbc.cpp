// multibladeAverage: the multiblade transform of per-azimuth state-space models (linearize/mbc.hpp).
#include <cctype>

#include "linearize/mbc.hpp"
#include "linearize/state_space.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

std::vector<int> bladesOf(const std::vector<StateSpaceVariable>& v) {
  std::vector<int> b;
  for (const auto& e : v) b.push_back(e.blade);
  return b;
}

// "blade 2 flap 1" → "flap 1"; "UA x1 blade 2 element 7" → "UA x1 element 7" (as the Campbell diagram's
// mode shapes name them); "RootMFlp2" → "RootMFlp" (the blade number removed).
std::string baseName(const std::string& name, int blade) {
  const std::string prefix = "blade " + std::to_string(blade + 1) + " ";
  if (name.rfind(prefix, 0) == 0) return name.substr(prefix.size());
  if (const std::size_t at = name.find(" " + prefix); at != std::string::npos)
    return name.substr(0, at + 1) + name.substr(at + 1 + prefix.size());
  const std::string suffix = std::to_string(blade + 1);
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
      !std::isdigit(static_cast<unsigned char>(name[name.size() - suffix.size() - 1])))
    return name.substr(0, name.size() - suffix.size());
  return name;
}

void rename(std::vector<StateSpaceVariable>& vars, const std::vector<MbcCoordinate>& coords) {
  for (size_t i = 0; i < vars.size(); ++i) {
    if (vars[i].blade < 0) continue;
    StateSpaceVariable& v = vars[i];
    const bool rate = v.name.rfind("d(", 0) == 0 && v.name.size() > 6 && v.name.substr(v.name.size() - 4) == ")/dt";
    const std::string inner = rate ? v.name.substr(2, v.name.size() - 6) : v.name;
    std::string n = baseName(inner, v.blade);
    std::string kind = toString(coords[i]);
    if (n.empty() || n.back() != ' ') n += " ";
    n += kind;
    v.name = rate ? "d(" + n + ")/dt" : n;
    v.blade = -1;
  }
}

MatX column(const std::vector<StateSpaceVariable>& v) {
  MatX c(static_cast<Eigen::Index>(v.size()), 1);
  for (size_t i = 0; i < v.size(); ++i) c(i, 0) = v[i].op;
  return c;
}

}  // namespace

StateSpaceModel multibladeAverage(const std::vector<StateSpaceModel>& models, std::vector<StateSpaceModel>* per) {
  if (models.empty()) throw InputError("multiblade transform: no model");
  const StateSpaceModel& first = models.front();
  int N = 0;
  for (const auto& s : models) N = std::max(N, bladeCount(s));
  if (N < 3)
    throw InputError("multiblade transform: " + std::to_string(N) + " blades in the rotating frame; at least 3 needed");
  MbcLayout L;
  L.num_blades = N;
  L.state_blade = bladesOf(first.x);
  L.velocity_of.assign(first.x.size(), -1);
  for (size_t i = 0; i < first.x.size(); ++i) L.velocity_of[i] = first.x[i].rate_of;
  L.input_blade = bladesOf(first.u);
  L.output_blade = bladesOf(first.y);
  // Operating points go through the same transform: x_op as a column of B (fixed-frame input),
  // y_op and u_op as columns of D (their own frames on the rows).
  MbcLayout Lu = L;
  Lu.output_blade = L.input_blade;
  Lu.input_blade.clear();
  MbcLayout Lop = L;
  Lop.input_blade.clear();

  std::vector<MbcSample> samples;
  StateSpaceModel avg = first;
  VecX xop = VecX::Zero(first.x.size()), uop = VecX::Zero(first.u.size()), yop = VecX::Zero(first.y.size());
  VecX xdot = VecX::Zero(first.x.size());
  std::vector<MbcSample> transformed;
  for (const auto& s : models) {
    if (s.A.rows() != first.A.rows() || s.B.cols() != first.B.cols() || s.C.rows() != first.C.rows())
      throw InputError("multiblade transform: the per-azimuth models differ in size");
    MbcSample m;
    m.azimuth = s.azimuth;
    m.rotor_speed = s.rotor_speed;
    m.A = s.A;
    m.B = s.B;
    m.C = s.C;
    m.D = s.D;
    samples.push_back(m);
    MbcSample ops;
    ops.azimuth = s.azimuth;
    ops.rotor_speed = s.rotor_speed;
    ops.A = MatX::Zero(s.A.rows(), s.A.cols());
    MatX xcols(s.x.size(), 2);
    xcols.col(0) = column(s.x);
    xcols.col(1) = s.xdot_op;
    ops.B = xcols;
    ops.D = MatX::Zero(s.y.size(), 2);
    if (!s.y.empty()) ops.D.col(0) = column(s.y);
    const MbcSample t = mbcTransform(Lop, ops);
    MbcSample uops;
    uops.azimuth = s.azimuth;
    uops.A = MatX::Zero(s.A.rows(), s.A.cols());
    uops.D = column(s.u);
    const MbcSample tu = mbcTransform(Lu, uops);
    StateSpaceModel one = s;
    for (size_t i = 0; i < one.x.size(); ++i) one.x[i].op = t.B(i, 0);
    one.xdot_op = t.B.col(1);
    for (size_t i = 0; i < one.y.size(); ++i) one.y[i].op = t.D(i, 0);
    for (size_t i = 0; i < one.u.size(); ++i) one.u[i].op = tu.D(i, 0);
    xop += t.B.col(0);
    xdot += t.B.col(1);
    yop += t.D.col(0);
    uop += tu.D.col(0);
    if (per) per->push_back(std::move(one));
  }
  const MbcResult r = mbcAverage(L, samples);
  const double inv = 1.0 / static_cast<double>(models.size());
  avg.A = r.A;
  avg.B = r.B.size() ? r.B : MatX::Zero(first.x.size(), first.u.size());
  avg.C = r.C.size() ? r.C : MatX::Zero(first.y.size(), first.x.size());
  avg.D = r.D.size() ? r.D : MatX::Zero(first.y.size(), first.u.size());
  for (size_t i = 0; i < avg.x.size(); ++i) avg.x[i].op = xop(i) * inv;
  avg.xdot_op = xdot * inv;
  for (size_t i = 0; i < avg.u.size(); ++i) avg.u[i].op = uop(i) * inv;
  for (size_t i = 0; i < avg.y.size(); ++i) avg.y[i].op = yop(i) * inv;
  rename(avg.x, r.states);
  rename(avg.u, r.inputs);
  rename(avg.y, r.outputs);
  avg.multiblade = true;
  if (per)
    for (size_t k = 0; k < per->size(); ++k) {
      StateSpaceModel& one = (*per)[k];
      one.A = r.samples[k].A;
      if (r.samples[k].B.size()) one.B = r.samples[k].B;
      if (r.samples[k].C.size()) one.C = r.samples[k].C;
      if (r.samples[k].D.size()) one.D = r.samples[k].D;
      rename(one.x, r.states);
      rename(one.u, r.inputs);
      rename(one.y, r.outputs);
      one.multiblade = true;
    }
  return avg;
}

}  // namespace whirl
