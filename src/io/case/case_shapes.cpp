// Shape functions of a beam in a case (`shapes:`): polynomial, one_minus_cos, clamped_topmass,
// torsion_sine and table; or a map {from: fem} (case_fem_shapes.cpp). Each shape is one elastic DOF named after the
// shape.
#include <charconv>
#include <cmath>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/case/case_columns.hpp"
#include "src/io/case/case_reader.hpp"

namespace whirl {
namespace {

const std::vector<std::string> kTableColumns = {"x", "fraction", "uy", "uz", "tx", "uy1", "uz1", "tx1", "uy2", "uz2"};

// Unit direction of a bending shape: y, z or [dy, dz].
std::pair<double, double> readDirection(const CaseNode& shape) {
  const CaseNode d = shape.at("direction");
  if (d.isScalar()) {
    const std::string s = d.text();
    if (s == "y") return {1.0, 0.0};
    if (s == "z") return {0.0, 1.0};
    d.fail("expected y, z or [dy, dz], got '" + s + "'");
  }
  const std::vector<double> v = d.numbers();
  if (v.size() != 2) d.fail("expected y, z or [dy, dz]");
  if (v[0] == 0 && v[1] == 0) d.fail("the direction must not be zero");
  return {v[0], v[1]};
}

// {power: coefficient} → coefficients by power.
std::vector<double> readCoefficients(const CaseNode& c) {
  std::vector<double> a;
  const std::vector<MapEntry> entries = c.entries();
  if (entries.empty()) c.fail("expected a map {power: coefficient}, e.g. {2: 0.7, 3: 0.3}");
  for (const MapEntry& e : entries) {
    int k = -1;
    const auto [end, ec] = std::from_chars(e.key.data(), e.key.data() + e.key.size(), k);
    if (ec != std::errc() || end != e.key.data() + e.key.size() || k < 0 || k > 30)
      e.key_where.fail("a power must be a whole number from 0 to 30, got '" + e.key + "'");
    if (static_cast<int>(a.size()) <= k) a.resize(k + 1, 0.0);
    a[k] = e.value.number();
  }
  return a;
}

// Builds a shape with a core constructor; its InputError is re-thrown at the shape.
template <class F>
ShapePtr located(const CaseNode& s, F&& make) {
  try {
    return make();
  } catch (const InputError& e) {
    rethrowAt(s.where(), e);
  }
}

ShapePtr tableFromColumns(const CaseNode& s, const std::string& name, double L, bool& angular) {
  const Columns c = readColumns(s, kTableColumns, {"name", "type"});
  ShapeTable t;
  t.x = stations(s, c, L, true);
  auto col = [&](const char* key) { return c.count(key) ? c.at(key).values : VecX(); };
  t.uy = col("uy");
  t.uz = col("uz");
  t.tx = col("tx");
  t.uy1 = col("uy1");
  t.uz1 = col("uz1");
  t.tx1 = col("tx1");
  t.uy2 = col("uy2");
  t.uz2 = col("uz2");
  if (!t.uy.size() && !t.uz.size() && !t.tx.size()) s.fail("a table shape needs a column uy, uz or tx");
  angular = !t.uy.size() && !t.uz.size();
  return located(s, [&] { return tableShape(name, t); });
}

// A shape that overflows (e.g. cosh of a high mode) would give NaN integrals: refuse it here.
void requireFinite(const CaseNode& s, const Shape& shape, double L) {
  for (int k = 0; k <= 200; ++k) {
    const ShapeValue v = shape.eval(L * k / 200);
    for (double d : {v.uy, v.uz, v.tx, v.uy1, v.uz1, v.tx1, v.uy2, v.uz2})
      if (!std::isfinite(d)) s.fail("the shape is not finite at x = " + num(L * k / 200) + " m (mode too high?)");
  }
}

}  // namespace

std::vector<ShapePtr> readShapes(const CaseNode& beam, const BeamProperties& props, int index, CaseBuild& build) {
  std::vector<ShapePtr> shapes;
  const auto list = beam.find("shapes");
  if (!list) return shapes;
  if (list->isMap()) return readFemShapes(*list, props, index, build);
  const double L = props.length;
  for (const CaseNode& s : list->items()) {
    const std::string type = s.at("type").text();
    const CaseNode name_node = s.at("name");
    const std::string name = name_node.text();
    bool angular = false;
    if (type == "polynomial") {
      s.allowKeys({"name", "type", "direction", "coefficients", "reference_length", "offset", "normalize"});
      const auto [dy, dz] = readDirection(s);
      std::vector<double> a = readCoefficients(s.at("coefficients"));
      // normalize: divide by Σ a_k so that u(reference_length) = 1 ([BranlardGeisler2022, eq. 47], YAMS).
      if (s.find("normalize") && s.at("normalize").boolean()) {
        double sum = 0;
        for (double c : a) sum += c;
        if (std::abs(sum) < 1e-12) s.at("normalize").fail("the coefficients sum to zero");
        for (double& c : a) c /= sum;
      }
      // u = Σ a_k ((x + offset)/reference_length)^k; defaults: offset 0, the beam length.
      const double ref = s.find("reference_length") ? s.at("reference_length").number() : L;
      const double x0 = s.find("offset") ? s.at("offset").number() : 0.0;
      if (!(ref > 0)) s.at("reference_length").fail("must be positive");
      shapes.push_back(located(s, [&, dy = dy, dz = dz] { return polynomialShape(name, ref, a, dy, dz, x0); }));
    } else if (type == "one_minus_cos") {
      s.allowKeys({"name", "type", "direction"});
      const auto [dy, dz] = readDirection(s);
      shapes.push_back(located(s, [&, dy = dy, dz = dz] { return oneMinusCosShape(name, L, dy, dz); }));
    } else if (type == "clamped_topmass") {
      s.allowKeys({"name", "type", "direction", "mode", "tip_mass_ratio"});
      const auto [dy, dz] = readDirection(s);
      const int mode = s.at("mode").integer();
      const double ratio = s.at("tip_mass_ratio").number();
      if (mode < 1 || mode > limits::kMaxAnalyticShapeMode)
        s.at("mode").fail("the mode number must be from 1 to " + std::to_string(limits::kMaxAnalyticShapeMode) +
                          " (src/base/limits.hpp)");
      if (ratio < 0) s.at("tip_mass_ratio").fail("must not be negative");
      shapes.push_back(located(s, [&, dy = dy, dz = dz] { return clampedTopMassShape(name, L, mode, ratio, dy, dz); }));
    } else if (type == "torsion_sine") {
      s.allowKeys({"name", "type", "mode"});
      const int mode = s.at("mode").integer();
      if (mode < 1 || mode > limits::kMaxAnalyticShapeMode)
        s.at("mode").fail("the mode number must be from 1 to " + std::to_string(limits::kMaxAnalyticShapeMode) +
                          " (src/base/limits.hpp)");
      shapes.push_back(located(s, [&] { return torsionSineShape(name, L, mode); }));
      angular = true;
    } else if (type == "table") {
      shapes.push_back(tableFromColumns(s, name, L, angular));
    } else {
      s.at("type").fail("unknown shape type '" + type +
                        "' (allowed: polynomial, one_minus_cos, clamped_topmass, torsion_sine, table)");
    }
    requireFinite(s, *shapes.back(), L);
    build.addDof(name, DofKind::Elastic, index, static_cast<int>(shapes.size()) - 1, name_node.where(), angular);
  }
  return shapes;
}

}  // namespace whirl
