// The BeamDyn reader (src/io/openfast/beamdyn/beamdyn_input.hpp): the NREL 5MW blade of certification Test26
// (cases/nrel5mw_beamdyn, BeamDyn v1.01 layout), a small generated blade in the OpenFAST v4 layout
// (with the modal-damping block), and one error per bad input, each "file:line: key: reason".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "src/base/error.hpp"
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "tests/unit/openfast_test_util.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

const std::filesystem::path kDir = test::sourceDir() / "cases" / "nrel5mw_beamdyn" / "5MW_Baseline";

// A BeamDyn primary file: one member along z_r with `kp` key points over 10 m, 2° of twist at the root.
std::string primary(int kp_total, int kp_member, bool pitch_actuator = false) {
  std::ostringstream s;
  s << "--------- BEAMDYN with OpenFAST INPUT FILE ---------\ntest blade\n"
       "---------------------- SIMULATION CONTROL --------\n"
       "False         Echo            - Echo\n"
       "True          QuasiStaticInit - init\n"
       " 0            rhoinf          - damping\n"
       " 2            quadrature      - 1=Gaussian; 2=Trapezoidal\n"
       " 2            refine          - refinement\n"
       "---------------------- GEOMETRY PARAMETER --------\n"
       "          1   member_total    - members\n"
    << "         " << kp_total << "   kp_total        - key points\n"
    << "     1     " << kp_member << "                 - Member number; Number of key points in this member\n"
    << "  kp_xr kp_yr kp_zr initial_twist\n  (m) (m) (m) (deg)\n";
  for (int k = 0; k < kp_member; ++k)
    s << "  0.0  0.0  " << 10.0 * k / (kp_member - 1) << "  " << 2.0 * (1 - double(k) / (kp_member - 1)) << "\n";
  s << "---------------------- MESH PARAMETER ------------\n"
       "          5   order_elem      - order\n"
       "---------------------- MATERIAL PARAMETER --------\n"
       "\"blade.dat\"    BldFile         - blade file\n"
       "---------------------- PITCH ACTUATOR PARAMETERS -\n"
    << (pitch_actuator ? "True" : "False")
    << "         UsePitchAct     - actuator\n"
       "200           PitchJ          - inertia\n"
       "---------------------- OUTPUTS -------------------\n"
       "True          SumPrint        - summary\n"
       "              OutList         - outputs\n"
       "END of input file\n";
  return s.str();
}

// A blade file with stations at `eta`, a uniform section (EA 1e9, shear 1e8, EI 1e7/2e7, GJ 5e6;
// m 10 kg/m), and one edit hook per station.
struct BladeText {
  std::vector<double> eta = {0.0, 0.5, 1.0};
  double K12 = 0, K21 = 0;   ///< entries (1,2) and (2,1) of the middle station's stiffness
  double K44 = 1e7;          ///< the middle station's first bending stiffness
  int stop_after_rows = -1;  ///< truncate: lines of the station block kept (−1: all)
  bool modal_block = true;
  std::string text() const {
    std::ostringstream s;
    s << "------- BEAMDYN INDIVIDUAL BLADE INPUT FILE ------\n test\n"
         "---------------------- BLADE PARAMETERS ----------\n"
      << eta.size() << "   station_total    - Number of blade input stations (-)\n"
      << " 1   damp_type        - Damping type\n"
         "---------------------- DAMPING COEFFICIENT -------\n"
         " mu1 mu2 mu3 mu4 mu5 mu6\n (s) (s) (s) (s) (s) (s)\n"
         "1.0E-03 2.0E-03 3.0E-03 4.0E-03 5.0E-03 6.0E-03\n";
    if (modal_block) s << "---------------------- MODAL DAMPING -----\n 0   n_modes - modes\n 0.0   zeta - ratios\n";
    s << "---------------------- DISTRIBUTED PROPERTIES ----\n";
    std::ostringstream body;
    for (std::size_t i = 0; i < eta.size(); ++i) {
      if (i > 0) body << "\n";
      body << eta[i] << "\n";
      const bool mid = i == 1;
      const double d[6] = {1e8, 1e8, 1e9, mid ? K44 : 1e7, 2e7, 5e6};
      for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) {
          double v = r == c ? d[r] : 0.0;
          if (mid && r == 0 && c == 1) v = K12;
          if (mid && r == 1 && c == 0) v = K21;
          body << " " << v;
        }
        body << "\n";
      }
      body << "\n";
      const double m[6] = {10, 10, 10, 0.5, 0.2, 0.7};
      for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) body << " " << (r == c ? m[r] : 0.0);
        body << "\n";
      }
    }
    std::string b = body.str();
    if (stop_after_rows >= 0) {
      std::size_t at = 0;
      for (int k = 0; k < stop_after_rows && at != std::string::npos; ++k) at = b.find('\n', at) + 1;
      b = b.substr(0, at);
    }
    return s.str() + b;
  }
};

std::string readError(const std::string& primary_text, const std::string& blade_text) {
  test::ScratchDir dir;
  const auto p = dir.write("primary.dat", primary_text);
  dir.write("blade.dat", blade_text);
  return errorOf([&] { io::readBeamDyn(p); });
}

TEST(BeamDynInput, Nrel5mwTest26) {
  // Values of 5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat and _Blade.dat (OpenFAST r-test Test26).
  const io::BeamDynInput bd = io::readBeamDyn(kDir / "NRELOffshrBsline5MW_BeamDyn.dat");
  EXPECT_EQ(bd.quadrature, 2);
  EXPECT_EQ(bd.refine, 1);  // DEFAULT
  EXPECT_EQ(bd.order_elem, 5);
  ASSERT_EQ(bd.member_key_points, std::vector<int>{49});
  ASSERT_EQ(bd.key_points.size(), 49u);
  EXPECT_DOUBLE_EQ(bd.key_points[0].twist, 13.308 * std::numbers::pi / 180);
  EXPECT_DOUBLE_EQ(bd.key_points[1].r.z(), 0.199875);
  EXPECT_DOUBLE_EQ(bd.key_points[48].r.z(), 61.5);
  EXPECT_FALSE(bd.UsePitchAct);
  const io::BeamDynBlade& b = bd.blade;
  EXPECT_EQ(b.damp_type, 1);
  EXPECT_DOUBLE_EQ(b.mu[5], 1e-3);
  ASSERT_EQ(b.stations.size(), 49u);
  EXPECT_DOUBLE_EQ(b.stations[0].K(2, 2), 9.729480e9);   // EA: index 3 is the axial strain
  EXPECT_DOUBLE_EQ(b.stations[0].K(3, 3), 1.811360e10);  // edgewise bending (about x_r)
  EXPECT_DOUBLE_EQ(b.stations[0].K(4, 4), 1.811000e10);  // flapwise bending (about y_r)
  EXPECT_DOUBLE_EQ(b.stations[0].K(5, 5), 5.564400e9);   // torsion
  EXPECT_DOUBLE_EQ(b.stations[0].M(0, 0), 678.935);
  EXPECT_DOUBLE_EQ(b.stations[1].eta, 0.00325);
  EXPECT_DOUBLE_EQ(b.stations[48].eta, 1.0);
}

TEST(BeamDynInput, GeneratedBladeWithModalBlock) {
  test::ScratchDir dir;
  const auto p = dir.write("primary.dat", primary(5, 5));
  dir.write("blade.dat", BladeText{}.text());
  const io::BeamDynInput bd = io::readBeamDyn(p);
  ASSERT_EQ(bd.blade.stations.size(), 3u);
  EXPECT_DOUBLE_EQ(bd.blade.mu[2], 3e-3);
  EXPECT_DOUBLE_EQ(bd.blade.stations[1].K(3, 3), 1e7);
  EXPECT_DOUBLE_EQ(bd.blade.stations[2].M(5, 5), 0.7);
  EXPECT_DOUBLE_EQ(bd.key_points[4].r.z(), 10.0);
  BladeText old;
  old.modal_block = false;  // BeamDyn v1.0x: no modal damping block
  dir.write("blade.dat", old.text());
  EXPECT_EQ(io::readBeamDyn(p).blade.stations.size(), 3u);
}

TEST(BeamDynInput, NotSymmetricNamesStation) {
  BladeText b;
  b.K12 = 1e5;
  b.K21 = 2e5;
  const std::string e = readError(primary(5, 5), b.text());
  EXPECT_THAT(e, HasSubstr("blade.dat:"));
  EXPECT_THAT(e, HasSubstr(": stiffness_matrix: station 2: not symmetric, entry (1,2)"));
}

TEST(BeamDynInput, NotPositiveDefinite) {
  BladeText b;
  b.K44 = -1e7;
  const std::string e = readError(primary(5, 5), b.text());
  EXPECT_THAT(e, HasSubstr(": stiffness_matrix: station 2 (η = 0.500000): not positive definite"));
  b.K44 = 1e7;
  b.K12 = b.K21 = 2e8;  // symmetric, |K12| > sqrt(K11 K22): indefinite
  EXPECT_THAT(readError(primary(5, 5), b.text()), HasSubstr("station 2 (η = 0.500000): not positive definite"));
}

TEST(BeamDynInput, StationsNotIncreasing) {
  BladeText b;
  b.eta = {0.0, 0.6, 0.4, 1.0};
  EXPECT_THAT(readError(primary(5, 5), b.text()),
              HasSubstr(": station_eta: stations must increase: station 3 at η = 0.400000 after 0.600000"));
  b.eta = {0.1, 0.5, 1.0};
  EXPECT_THAT(readError(primary(5, 5), b.text()), HasSubstr(": station_eta: the first station must be at 0"));
  b.eta = {0.0, 0.5, 0.9};
  EXPECT_THAT(readError(primary(5, 5), b.text()), HasSubstr(": station_eta: the last station must be at 1"));
}

TEST(BeamDynInput, KeyPointCountMismatch) {
  EXPECT_THAT(readError(primary(6, 5), BladeText{}.text()),
              HasSubstr("primary.dat:11: kp_total: 6 key points, but the members hold 5"));
  // Rows beyond kp_total: the next line must be the mesh section.
  EXPECT_THAT(readError(primary(4, 4), BladeText{}.text()), ::testing::Not(HasSubstr("kp_total")));
  std::string p = primary(5, 5);
  p.insert(p.find("-------------------- MESH"), "  0.0 0.0 11.0 0.0\n");
  EXPECT_THAT(readError(p, BladeText{}.text()), HasSubstr(": kp_total: is 5 but line 20 is another row"));
}

TEST(BeamDynInput, TruncatedBlade) {
  BladeText b;
  b.stop_after_rows = 20;  // station 1 complete (14 lines), station 2 cut in its stiffness matrix
  const std::string e = readError(primary(5, 5), b.text());
  EXPECT_THAT(e, HasSubstr(": stiffness_matrix: the file ends before row"));
  EXPECT_THAT(e, HasSubstr("station 2"));
}

TEST(BeamDynInput, RefusesPitchActuatorAndModalDamping) {
  EXPECT_THAT(readError(primary(5, 5, true), BladeText{}.text()),
              HasSubstr(": UsePitchAct: True not supported by whirl (the pitch actuator of BeamDyn is not modelled)"));
  std::string b = BladeText{}.text();
  b.replace(b.find(" 1   damp_type"), 14, " 2   damp_type");
  EXPECT_THAT(readError(primary(5, 5), b), HasSubstr(": damp_type: 2 not supported by whirl (modal damping"));
}

}  // namespace
}  // namespace whirl
