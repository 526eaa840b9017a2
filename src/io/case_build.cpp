#include "src/io/case_reader.hpp"

#include "src/model/error.hpp"

namespace whirl {
namespace {

template <class V>
std::string names(const V& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i.name;
  return s.empty() ? "none" : s;
}

}  // namespace

void CaseBuild::addDof(const std::string& name, DofKind kind, int body, int local, const Where& w, bool angular) {
  if (name.empty()) w.fail("a DOF name must not be empty");
  if (const auto k = model.findDof(name)) {
    const Where& first = dof_where[*k];
    w.fail("DOF name '" + name + "' is already used" + (first.line > 0 ? " at line " + std::to_string(first.line) : ""));
  }
  Dof d;
  d.name = name;
  d.kind = kind;
  d.body = body;
  d.local = local;
  model.dofs.push_back(d);
  dof_where.push_back(w);
  dof_angular.push_back(angular);
}

int CaseBuild::dofIndex(const std::string& name, const Where& w) const {
  if (const auto k = model.findDof(name)) return *k;
  w.fail("no DOF named '" + name + "' (DOFs: " + names(model.dofs) + ")");
}

int CaseBuild::bodyIndex(const std::string& name, const Where& w) const {
  if (const auto k = model.findBody(name)) return *k;
  w.fail("no body named '" + name + "' (bodies: " + names(model.bodies) + ")");
}

int CaseBuild::inputIndex(const std::string& name, const Where& w) const {
  if (const auto k = model.findInput(name)) return *k;
  w.fail("no input named '" + name + "' (inputs: " + names(model.inputs) + ")");
}

int CaseBuild::pointIndex(int b, const std::string& name, const Where& w) const {
  const auto& pts = model.bodies[b].points;
  for (size_t i = 0; i < pts.size(); ++i)
    if (pts[i].name == name) return static_cast<int>(i);
  w.fail("body '" + model.bodies[b].name + "' has no point named '" + name + "' (points: " + names(pts) + ")");
}

void rethrowAt(const Where& w, const std::exception& e) {
  throw InputError(where(w.file, w.line, "", e.what()));
}

}  // namespace whirl
