// Blade elements on `fe_blade` bodies (`aero:` on a blade of 6 × 6 sections, src/io/case/case_aero.cpp):
// the example rotor of cases/aero_rotor, its uniform Rayleigh–Ritz blades (exact cantilever shapes) written
// as FE blades of the same section properties, has the same aeroelastic flap and edge modes at the case's
// operating point (8 m/s, 12 rpm) — two independent paths to the blade body, sharing the BEM and the
// element loads — and an aerodynamic-centre offset on the FE blade is a rigid arm that turns with the
// section, so the lift reaches the torsion mode.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "tests/unit/case_file_test_util.hpp"

namespace whirl {
namespace {

std::string sourceText(const std::string& relative) {
  std::ifstream in(std::string(WHIRL_SOURCE_DIR) + "/" + relative, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example's blade, uniform: m = 300 kg/m, EI 4e9 N m² flapwise (body y = x_r: about y_r, K55) and
// 1e10 edgewise (body z = y_r: about x_r, K44); shear, extension and torsion stiff enough not to matter
// below the second flap mode unless `torsion_gj` lowers the torsion; no rotary inertia but the torsion's.
std::string feBladeKeys(int modes, double torsion_gj) {
  std::ostringstream s;
  s << std::setprecision(17);
  s << "    elements: 20\n    modes: " << modes << "\n"
    << "    reference_axis: {kp_xr: [0, 0, 0], kp_yr: [0, 0, 0], kp_zr: [0, 20, 40], twist: [0, 0, 0]}\n"
    << "    sections:\n";
  for (const char* eta : {"0", "1"})
    s << "      - eta: " << eta << "\n"
      << "        K: [[1e12, 0, 0, 0, 0, 0], [0, 1e12, 0, 0, 0, 0], [0, 0, 1e12, 0, 0, 0],\n"
      << "            [0, 0, 0, 1e10, 0, 0], [0, 0, 0, 0, 4e9, 0], [0, 0, 0, 0, 0, " << torsion_gj << "]]\n"
      << "        M: [[300, 0, 0, 0, 0, 0], [0, 300, 0, 0, 0, 0], [0, 0, 300, 0, 0, 0],\n"
      << "            [0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 10]]\n";
  return s.str();
}

// The example case with its blades' beam keys replaced (fe = true) or its structural damping taken out
// (fe = false: the FE blades have none, mu = 0), in `dir` with the case's airfoil and station files.
std::string writeRotor(const testing::TempCaseDir& dir, bool fe, int modes = 2, double torsion_gj = 1e12,
                       const std::string& stations = "blade_aero.csv") {
  std::string text = sourceText("cases/aero_rotor/aero_rotor.yaml");
  const std::regex beam(R"(    type: beam\n    parent: hub\n([\s\S]*?)    length: 40\n[\s\S]*?    damping: [^\n]*\n)");
  text = fe ? std::regex_replace(text, beam, "    type: fe_blade\n    parent: hub\n$1" + feBladeKeys(modes, torsion_gj))
            : std::regex_replace(text, std::regex(R"(damping: \{ratio: \[0.005, 0.005\]\})"),
                                 "damping: {ratio: [0, 0]}");
  text = std::regex_replace(text, std::regex("file: blade_aero.csv"), "file: " + stations);
  std::filesystem::create_directories(dir.dir / "airfoils");
  dir.write("airfoils/NACA64_A17.dat", sourceText("cases/aero_rotor/airfoils/NACA64_A17.dat"));
  dir.write("blade_aero.csv", sourceText("cases/aero_rotor/blade_aero.csv"));
  return dir.write("rotor.yaml", text);
}

struct Root {
  double freq_hz, damping;
};

// The oscillating roots of the linear model at the case's operating point, by frequency.
std::vector<Root> roots(const Model& m) {
  const LinearModel lin = linearize(m, solveOperatingPoint(m, initialPoint(m)));
  const Eigen::VectorXcd ev = Eigen::EigenSolver<MatX>(lin.A, false).eigenvalues();
  std::vector<Root> out;
  for (const auto& l : ev)
    if (l.imag() > 1e-6) out.push_back({std::abs(l) / (2 * std::numbers::pi), -l.real() / std::abs(l)});
  std::sort(out.begin(), out.end(), [](const Root& a, const Root& b) { return a.freq_hz < b.freq_hz; });
  return out;
}

TEST(CaseFeBladeAero, FeBladesOfTheExampleRotorHaveItsAeroelasticModes) {
  testing::TempCaseDir beam_dir, fe_dir;
  const Model beam = readCase(writeRotor(beam_dir, false)), fe = readCase(writeRotor(fe_dir, true));
  ASSERT_EQ(fe.aero.blades.size(), 3u);
  ASSERT_EQ(fe.aero.blades[0].stations.size(), beam.aero.blades[0].stations.size());
  ASSERT_EQ(fe.ndof(), beam.ndof());
  for (int k = 0; k < fe.ndof(); ++k) EXPECT_EQ(fe.dofs[k].name, beam.dofs[k].name);
  const std::vector<Root> a = roots(beam), b = roots(fe);
  ASSERT_EQ(a.size(), 6u);  // flap and edge of three blades on a rigid hub at a frozen azimuth
  ASSERT_EQ(b.size(), 6u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    // The FE blade's modes converge to the exact cantilever shapes with the mesh (20 elements: measured
    // 2e-4 in frequency, 1e-3 in damping); the aerodynamic damping follows the shapes at the stations.
    EXPECT_NEAR(b[k].freq_hz, a[k].freq_hz, 5e-4 * a[k].freq_hz) << "root " << k;
    EXPECT_NEAR(b[k].damping, a[k].damping, 3e-3 * std::abs(a[k].damping)) << "root " << k;
  }
  // Flap modes in attached flow: strongly damped by the air (structural damping is zero in both).
  EXPECT_GT(a[0].damping, 0.05);
}

TEST(CaseFeBladeAero, AerodynamicCentreAftOfTheAxisStiffensAndDampsTheTorsion) {
  // Torsion soft enough to be among the three modes kept (GJ 1e7 N m²: about 6 Hz), the aerodynamic centre
  // 0.3 m off the axis along body +z — in the rotor plane against the rotation, towards the trailing edge.
  // On the rigid arm the lift now twists the section: a nose-up twist raises the lift behind the axis,
  // whose moment turns the nose down again (the classical aerodynamic centre aft of the elastic axis: no
  // divergence, Bisplinghoff, Ashley & Halfman 1955), so the torsion gains stiffness and damping from the air.
  testing::TempCaseDir on_dir, aft_dir;
  std::string csv = sourceText("cases/aero_rotor/blade_aero.csv");
  csv = std::regex_replace(csv, std::regex("x,   chord, twist_deg, airfoil"), "x,   chord, twist_deg, airfoil, ac_z");
  csv = std::regex_replace(csv, std::regex("(, 1)\n"), "$1, 0.3\n");
  aft_dir.write("aft.csv", csv);
  const Model on = readCase(writeRotor(on_dir, true, 3, 1e7));
  const Model aft = readCase(writeRotor(aft_dir, true, 3, 1e7, "aft.csv"));
  const int torsion = *on.findDof("blade 1 torsion 1");
  const LinearModel a = linearize(on, solveOperatingPoint(on, initialPoint(on)));
  const LinearModel b = linearize(aft, solveOperatingPoint(aft, initialPoint(aft)));
  const auto row = [&](const LinearModel& l) {
    return static_cast<int>(std::find(l.dofs.begin(), l.dofs.end(), torsion) - l.dofs.begin());
  };
  const int ra = row(a), rb = row(b);
  // Measured: the modal stiffness 3.17e5 gains 7.06e4 (22 %); the damping 614, where the axis' own row of C
  // has entries up to 277 (the section's speed through the air as it twists).
  EXPECT_GT(b.K(rb, rb) - a.K(ra, ra), 0.1 * a.K(ra, ra));
  EXPECT_GT(b.C(rb, rb) - a.C(ra, ra), a.C.row(ra).cwiseAbs().maxCoeff());
}

TEST(CaseFeBladeAero, BendingMomentOutputOnAnFeBladeComesFromItsElements) {
  // A `type: moment` output at the root of blade 1: its gain on the flap mode is the FE blade's
  // element resultant (fem::blade6MomentGains), within 1e-3 of the beam rotor's exact cantilever
  // curvature EI φ''(0) (measured 4.9e-4 at 20 elements); the edge mode adds nothing to the flap moment.
  const std::string output = "outputs:\n  - {name: M, type: moment, body: blade 1, x: 0, component: y}\n";
  testing::TempCaseDir beam_dir, fe_dir;
  const auto withMoment = [&](const testing::TempCaseDir& dir, bool fe) {
    const std::string path = writeRotor(dir, fe);
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return readCase(dir.write("rotor.yaml", std::regex_replace(text.str(), std::regex("outputs:\n"), output)));
  };
  const Model beam = withMoment(beam_dir, false), fe = withMoment(fe_dir, true);
  const auto gain = [](const Model& m, const std::string& dof) {
    const Output& o = m.outputs[static_cast<std::size_t>(*m.findOutput("M"))];
    for (const auto& t : o.terms)
      if (t.first == *m.findDof(dof)) return t.second;
    return 0.0;
  };
  const double exact = gain(beam, "blade 1 flap 1");
  EXPECT_GT(exact, 1e6);
  EXPECT_NEAR(gain(fe, "blade 1 flap 1"), exact, 1e-3 * exact);
  EXPECT_NEAR(gain(fe, "blade 1 edge 1"), 0.0, 1e-9 * exact);
}

}  // namespace
}  // namespace whirl
