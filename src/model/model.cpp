#include "src/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include <fmt/format.h>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/text.hpp"

namespace whirl {
namespace {

template <class V>
std::optional<int> findByName(const V& items, const std::string& name) {
  for (size_t i = 0; i < items.size(); ++i)
    if (items[i].name == name) return static_cast<int>(i);
  return std::nullopt;
}

bool allFinite(const MatX& m) { return m.allFinite(); }

std::string bodyWhere(const Body& b, const std::string& what) { return "body '" + b.name + "': " + what; }

// Depth of each body in the tree; throws on unknown parents and cycles.
std::vector<int> depths(const std::vector<Body>& bodies) {
  const int n = static_cast<int>(bodies.size());
  std::vector<int> depth(n, -1);
  for (int i = 0; i < n; ++i) {
    int d = 0, j = i;
    while (bodies[j].parent >= 0) {
      if (bodies[j].parent >= n) throw InputError(bodyWhere(bodies[j], "parent index out of range"));
      j = bodies[j].parent;
      if (++d > n) throw InputError(bodyWhere(bodies[i], "the parent chain forms a loop"));
    }
    depth[i] = d;
  }
  return depth;
}

// Active length of each row of P: the last basis entry any integral of that component touches.
void setActiveLengths(BodyInertia& in) {
  const int nc = in.nc();
  for (int j = 0; j < 3; ++j) {
    int len = 1;
    for (int i = 0; i < nc; ++i) {
      bool used = in.m1(j, i) != 0.0;
      for (int l = 0; l < 3 && !used; ++l)
        used = !in.S[3 * j + l].row(i).isZero(0) || !in.S[3 * l + j].col(i).isZero(0);
      if (used) len = i + 1;
    }
    in.len[j] = len;
  }
  in.Strace = in.S[0] + in.S[4] + in.S[8];
  in.massless = in.mass == 0.0 && in.m1.isZero(0);
  for (const MatX& S : in.S) in.massless = in.massless && S.isZero(0);
  auto block = [](const MatX& S, int rows, int cols) {
    ShapeIntegralBlock b;
    for (int r = 0; r < rows; ++r)
      if (!S.row(r).head(cols).isZero(0)) b.rows.push_back(r);
    for (int c = 0; c < cols; ++c)
      if (!S.col(c).head(rows).isZero(0)) b.cols.push_back(c);
    for (int r : b.rows)
      for (int c : b.cols) b.values.push_back(S(r, c));
    return b;
  };
  for (int j = 0; j < 3; ++j)
    for (int l = 0; l < 3; ++l) in.S_block[3 * j + l] = block(in.S[3 * j + l], in.len[j], in.len[l]);
  in.Strace_block = block(in.Strace, nc, nc);
}

void checkInertia(const Body& b) {
  const BodyInertia& in = b.inertia;
  if (!std::isfinite(in.mass)) throw InputError(bodyWhere(b, "mass is not finite"));
  if (in.mass < 0) throw InputError(bodyWhere(b, "negative mass " + std::to_string(in.mass) + " kg"));
  if (in.m1.cols() != in.nc()) throw InputError(bodyWhere(b, "shape integrals have the wrong size"));
  if (!allFinite(in.m1)) throw InputError(bodyWhere(b, "shape integrals are not finite (NaN in a property?)"));
  for (const auto& s : in.S) {
    if (s.rows() != in.nc() || s.cols() != in.nc())
      throw InputError(bodyWhere(b, "shape integrals have the wrong size"));
    if (!allFinite(s)) throw InputError(bodyWhere(b, "shape integrals are not finite (NaN in a property?)"));
  }
  // The rigid-body mass matrix [[m 1, −m ρ̃], [m ρ̃, J_O]] is positive semi-definite iff the inertia
  // tensor at the COG is (J_O from the second moment Θ: J = tr(Θ) 1 − Θ; parallel-axis shift to G).
  Mat3 theta;
  for (int j = 0; j < 3; ++j)
    for (int l = 0; l < 3; ++l) theta(j, l) = in.S[3 * j + l](0, 0);
  const Mat3 J_O = theta.trace() * Mat3::Identity() - theta;
  const Vec3 rho = in.mass > 0 ? Vec3(in.m1.col(0) / in.mass) : Vec3::Zero();
  const Mat3 J_G = J_O - in.mass * (rho.squaredNorm() * Mat3::Identity() - rho * rho.transpose());
  const double scale = std::max(1.0, J_G.cwiseAbs().maxCoeff());
  if (Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (J_G + J_G.transpose())).eigenvalues().minCoeff() < -1e-9 * scale)
    throw InputError(bodyWhere(b, "inertia tensor at the COG is not positive semi-definite"));
  if (in.ne > 0) {
    MatX mee = MatX::Zero(in.ne, in.ne);
    for (int k = 0; k < 3; ++k) mee += in.S[4 * k].block(1, 1, in.ne, in.ne);
    // Scaled to unit diagonal, so that the test does not depend on how each shape is normalized: two
    // identical shapes give an eigenvalue 0 up to round-off, which a Cholesky factorization may pass.
    const VecX d = mee.diagonal();
    bool definite = (d.array() > 0).all();
    if (definite) {
      const VecX s = d.cwiseSqrt().cwiseInverse();
      const MatX unit = s.asDiagonal() * (0.5 * (mee + mee.transpose())) * s.asDiagonal();
      definite = Eigen::SelfAdjointEigenSolver<MatX>(unit, Eigen::EigenvaluesOnly).eigenvalues().minCoeff() > 1e-10;
    }
    if (!definite)
      throw InputError(bodyWhere(b,
                                 "elastic mass matrix is not positive definite (a shape function with no "
                                 "mass, or two identical shapes)"));
    if (b.elastic.K.rows() != in.ne || b.elastic.K.cols() != in.ne || b.elastic.D.rows() != in.ne ||
        b.elastic.D.cols() != in.ne)
      throw InputError(bodyWhere(b, "elastic stiffness/damping size differs from the number of shapes"));
    if (!allFinite(b.elastic.K) || !allFinite(b.elastic.D))
      throw InputError(bodyWhere(b, "elastic stiffness or damping is not finite"));
    if (b.elastic.A.size() > 0 &&
        (b.elastic.A.rows() != in.ne || b.elastic.A.cols() != in.ne || !allFinite(b.elastic.A)))
      throw InputError(bodyWhere(b, "elastic added mass is not a finite matrix of the number of shapes"));
  }
  for (const auto& p : b.points) {
    if (p.P.cols() != in.nc() || p.theta.cols() != in.ne)
      throw InputError(bodyWhere(b, "point '" + p.name + "' has the wrong size"));
    if (!allFinite(p.P) || !allFinite(p.theta)) throw InputError(bodyWhere(b, "point '" + p.name + "' is not finite"));
  }
}

std::vector<ChainStep> buildChain(const Model& m, int i) {
  const Body& b = m.bodies[i];
  std::vector<ChainStep> steps;
  if (b.parent >= 0 && b.parent_point >= 0) {
    const Body& p = m.bodies[b.parent];
    const BodyPoint& pt = p.points[b.parent_point];
    if (!pt.P.isZero(0)) {
      ChainStep s;
      s.kind = ChainStep::PointTranslate;
      s.body = b.parent;
      s.point = b.parent_point;
      steps.push_back(s);
    }
    // Small rotations of the point, applied in the order y, z, x ([Branlard2019, §4.1]: R_y R_z R_x).
    for (int axis : {1, 2, 0}) {
      if (p.inertia.ne == 0 || pt.theta.row(axis).isZero(0)) continue;
      ChainStep s;
      s.kind = ChainStep::ElasticRotate;
      s.body = b.parent;
      s.point = b.parent_point;
      s.axis_index = axis;
      steps.push_back(s);
    }
  }
  if (!b.offset.isZero(0)) {
    ChainStep s;
    s.kind = ChainStep::ConstTranslate;
    s.vec = b.offset;
    steps.push_back(s);
  }
  if (!b.rotation.isIdentity(0)) {
    ChainStep s;
    s.kind = ChainStep::ConstRotate;
    s.rot = b.rotation;
    steps.push_back(s);
  }
  auto axisStep = [&](ChainStep::Kind kind, const Vec3& axis, int dof) {
    ChainStep s;
    s.kind = kind;
    s.vec = axis;
    s.dof = dof;
    steps.push_back(s);
  };
  switch (b.joint) {
    case JointType::Fixed: break;
    case JointType::Revolute:
      axisStep(ChainStep::AxisRotate, b.axis, b.joint_dof);
      steps.back().ratio = b.joint_ratio;
      break;
    case JointType::Prismatic: axisStep(ChainStep::AxisTranslate, b.axis, b.joint_dof); break;
    case JointType::Free:
      // Translations along the joint-frame axes, then yaw (z), pitch (y'), roll (x'').
      for (int k = 0; k < 3; ++k) axisStep(ChainStep::AxisTranslate, Vec3::Unit(k), b.joint_dof + k);
      axisStep(ChainStep::AxisRotate, Vec3::UnitZ(), b.joint_dof + 5);
      axisStep(ChainStep::AxisRotate, Vec3::UnitY(), b.joint_dof + 4);
      axisStep(ChainStep::AxisRotate, Vec3::UnitX(), b.joint_dof + 3);
      break;
  }
  return steps;
}

}  // namespace

int jointDofCount(JointType t) {
  switch (t) {
    case JointType::Fixed: return 0;
    case JointType::Revolute: return 1;
    case JointType::Prismatic: return 1;
    case JointType::Free: return 6;
  }
  return 0;
}

std::optional<int> Model::findBody(const std::string& n) const { return findByName(bodies, n); }
std::optional<int> Model::findDof(const std::string& n) const { return findByName(dofs, n); }
std::optional<int> Model::findInput(const std::string& n) const { return findByName(inputs, n); }
std::optional<int> Model::findOutput(const std::string& n) const { return findByName(outputs, n); }

void requireActiveDof(const Model& model, const std::string& what) {
  for (const Dof& d : model.dofs)
    if (!d.frozen) return;
  throw InputError(
      where("", 0, what,
            "the model has no active degree of freedom (all frozen or none defined): nothing to linearize"));
}

std::vector<int> Model::activeDofs() const {
  std::vector<int> a;
  for (int i = 0; i < ndof(); ++i)
    if (!dofs[i].frozen) a.push_back(i);
  return a;
}

namespace {

// Input DOF targets and outputs: DOF indices renumbered, names unique, values checked.
void finalizeInputsAndOutputs(Model& m, const std::vector<int>& new_dof) {
  auto remap = [&](int& d, const std::string& what) {
    if (d < 0 || d >= static_cast<int>(new_dof.size())) throw InputError(what + ": no such DOF");
    d = new_dof[d];
  };
  std::set<std::string> names;
  for (Input& in : m.inputs) {
    if (!names.insert(in.name).second) throw InputError("input '" + in.name + "': name used twice");
    if (!std::isfinite(in.value)) throw InputError("input '" + in.name + "': value not finite");
    for (InputDofTarget& t : in.dofs) {
      remap(t.dof, "input '" + in.name + "'");
      if (!m.dofs[t.dof].frozen)
        throw InputError("input '" + in.name + "': DOF '" + m.dofs[t.dof].name +
                         "' is not frozen (an input sets the value of frozen coordinates only)");
      if (!std::isfinite(t.gain)) throw InputError("input '" + in.name + "': gain not finite");
    }
  }
  names.clear();
  for (Output& o : m.outputs) {
    const std::string what = "output '" + o.name + "'";
    if (o.name.empty()) throw InputError("an output has no name");
    if (!names.insert(o.name).second) throw InputError(what + ": name used twice");
    if (o.order < 0 || o.order > 2) throw InputError(what + ": order must be 0, 1 or 2");
    if (o.kind == OutputKind::DofCombination) {
      if (o.terms.empty()) throw InputError(what + ": no DOF");
      int blade = -2;
      for (auto& [d, g] : o.terms) {
        remap(d, what);
        if (!std::isfinite(g)) throw InputError(what + ": gain not finite");
        const int b = m.dofs[d].blade;
        blade = blade == -2 || blade == b ? b : -1;
      }
      if (o.blade < 0) o.blade = std::max(blade, -1);
    } else if (o.kind == OutputKind::Point || o.kind == OutputKind::Angular) {
      if (o.kind == OutputKind::Angular && o.order == 0)
        throw InputError(what + ": an angular output is a rate (order 1) or an acceleration (order 2)");
      if (o.kind == OutputKind::Point && o.point >= static_cast<int>(m.bodies[o.body].points.size()))
        throw InputError(what + ": no such point");
      if (!o.direction.allFinite() || o.direction.norm() < 1e-12) throw InputError(what + ": direction is zero");
      o.direction.normalize();
    }
  }
}

// Names and units go into generated scripts and tables; the readers check them with file and line,
// this catches models built otherwise.
void requirePrintableNames(const Model& m) {
  requirePrintable(m.name, "", 0, "model name");
  for (const Body& b : m.bodies) {
    requirePrintable(b.name, "", 0, "body '" + b.name + "'");
    for (const auto& p : b.points) requirePrintable(p.name, "", 0, "body '" + b.name + "': point '" + p.name + "'");
  }
  for (const Dof& d : m.dofs) requirePrintable(d.name, "", 0, "DOF '" + d.name + "'");
  for (const Input& in : m.inputs) {
    requirePrintable(in.name, "", 0, "input '" + in.name + "'");
    requirePrintable(in.unit, "", 0, "input '" + in.name + "': unit");
  }
  for (const Output& o : m.outputs) {
    requirePrintable(o.name, "", 0, "output '" + o.name + "'");
    requirePrintable(o.unit, "", 0, "output '" + o.name + "': unit");
  }
}

// Roles: DOF indices renumbered, input indices checked, the azimuth = the rotating coordinates.
void finalizeRoles(Model& m, const std::vector<int>& new_dof) {
  ModelRoles& r = m.roles;
  auto dof = [&](int& d, const char* what) {
    if (d < 0) return;
    if (d >= static_cast<int>(new_dof.size())) throw InputError(std::string("model roles: ") + what + ": no such DOF");
    d = new_dof[d];
  };
  auto input = [&](int i, const char* what) {
    if (i >= m.ninput()) throw InputError(std::string("model roles: ") + what + ": no such input");
  };
  for (int& d : r.blade_pitch) {
    if (d < 0) throw InputError("model roles: blade pitch: every blade needs its pitch coordinate");
    dof(d, "blade pitch");
    if (!m.dofs[d].frozen) throw InputError("model roles: blade pitch: DOF '" + m.dofs[d].name + "' is not frozen");
  }
  dof(r.yaw_dof, "yaw");
  dof(r.teeter_dof, "teeter");
  input(r.collective_pitch_input, "collective pitch");
  for (int i : r.blade_pitch_inputs) input(i, "blade pitch");
  input(r.wind_speed_input, "wind speed");
  input(r.generator_torque_input, "generator torque");
  r.azimuth.clear();
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[i].rotating) r.azimuth.push_back(i);
}

}  // namespace

namespace {

void requireUniqueBodyNames(const Model& m) {
  std::set<std::string> names;
  for (const auto& b : m.bodies) {
    if (b.name.empty()) throw InputError("a body has no name");
    if (!names.insert(b.name).second) throw InputError(bodyWhere(b, "name used twice"));
  }
}

/// Orders the bodies parents first, by depth (stable, so siblings keep the order they were given
/// in), and renumbers the parent and geared-joint references; returns the new index of each old body.
std::vector<int> sortBodiesParentsFirst(Model& m) {
  const int nb = static_cast<int>(m.bodies.size());
  const std::vector<int> depth = depths(m.bodies);
  std::vector<int> order(nb);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth[a] < depth[b]; });
  std::vector<int> new_index(nb);
  for (int k = 0; k < nb; ++k) new_index[order[k]] = k;
  std::vector<Body> sorted;
  sorted.reserve(nb);
  for (int k = 0; k < nb; ++k) {
    sorted.push_back(std::move(m.bodies[order[k]]));
    Body& b = sorted.back();
    if (b.parent >= 0) b.parent = new_index[b.parent];
    if (b.joint_follows >= nb) throw InputError(bodyWhere(b, "geared joint follows a body that does not exist"));
    if (b.joint_follows >= 0) b.joint_follows = new_index[b.joint_follows];
  }
  m.bodies = std::move(sorted);
  return new_index;
}

/// DOFs, point loads, point outputs and 6×6 body matrices refer to the renumbered bodies.
void remapBodyReferences(Model& m, const std::vector<int>& new_index) {
  const int nb = static_cast<int>(new_index.size());
  for (auto& d : m.dofs) {
    if (d.body < 0 || d.body >= nb) throw InputError("DOF '" + d.name + "': no such body");
    d.body = new_index[d.body];
  }
  auto remapBody = [&](int& b, const std::string& what) {
    if (b < 0 || b >= nb) throw InputError(what + ": no such body");
    b = new_index[b];
  };
  for (auto& l : m.point_loads) remapBody(l.body, "point load");
  for (auto& o : m.outputs)
    if (o.kind == OutputKind::Point || o.kind == OutputKind::Angular) {
      remapBody(o.body, "output '" + o.name + "'");
      if (o.frame_body >= 0) remapBody(o.frame_body, "output '" + o.name + "' frame");
    }
  for (auto& l : m.body_matrices) remapBody(l.body, "body matrices");
  for (auto& l : m.body_states) remapBody(l.body, "body states");
  for (auto& l : m.mooring) remapBody(l.body, l.name);
}

/// Checks what a body's placement and inertia need (axis, offset, rotation, parent point).
void checkBody(const Model& m, Body& b) {
  checkInertia(b);
  setActiveLengths(b.inertia);
  if (b.parent >= 0 && b.parent_point >= static_cast<int>(m.bodies[b.parent].points.size()))
    throw InputError(bodyWhere(b, "parent point index out of range"));
  if (b.parent < 0 && b.parent_point >= 0)
    throw InputError(bodyWhere(b, "a point on the ground is not allowed; use offset"));
  if (b.joint == JointType::Revolute || b.joint == JointType::Prismatic) {
    if (!b.axis.allFinite() || b.axis.norm() < 1e-12) throw InputError(bodyWhere(b, "joint axis is zero"));
    b.axis.normalize();
  }
  if (!b.offset.allFinite() || !b.rotation.allFinite()) throw InputError(bodyWhere(b, "offset or rotation not finite"));
  if ((b.rotation.transpose() * b.rotation - Mat3::Identity()).norm() > 1e-9)
    throw InputError(bodyWhere(b, "rotation is not orthonormal"));
}

/// Numbers the DOFs body by body — joint coordinates, then elastic ones — keeping the names and
/// values given for them and naming the others "<body> joint k" / "<body> shape k"; returns the new
/// index of each given DOF.
std::vector<int> numberDofs(Model& m) {
  std::map<std::pair<int, std::pair<int, int>>, int> given;  // (body, (kind, local)) -> old index
  for (int k = 0; k < m.ndof(); ++k) {
    const Dof& d = m.dofs[k];
    auto key = std::make_pair(d.body, std::make_pair(static_cast<int>(d.kind), d.local));
    if (!given.emplace(key, k).second) throw InputError("DOF '" + d.name + "': defined twice");
  }
  std::vector<Dof> dofs;
  std::vector<int> new_dof(m.ndof(), -1);
  for (int i = 0; i < static_cast<int>(m.bodies.size()); ++i) {
    Body& b = m.bodies[i];
    checkBody(m, b);
    auto place = [&](DofKind kind, int local, const std::string& default_name) {
      auto it = given.find({i, {static_cast<int>(kind), local}});
      Dof d;
      if (it != given.end()) {
        d = m.dofs[it->second];
        new_dof[it->second] = static_cast<int>(dofs.size());
      } else {
        d.name = default_name;
        d.kind = kind;
        d.local = local;
      }
      d.body = i;
      if (!std::isfinite(d.value) || !std::isfinite(d.rate)) throw InputError("DOF '" + d.name + "': value not finite");
      dofs.push_back(d);
    };
    const int nj = b.joint_follows >= 0 ? 0 : jointDofCount(b.joint);
    b.joint_dof = nj > 0 ? static_cast<int>(dofs.size()) : -1;
    for (int k = 0; k < nj; ++k) place(DofKind::Joint, k, b.name + " joint " + std::to_string(k + 1));
    b.elastic_dof = b.inertia.ne > 0 ? static_cast<int>(dofs.size()) : -1;
    for (int k = 0; k < b.inertia.ne; ++k) place(DofKind::Elastic, k, b.name + " shape " + std::to_string(k + 1));
  }
  for (size_t k = 0; k < new_dof.size(); ++k)
    if (new_dof[k] < 0) throw InputError("DOF '" + m.dofs[k].name + "': its body has no such coordinate");
  m.dofs = std::move(dofs);
  std::set<std::string> names;
  for (const auto& d : m.dofs)
    if (!names.insert(d.name).second) throw InputError("DOF '" + d.name + "': name used twice");
  return new_dof;
}

/// DOF loads and springs refer to the renumbered DOFs; loads to existing points and inputs.
void remapDofReferences(Model& m, const std::vector<int>& new_dof) {
  auto remapDof = [&](int& d, const std::string& what) {
    if (d < 0 || d >= static_cast<int>(new_dof.size())) throw InputError(what + ": no such DOF");
    d = new_dof[d];
  };
  for (auto& l : m.dof_loads) remapDof(l.dof, "DOF load");
  for (auto& s : m.springs) remapDof(s.dof, "DOF spring");
  for (const auto& bm : m.body_matrices)
    if (m.bodies[bm.body].joint != JointType::Free)
      throw InputError(bodyWhere(m.bodies[bm.body], "6x6 matrices need a free joint"));
  for (const auto& bs : m.body_states) {
    if (m.bodies[bs.body].joint != JointType::Free)
      throw InputError(bodyWhere(m.bodies[bs.body], "first-order states on its motion need a free joint"));
    const Eigen::Index nz = bs.A.rows();
    if (bs.A.cols() != nz || bs.B.rows() != nz || bs.B.cols() != 6 || bs.C.rows() != 6 || bs.C.cols() != nz ||
        static_cast<Eigen::Index>(bs.groups.size()) != nz)
      throw InputError(bodyWhere(m.bodies[bs.body], "first-order states: A, B, C and names differ in size"));
    if (!bs.A.allFinite() || !bs.B.allFinite() || !bs.C.allFinite())
      throw InputError(bodyWhere(m.bodies[bs.body], "first-order states: a matrix entry is not finite"));
  }
  for (const auto& l : m.mooring) {
    if (m.bodies[l.body].inertia.ne != 0) throw InputError(l.name + ": its fairlead must be on a rigid body");
    if (!l.fairlead.allFinite() || !l.anchor.allFinite() || !(l.length > 0) || !(l.weight > 0) || !(l.EA > 0) ||
        !(l.CB >= 0) || !std::isfinite(l.length + l.weight + l.EA + l.CB))
      throw InputError(l.name + ": length, weight in fluid and EA must be positive and finite, CB >= 0");
  }
  for (const auto& l : m.point_loads) {
    if (l.point >= static_cast<int>(m.bodies[l.body].points.size())) throw InputError("point load: no such point");
    if (l.input >= m.ninput()) throw InputError("point load: no such input");
  }
  for (const auto& l : m.dof_loads)
    if (l.input >= m.ninput()) throw InputError("DOF load: no such input");
}

/// Geared joints take the coordinate of the joint they follow.
void bindGearedJoints(Model& m) {
  for (Body& b : m.bodies) {
    if (b.joint_follows < 0) continue;
    const Body& f = m.bodies[b.joint_follows];
    if (b.joint != JointType::Revolute || f.joint != JointType::Revolute || f.joint_follows >= 0)
      throw InputError(
          bodyWhere(b, "a geared joint must be revolute and follow a revolute joint with its own coordinate"));
    if (!std::isfinite(b.joint_ratio)) throw InputError(bodyWhere(b, "gear ratio is not finite"));
    b.joint_dof = f.joint_dof;
  }
}

/// Each body's chain to the ground and the coordinates that move it (its support).
void buildChainsAndSupports(Model& m) {
  const int nb = static_cast<int>(m.bodies.size());
  m.chains.assign(nb, {});
  m.support.assign(nb, {});
  for (int i = 0; i < nb; ++i) {
    m.chains[i] = buildChain(m, i);
    const Body& b = m.bodies[i];
    std::set<int> s;
    if (b.parent >= 0) {
      s.insert(m.support[b.parent].begin(), m.support[b.parent].end());
      const Body& p = m.bodies[b.parent];
      if (b.parent_point >= 0)
        for (int k = 0; k < p.inertia.ne; ++k) s.insert(p.elastic_dof + k);
    }
    for (int k = 0; k < jointDofCount(b.joint); ++k) s.insert(b.joint_dof + k);  // own or geared
    m.support[i].assign(s.begin(), s.end());
  }
}

}  // namespace

void finalize(Model& m) {
  requirePrintableNames(m);
  requireUniqueBodyNames(m);
  if (!m.gravity.allFinite()) throw InputError("gravity: not finite");
  if (m.gravity.norm() > limits::kMaxGravity)
    throw InputError(fmt::format("gravity: magnitude {:g} m/s² is above the limit of {:g} m/s² (100 g)",
                                 m.gravity.norm(), limits::kMaxGravity));
  const std::vector<int> new_index = sortBodiesParentsFirst(m);
  remapBodyReferences(m, new_index);
  const std::vector<int> new_dof = numberDofs(m);
  remapDofReferences(m, new_dof);
  finalizeInputsAndOutputs(m, new_dof);
  finalizeAero(m, new_index, new_dof);
  finalizeRoles(m, new_dof);
  bindGearedJoints(m);
  buildChainsAndSupports(m);
}

}  // namespace whirl
