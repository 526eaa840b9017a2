#include "src/model/model_builder.hpp"

#include <utility>

namespace whirl {
namespace {

template <class V>
std::string names(const V& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i.name;
  return s.empty() ? "none" : s;
}

}  // namespace

int ModelBuilder::addBody(Body body, const Where& at) {
  model_.bodies.push_back(std::move(body));
  body_where_.push_back(at);
  return static_cast<int>(model_.bodies.size()) - 1;
}

int ModelBuilder::addDof(Dof dof, const Where& at) {
  if (dof.name.empty()) at.fail("a DOF name must not be empty");
  if (const auto k = model_.findDof(dof.name)) {
    const Where& first = dof_where_[*k];
    at.fail("DOF name '" + dof.name + "' is already used" +
            (first.line > 0 ? " at line " + std::to_string(first.line) : ""));
  }
  model_.dofs.push_back(std::move(dof));
  dof_where_.push_back(at);
  return static_cast<int>(model_.dofs.size()) - 1;
}

int ModelBuilder::dofIndex(const std::string& name, const Where& at) const {
  if (const auto k = model_.findDof(name)) return *k;
  at.fail("no DOF named '" + name + "' (DOFs: " + names(model_.dofs) + ")");
}

int ModelBuilder::bodyIndex(const std::string& name, const Where& at) const {
  if (const auto k = model_.findBody(name)) return *k;
  at.fail("no body named '" + name + "' (bodies: " + names(model_.bodies) + ")");
}

int ModelBuilder::inputIndex(const std::string& name, const Where& at) const {
  if (const auto k = model_.findInput(name)) return *k;
  at.fail("no input named '" + name + "' (inputs: " + names(model_.inputs) + ")");
}

int ModelBuilder::pointIndex(int body, const std::string& name, const Where& at) const {
  const auto& pts = model_.bodies[body].points;
  for (size_t i = 0; i < pts.size(); ++i)
    if (pts[i].name == name) return static_cast<int>(i);
  at.fail("body '" + model_.bodies[body].name + "' has no point named '" + name + "' (points: " + names(pts) + ")");
}

Model ModelBuilder::finish() && {
  finalize(model_);
  return std::move(model_);
}

}  // namespace whirl
