// NREL 5MW tower and blade FE shapes from the ElastoDyn distributed properties (shapes=fem) against
// (a) the FEM mode shapes shipped with the data, cases/nrel5mw/NREL5MW_*_FEM_Modes.csv, and
// (b) the ElastoDyn polynomials of the input files, which NREL fitted to BModes modes.
//
// What the CSV files are: their headers name columns only (x, displacements U and rotations V of two
// modes; blade x = r from the rotor centre, 1.5 … 63 m at the blade-file stations; tower x = height,
// 0 … 87.6 m), both modes scaled to unit tip displacement. They give no frequencies and do not say
// which top mass, rotor speed or twist they assume, so only shapes are compared (MAC and the largest
// deviation), with tolerances set from what the compared models leave out (each test says so).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "src/fem/shape_comparison.hpp"
#include "src/model/elastodyn_model.hpp"

namespace whirl {
namespace {

const std::string kDir = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/";

// Whitespace-separated numbers, '#' lines skipped.
std::vector<std::vector<double>> readColumns(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::vector<double> r;
    for (double v; s >> v;) r.push_back(v);
    if (!r.empty()) rows.push_back(r);
  }
  return rows;
}

// A table shape from the columns (uy, uz) of the file, x shifted by x0; slopes by finite differences.
ShapePtr csvShape(const std::vector<std::vector<double>>& rows, double x0, int col_y, int col_z) {
  ShapeTable t;
  const auto n = static_cast<Eigen::Index>(rows.size());
  t.x.resize(n);
  t.uy = VecX::Zero(n);
  t.uz = VecX::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    t.x(i) = rows[i][0] - x0;
    if (col_y >= 0) t.uy(i) = rows[i][col_y];
    if (col_z >= 0) t.uz(i) = rows[i][col_z];
  }
  return tableShape("csv", t);
}

const fem::FlexibleBeam& beam(const std::vector<fem::FlexibleBeam>& beams, const std::string& name) {
  for (const auto& b : beams)
    if (b.body == name) return b;
  throw std::runtime_error("no body " + name);
}

const std::vector<fem::FlexibleBeam>& parked() {
  static const std::vector<fem::FlexibleBeam> b = readElastoDynFlexibleBeams(kDir + "Main_Onshore.fst", {"RotSpeed=0"});
  return b;
}

TEST(Nrel5mwFemShapes, TowerFirstModesMatchTheFemModesFile) {
  const fem::FlexibleBeam& tw = beam(parked(), "tower");
  const std::vector<fem::ShapeComparison> rows = fem::compareShapes(tw);
  const auto csv = readColumns(kDir + "NREL5MW_Tower_Onshore_FEM_Modes.csv");
  const double L = tw.input.props.length;
  // FA 1 (body z) against U1, SS 1 (body y) against U2 (the file's two columns are equal: the
  // ElastoDyn tower is axisymmetric in stiffness).
  const ShapePtr fa = csvShape(csv, 0, -1, 1), ss = csvShape(csv, 0, 3, -1);
  for (const auto& r : rows) {
    if (r.index != 1) continue;
    const ShapePtr& ref = r.direction == 'z' ? fa : ss;
    const double mac = fem::shapeMac(*r.mode.shape, *ref, L), dev = fem::shapeMaxDeviation(*r.mode.shape, *ref, L);
    std::printf("tower %s: FE %.4f Hz, MAC vs FEM_Modes.csv %.8f, max dev %.5f\n", r.shape.c_str(), r.freq_hz, mac, dev);
    EXPECT_GT(mac, 0.999) << r.shape;
    EXPECT_LT(dev, 0.02) << r.shape;
  }
}

TEST(Nrel5mwFemShapes, BladeFlapAndEdgeMatchTheFemModesFile) {
  const fem::FlexibleBeam& bl = beam(parked(), "blade 1");
  const std::vector<fem::ShapeComparison> rows = fem::compareShapes(bl);
  const auto csv = readColumns(kDir + "NREL5MW_Blade_FEM_Modes.csv");
  const double L = bl.input.props.length, hub = 1.5;
  // Columns: 1–3 U1 (x flap, y edge, z), 7–9 U2. Blade body y = flap (j1), z = edge (j2).
  const ShapePtr m1 = csvShape(csv, hub, 1, 2), m2 = csvShape(csv, hub, 7, 8);
  for (const auto& r : rows) {
    if (r.index != 1) continue;
    const ShapePtr& ref = r.direction == 'y' ? m1 : m2;
    const double mac = fem::shapeMac(*r.mode.shape, *ref, L), dev = fem::shapeMaxDeviation(*r.mode.shape, *ref, L);
    std::printf("blade %s: FE %.4f Hz, MAC vs FEM_Modes.csv %.8f, max dev %.5f\n", r.shape.c_str(), r.freq_hz, mac, dev);
    EXPECT_GT(mac, 0.999) << r.shape;
    EXPECT_LT(dev, 0.02) << r.shape;
  }
}

TEST(Nrel5mwFemShapes, FittedPolynomialsAgainstTheElastoDynPolynomials) {
  for (const std::string body : {"tower", "blade 1"}) {
    const fem::FlexibleBeam& b = beam(parked(), body);
    const double L = b.input.props.length;
    for (const auto& r : fem::compareShapes(b)) {
      std::vector<double> a(7, 0.0);
      for (int k = 0; k < 5; ++k) a[k + 2] = r.fit.coeffs[k];
      const ShapePtr fit = polynomialShape("fit", L, a, r.direction == 'y', r.direction == 'z');
      const ShapePtr* cur = nullptr;
      for (const auto& s : b.shapes)
        if (s->name == r.shape) cur = &s;
      const double mac = fem::shapeMac(*fit, **cur, L);
      std::printf("%s %s: fit rms %.2e, a = [%.4f %.4f %.4f %.4f %.4f], MAC(fit, ElastoDyn) %.6f, MAC(FE, ElastoDyn) %.6f, dev %.4f\n",
                  body.c_str(), r.shape.c_str(), r.fit.rms, r.fit.coeffs[0], r.fit.coeffs[1], r.fit.coeffs[2],
                  r.fit.coeffs[3], r.fit.coeffs[4], mac, r.mac, r.max_deviation);
      EXPECT_GT(mac, 0.99) << body << " " << r.shape;
    }
  }
}

}  // namespace
}  // namespace whirl
