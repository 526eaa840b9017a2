// NREL 5MW tower and blade FE shapes from the ElastoDyn distributed properties (shapes=fem) against
// (a) the FEM mode shapes shipped with the data, cases/nrel5mw/NREL5MW_*_FEM_Modes.csv, and
// (b) the ElastoDyn polynomials of the input files, which NREL fitted to BModes modes.
//
// What the CSV files are: their headers name columns only (x, displacements U and rotations V of two
// modes; blade x = r from the rotor centre, 1.5 … 63 m at the blade-file stations; tower x = height,
// 0 … 87.6 m), both modes scaled to unit tip displacement. They give no frequencies and do not say
// which top mass, rotor speed or twist they assume; the tests below find it by matching: the tower
// alone (no top mass, no gravity) and the untwisted blade at 0 rpm. Only shapes are compared (MAC and
// the largest deviation), with tolerances set from what the compared models leave out (each test says so).
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "src/fem/shape_comparison.hpp"
#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"
#include "src/io/openfast/elastodyn/elastodyn_tower.hpp"
#include "src/turbine/elastodyn_model.hpp"

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

// The tower-top body of shapes=fem is the rotor-nacelle assembly: 350,000 kg ([Jonkman2009,
// Table 1-1]: rotor 110,000 kg, nacelle 240,000 kg), checked to 0.2 % (the blade
// mass integrates the piecewise-linear BMassDen exactly, FAST 2009 on AeroDyn's 17 elements), and the
// same as the ElastoDyn model's bodies above the tower to 0.5 % (those use BldNodes = 17 midpoints).
TEST(Nrel5mwFemShapes, TowerTopMassIsTheRotorNacelleAssembly) {
  const fem::ModeShapeInput& in = beam(parked(), "tower").input;
  EXPECT_NEAR(in.tip.mass, 350000.0, 0.002 * 350000.0);
  const Model m = readElastoDynModel(kDir + "Main_Onshore.fst", {"RotSpeed=0"});
  double above = 0;
  for (const Body& b : m.bodies)
    if (b.name != "tower") above += b.inertia.mass;
  EXPECT_NEAR(in.tip.mass, above, 0.005 * above);
  // Centre of mass: above the tower top (Twr2Shft 1.96 m, nacelle CM 1.75 m up) and upwind (rotor
  // overhang −5.02 m against the nacelle CM +1.9 m downwind): body x up, z = downwind.
  EXPECT_GT(in.tip.cm(0), 1.5);
  EXPECT_LT(in.tip.cm(2), 0.0);
  EXPECT_DOUBLE_EQ(in.axial_gravity, 9.80665);
}

// The tower file matches the tower ALONE (no top mass, no gravity): its shape is the exact clamped-free
// mode of the ElastoDyn properties to 2e-5, against 0.046 for the tower with its 350 t top (MAC 0.9982).
// The file's 11 stations hold 16 digits; what is left is the FE discretization on either side:
// MAC 1 − 1e-8, max deviation 1e-4 per unit tip. SS (U2) equals FA (U1) in the file: an axisymmetric tower.
TEST(Nrel5mwFemShapes, TowerAloneMatchesTheFemModesFile) {
  fem::ModeShapeInput in = beam(parked(), "tower").input;
  in.tip = fem::TipBody{};
  in.axial_gravity = 0;
  const double L = in.props.length;
  const auto csv = readColumns(kDir + "NREL5MW_Tower_Onshore_FEM_Modes.csv");
  const ShapePtr fa = csvShape(csv, 0, -1, 1), ss = csvShape(csv, 0, 3, -1);
  for (const fem::BeamMode& m : fem::beamModes(in, 1, 1)) {
    const ShapePtr& ref = m.direction == 'z' ? fa : ss;
    EXPECT_GT(fem::shapeMac(*m.shape, *ref, L, 11), 1 - 1e-8) << m.direction;  // at the file's 11 stations
    EXPECT_LT(fem::shapeMaxDeviation(*m.shape, *ref, L, 11), 1e-4) << m.direction;
  }
  // With the top mass (what shapes=fem uses) the shape is visibly different: the file is not that case.
  const fem::BeamMode top = fem::beamModes(beam(parked(), "tower").input, 0, 1).at(0);
  EXPECT_GT(fem::shapeMaxDeviation(*top.shape, *fa, L, 11), 0.03);
}

// The blade file matches the UNTWISTED blade at 0 rpm: MAC 0.999995 for flap 1 and edge 1; the largest
// deviation is the file's own cross component (0.0021 of the tip, U1y and U2x), which an untwisted
// beam does not have, hence 0.005. With the structural twist ElastoDyn's model has (and shapes=fem
// uses), flap 1 has −0.11 of the tip in plane and edge 1 +0.20 out of plane, as ElastoDyn's twisted
// polynomials have (MAC 0.9992 and 0.9963 against them): the file is not that case (MAC 0.984, 0.976).
TEST(Nrel5mwFemShapes, UntwistedBladeMatchesTheFemModesFile) {
  fem::ModeShapeInput in = beam(parked(), "blade 1").input;
  const fem::ModeShapeInput twisted = in;
  in.props.twist = VecX();
  const double L = in.props.length, hub = 1.5;
  const auto csv = readColumns(kDir + "NREL5MW_Blade_FEM_Modes.csv");
  // Columns: 1–3 U1 (x flap, y edge, z), 7–9 U2. Blade body y = flap (j1), z = edge (j2).
  const ShapePtr m1 = csvShape(csv, hub, 1, 2), m2 = csvShape(csv, hub, 7, 8);
  for (const fem::BeamMode& m : fem::beamModes(in, 1, 1)) {
    const ShapePtr& ref = m.direction == 'y' ? m1 : m2;
    EXPECT_GT(fem::shapeMac(*m.shape, *ref, L), 0.99999) << m.direction;
    EXPECT_LT(fem::shapeMaxDeviation(*m.shape, *ref, L), 0.005) << m.direction;
  }
  for (const fem::BeamMode& m : fem::beamModes(twisted, 1, 1))
    EXPECT_LT(fem::shapeMac(*m.shape, *(m.direction == 'y' ? m1 : m2), L), 0.99) << m.direction;
}

// Fitted polynomials (ElastoDyn form) of the FE modes used by shapes=fem against the polynomials of the
// NREL 5MW files, which NREL fitted to BModes modes with assumptions the files do not state. The
// coefficients themselves are ill-conditioned (the tower FA 1 fit has a2 = 1.00, the file 0.70, for
// MAC 0.9999), so shapes are compared, as 1-D polynomials along their direction (MAC over 101 stations):
// - tower (top mass and centre of mass, gravity): measured 0.99989, 0.99993, 0.99953, 0.99892 (FA 1,
//   SS 1, FA 2, SS 2); with the rigid rotor's rotary inertia at the top the second modes fall to
//   0.987 and 0.977, so BModes' tower had the top mass but not that inertia (elastodyn_fem_shapes.hpp);
// - blade (twisted, 0 rpm; the fit is to the dominant component): measured 0.99970, 0.99999, 0.99834
//   (flap 1, edge 1, flap 2).
// Each tolerance sits just under its measured value (the gap is a property of the files, not of a
// precision); the largest gap, flap 2, is where the files' polynomials and the FE disagree most.
TEST(Nrel5mwFemShapes, FittedPolynomialsAgainstTheElastoDynFiles) {
  const io::ElastoDynTower tw = io::readElastoDynTower(kDir + "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat");
  const io::ElastoDynBlade bl = io::readElastoDynBlade(kDir + "NRELOffshrBsline5MW_Blade.dat");
  const std::map<std::string, std::pair<io::ModeShapeCoeffs, double>> file = {{"tower FA 1", {tw.TwFAM1Sh, 0.9998}},
                                                                              {"tower SS 1", {tw.TwSSM1Sh, 0.9998}},
                                                                              {"tower FA 2", {tw.TwFAM2Sh, 0.9989}},
                                                                              {"tower SS 2", {tw.TwSSM2Sh, 0.9985}},
                                                                              {"flap 1", {bl.BldFl1Sh, 0.9995}},
                                                                              {"edge 1", {bl.BldEdgSh, 0.9999}},
                                                                              {"flap 2", {bl.BldFl2Sh, 0.997}}};
  int compared = 0;
  for (const std::string body : {"tower", "blade 1"}) {
    const fem::FlexibleBeam& b = beam(parked(), body);
    const double L = b.input.props.length;
    for (const auto& r : fem::compareShapes(b)) {
      const auto& [c, tol] = file.at(r.shape);
      const ShapePtr fit = polynomialShape(
          "fit", L, {0, 0, r.fit.coeffs[0], r.fit.coeffs[1], r.fit.coeffs[2], r.fit.coeffs[3], r.fit.coeffs[4]}, 1, 0);
      const ShapePtr ed = polynomialShape("file", L, {0, 0, c[0], c[1], c[2], c[3], c[4]}, 1, 0);
      const double mac = fem::shapeMac(*fit, *ed, L);
      std::printf(
          "%s %s: FE %.4f Hz, fit a2..a6 = [%.4f %.4f %.4f %.4f %.4f] (rms %.1e), file [%.4f %.4f %.4f %.4f %.4f], MAC "
          "%.5f\n",
          body.c_str(), r.shape.c_str(), r.freq_hz, r.fit.coeffs[0], r.fit.coeffs[1], r.fit.coeffs[2], r.fit.coeffs[3],
          r.fit.coeffs[4], r.fit.rms, c[0], c[1], c[2], c[3], c[4], mac);
      EXPECT_GT(mac, tol) << body << " " << r.shape;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 7);
}

}  // namespace
}  // namespace whirl
