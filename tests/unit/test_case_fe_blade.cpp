// `fe_blade` bodies of a case (src/io/case/case_blade6.cpp): a blade written by hand with 6 × 6
// sections. Written from certification Test26's BeamDyn blade (cases/nrel5mw_beamdyn: the key points
// and the 49 stations of the BeamDyn files, every number to 17 digits), the case's clamped blade has
// the deck's blade body's frequencies to round-off: two paths — the YAML reader and the multibody
// linearization (M and K of the model) against the turbine's BeamDyn adapter and the body's shape
// integrals — sharing the FE blade (src/fem/blade6_body.hpp). Bad input is one InputError
// "file:line: key: reason".
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/shapes/beam.hpp"
#include "src/turbine/beamdyn_blade.hpp"
#include "tests/unit/case_file_test_util.hpp"

namespace whirl {
namespace {

const char* kBeamDyn = "/cases/nrel5mw_beamdyn/5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat";
constexpr int kElements = 20, kModes = 6;

std::string matrixText(const Eigen::Matrix<double, 6, 6>& A, const std::string& indent) {
  std::ostringstream s;
  s << std::setprecision(17);
  for (int i = 0; i < 6; ++i) {
    s << indent << "- [";
    for (int j = 0; j < 6; ++j) s << (j ? ", " : "") << A(i, j);
    s << "]\n";
  }
  return s.str();
}

// The case: the BeamDyn blade as an fe_blade body clamped to the ground, no gravity.
std::string caseFromBeamDyn(const io::BeamDynInput& bd) {
  std::ostringstream s;
  s << std::setprecision(17);
  s << "name: fe blade\ngravity: 0\nbodies:\n  - name: blade\n    type: fe_blade\n";
  s << "    elements: " << kElements << "\n    modes: " << kModes << "\n";
  s << "    mu: [";
  for (int k = 0; k < 6; ++k) s << (k ? ", " : "") << bd.blade.mu[static_cast<std::size_t>(k)];
  s << "]\n    reference_axis:\n";
  const char* names[3] = {"kp_xr", "kp_yr", "kp_zr"};
  for (int c = 0; c < 3; ++c) {
    s << "      " << names[c] << ": [";
    for (std::size_t i = 0; i < bd.key_points.size(); ++i) s << (i ? ", " : "") << bd.key_points[i].r(c);
    s << "]\n";
  }
  s << "      twist: [";
  for (std::size_t i = 0; i < bd.key_points.size(); ++i) s << (i ? ", " : "") << bd.key_points[i].twist;
  s << "]\n    points: [{name: tip, fraction: 1}]\n    sections:\n";
  for (const io::BeamDynStation& st : bd.blade.stations) {
    s << "      - eta: " << st.eta << "\n        K:\n" << matrixText(st.K, "          ");
    s << "        M:\n" << matrixText(st.M, "          ");
  }
  return s.str();
}

// Frequencies [Hz] of K q = ω² M q.
VecX frequencies(const MatX& K, const MatX& M) {
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(0.5 * (K + K.transpose()), 0.5 * (M + M.transpose()));
  return es.eigenvalues().cwiseMax(0).cwiseSqrt() / (2 * std::numbers::pi);
}

TEST(CaseFeBlade, Test26BladeWrittenInACaseHasTheDeckBladesFrequencies) {
  const io::BeamDynInput bd = io::readBeamDyn(std::string(WHIRL_SOURCE_DIR) + kBeamDyn);
  testing::TempCaseDir dir;
  const Model m = readCase(dir.write("blade.yaml", caseFromBeamDyn(bd)));
  ASSERT_EQ(m.ndof(), kModes);
  const LinearModel lin = linearize(m, initialPoint(m));
  const VecX f_case = frequencies(lin.K, lin.M);

  // The deck's blade: the rotor builder's body (src/turbine/elastodyn_rotor.cpp: 4 trapezoid points per
  // element), clamped and parked: K q = ω² M_ee q with M_ee = Σ_k S_kk of its elastic coordinates.
  const BeamDynBladeBody fe = beamDynBladeBody(bd, {kElements, kModes});
  BeamOptions o;
  o.integration = {BeamIntegration::Trapezoid, 4 * kElements};
  const BeamBody bb = buildBeamBody(fe.beam.props, fe.beam.shapes, o, "blade");
  MatX Mee = MatX::Zero(kModes, kModes);
  for (int k = 0; k < 3; ++k) Mee += bb.inertia.S[4 * k].block(1, 1, kModes, kModes);
  const VecX f_deck = frequencies(fe.K, Mee);

  for (int k = 0; k < kModes; ++k) {
    EXPECT_EQ(m.dofs[k].name, "blade " + fe.beam.shapes[static_cast<std::size_t>(k)]->name);
    // Same inputs to the last digit, two assemblies of M: round-off.
    EXPECT_NEAR(f_case(k), f_deck(k), 1e-9 * f_deck(k)) << "mode " << k + 1;
  }
  // The NREL 5MW blade's first flap and edge modes, clamped (Jonkman et al. 2009, Table 9-1 lists
  // 0.68 and 1.08 Hz on the rotor; here clamped, not rotating, without ElastoDyn's mass factor).
  EXPECT_GT(f_case(0), 0.6);
  EXPECT_LT(f_case(0), 0.8);
}

// A small valid blade: three key points, two stations of an isotropic section.
const std::string kBase = R"(name: fe blade
gravity: 0
bodies:
  - name: blade
    type: fe_blade
    elements: 4
    modes: 2
    reference_axis: {kp_xr: [0, 0, 0], kp_yr: [0, 0, 0], kp_zr: [0, 5, 10], twist_deg: [0, 0, 0]}
    sections:
      - eta: 0
        K: [[1e8, 0, 0, 0, 0, 0], [0, 1e8, 0, 0, 0, 0], [0, 0, 1e9, 0, 0, 0],
            [0, 0, 0, 1e7, 0, 0], [0, 0, 0, 0, 2e7, 0], [0, 0, 0, 0, 0, 1e6]]
        M: [[100, 0, 0, 0, 0, 0], [0, 100, 0, 0, 0, 0], [0, 0, 100, 0, 0, 0],
            [0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 2]]
      - eta: 1
        K: [[1e8, 0, 0, 0, 0, 0], [0, 1e8, 0, 0, 0, 0], [0, 0, 1e9, 0, 0, 0],
            [0, 0, 0, 1e7, 0, 0], [0, 0, 0, 0, 2e7, 0], [0, 0, 0, 0, 0, 1e6]]
        M: [[100, 0, 0, 0, 0, 0], [0, 100, 0, 0, 0, 0], [0, 0, 100, 0, 0, 0],
            [0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 2]]
)";

std::string errorOf(const std::string& text) {
  testing::TempCaseDir dir;
  const std::string path = dir.write("case.yaml", text);
  try {
    readCase(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string replaced(std::string s, const std::string& from, const std::string& to, int occurrence = 1) {
  std::size_t at = s.find(from);
  for (int k = 1; k < occurrence; ++k) at = s.find(from, at + 1);
  s.replace(at, from.size(), to);
  return s;
}

TEST(CaseFeBlade, ValidBladeReadsWithNamedModes) {
  testing::TempCaseDir dir;
  const Model m = readCase(dir.write("case.yaml", kBase));
  ASSERT_EQ(m.ndof(), 2);
  // The first flap and edge modes (bending stiffness 1e7 and 2e7 N m²), named by their motion.
  EXPECT_TRUE(m.dofs[0].name == "blade flap 1" || m.dofs[0].name == "blade edge 1") << m.dofs[0].name;
  EXPECT_TRUE(m.dofs[1].name == "blade flap 1" || m.dofs[1].name == "blade edge 1") << m.dofs[1].name;
  EXPECT_NE(m.dofs[0].name, m.dofs[1].name);
}

TEST(CaseFeBlade, BadInputNamesFileLineKeyAndReason) {
  const auto expectError = [](const std::string& text, const std::string& want) {
    const std::string e = errorOf(text);
    EXPECT_NE(e.find(want), std::string::npos) << e;
  };
  // Not symmetric: K(1,2) = 5e6, K(2,1) = 0.
  expectError(replaced(kBase, "K: [[1e8, 0, 0", "K: [[1e8, 5e6, 0"),
              "case.yaml:11: bodies.blade.sections[0].K: not symmetric: entry (1,2) = 5e+06 but (2,1) = 0");
  // Not positive definite: a negative torsion stiffness.
  expectError(replaced(kBase, "[0, 0, 0, 0, 0, 1e6]]", "[0, 0, 0, 0, 0, -1e6]]"),
              "case.yaml:11: bodies.blade.sections[0].K: not positive definite");
  // A mass matrix with unequal translational masses.
  expectError(replaced(kBase, "M: [[100, 0", "M: [[90, 0"),
              "case.yaml:13: bodies.blade.sections[0].M: the first three diagonal entries must be the same");
  // Stations not increasing.
  expectError(replaced(kBase, "- eta: 1", "- eta: 0"),
              "case.yaml:15: bodies.blade.sections[1].eta: sections must increase in η: 0 after 0");
  expectError(replaced(kBase, "- eta: 1", "- eta: 0.8"),
              "case.yaml:15: bodies.blade.sections[1].eta: the last section must be at η = 1");
  // A row short, and a matrix with five rows.
  expectError(replaced(kBase, "[0, 0, 0, 0, 0, 1e6]]", "[0, 0, 0, 0, 1e6]]"),
              "bodies.blade.sections[0].K[5]: row 6 of a 6×6 matrix has 5 numbers");
  expectError(replaced(kBase, ", [0, 0, 0, 0, 0, 1e6]]", "]"),
              "case.yaml:11: bodies.blade.sections[0].K: expected a 6×6 matrix written as 6 rows");
  // Key points.
  expectError(replaced(kBase, "kp_zr: [0, 5, 10]", "kp_zr: [0, 5, 5]"),
              "bodies.blade.reference_axis.kp_zr: key points must advance along z_r (towards the tip): 5 after 5");
  expectError(replaced(kBase, "kp_xr: [0, 0, 0], ", ""), "bodies.blade.reference_axis: missing column 'kp_xr'");
  // Damping factors and the mode count.
  expectError(replaced(kBase, "modes: 2", "modes: 2\n    mu: [0.001, 0.001]"),
              "case.yaml:8: bodies.blade.mu: expected the 6 factors mu1 … mu6 [s], got 2");
  expectError(replaced(kBase, "modes: 2", "modes: 0"), "case.yaml:7: bodies.blade.modes: must be between 1 and 24");
  expectError(replaced(kBase, "modes: 2", "modes: 2\n    length: 10"),
              "case.yaml:8: bodies.blade.length: unknown key 'length' (allowed: name, type");
}

}  // namespace
}  // namespace whirl
