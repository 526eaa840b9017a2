// `shapes: {from: fem, …}` of a beam: the shape functions are the lowest bending modes of the beam's
// own distributed properties, computed by the beam FE (src/fem/mode_shapes.hpp) when the case is read.
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/case/case_reader.hpp"

namespace whirl {

fem::ModeShapeInput readFemShapeSettings(const CaseNode& s, const BeamProperties& props) {
  s.allowKeys(
      {"from", "elements", "tip_mass", "axial_gravity", "rotor_speed_rpm", "hub_radius", "rotation_axis", "modes"});
  fem::ModeShapeInput in;
  in.props = props;
  if (const auto e = s.find("elements")) {
    in.elements = e->integer();
    if (in.elements < 1 || in.elements > limits::kMaxFemShapeElements)
      e->fail("the number of elements must be from 1 to " + std::to_string(limits::kMaxFemShapeElements) +
              " (src/base/limits.hpp)");
  }
  if (const auto t = s.find("tip_mass")) {
    t->allowKeys({"mass", "cog", "inertia"});
    in.tip.mass = t->at("mass").number();
    if (in.tip.mass < 0) t->at("mass").fail("negative mass " + num(in.tip.mass) + " kg");
    in.tip.cm = t->vec3("cog", Vec3::Zero());
    const Vec3 J = t->vec3("inertia", Vec3::Zero());
    if ((J.array() < 0).any()) t->at("inertia").fail("the principal inertias must be ≥ 0");
    in.tip.inertia = J.asDiagonal();
  }
  in.axial_gravity = s.number("axial_gravity", 0.0);
  in.rotor_speed = s.number("rotor_speed_rpm", 0.0) * std::numbers::pi / 30.0;
  in.hub_radius = s.number("hub_radius", 0.0);
  if (const auto a = s.find("rotation_axis")) {
    if (a->isScalar() && a->text() == "y") in.rotation_axis = Vec3::UnitY();
    else if (a->isScalar() && a->text() == "z") in.rotation_axis = Vec3::UnitZ();
    else if (a->isScalar()) a->fail("expected y, z or [x, y, z], got '" + a->text() + "'");
    else in.rotation_axis = a->vec3();
    if (Vec3(0, in.rotation_axis(1), in.rotation_axis(2)).norm() == 0)
      a->fail("the rotation axis must not be along the beam (give y, z or [x, y, z])");
  }
  return in;
}

std::vector<ShapePtr> readFemShapes(const CaseNode& s, const BeamProperties& props, int index, CaseBuild& build) {
  const std::string from = s.at("from").text();
  if (from != "fem") s.at("from").fail("unknown shape source '" + from + "' (allowed: fem)");
  const fem::ModeShapeInput in = readFemShapeSettings(s, props);
  struct Request {
    std::string name;
    char dir;
    int mode;
    CaseNode node;
  };
  std::vector<Request> req;
  int ny = 0, nz = 0;
  for (const CaseNode& m : s.at("modes").items()) {
    m.allowKeys({"name", "direction", "mode"});
    const std::string d = m.at("direction").text();
    if (d != "y" && d != "z") m.at("direction").fail("expected y or z, got '" + d + "'");
    const int j = m.at("mode").integer();
    if (j < 1 || j > limits::kMaxFemShapeMode)
      m.at("mode").fail("the mode number must be from 1 to " + std::to_string(limits::kMaxFemShapeMode) +
                        " (src/base/limits.hpp)");
    (d == "y" ? ny : nz) = std::max(d == "y" ? ny : nz, j);
    req.push_back({m.at("name").text(), d[0], j, m});
  }
  if (req.empty()) s.at("modes").fail("list at least one mode, e.g. {name: tower FA 1, direction: z, mode: 1}");
  std::vector<fem::BeamMode> modes;
  try {
    modes = fem::beamModes(in, ny, nz);
  } catch (const std::exception& e) {
    rethrowAt(s.where(), e);
  }
  std::vector<ShapePtr> shapes;
  for (const Request& r : req)
    for (const fem::BeamMode& b : modes)
      if (b.direction == r.dir && b.index == r.mode) {
        shapes.push_back(tableShape(r.name, b.table));
        build.addDof(r.name, DofKind::Elastic, index, static_cast<int>(shapes.size()) - 1, r.node.at("name").where(),
                     false);
      }
  return shapes;
}

}  // namespace whirl
