// BeamDyn blades (CompElast = 2, issue 46) on the NREL 5MW of certification Test26
// (cases/nrel5mw_beamdyn): `whirl modes` of the structural model, parked and at the rated 12.1 rpm
// [Jonkman2009, Table 1-1], against the same deck with ElastoDyn blades (`--set CompElast=1`, and
// AdjBlMs = 1: the BeamDyn file has ElastoDyn's properties without its 4.5 % mass factor).
//
// Measured (Hz; BeamDyn, ElastoDyn, difference), 60 elements, 8 modes per blade:
//   parked    flap 1 cos / collective   0.6804 0.7049 | 0.6813 0.7058 | −0.13 %
//             edge 1 sin                1.0822        | 1.1040        | −1.97 %
//   12.1 rpm  flap 1 BW / coll. / FW    0.5314 0.7566 0.9303 | 0.5323 0.7575 0.9312 | −0.17 … −0.10 %
//             edge 1 BW / FW            0.8925 1.2995 | 0.9143 1.3213 | −2.4 %, −1.6 %
//             torsion 1 collective      5.578 (BeamDyn only)
// The flap modes agree; the edge modes are lower with BeamDyn by its shear flexibility (shear stiffness
// 0.1 EA in the file; ElastoDyn's blade is Euler–Bernoulli): with the shear entries × 1000 the first
// edge mode is 1.1115 Hz, +0.7 % over ElastoDyn's. Tolerances: flap 0.5 %, edge 3 % (the shear).
// With the sections' flap and edge rotary inertia (BeamDyn's M44, M55, M45; the numbers above are from
// before it): edge 1 sin 1.0814, BW / FW 0.8917 / 1.2987 Hz, flap 1 collective 0.7048 / 0.7565 Hz.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

const std::string kDeck = "cases/nrel5mw_beamdyn/Test26.fst";
const std::string kStructure = " --set CompAero=0 --set CompInflow=0";
const std::string kElastoDyn = " --set CompElast=1 --set AdjBlMs=1";

// name → frequency of the first mode of each name, from `whirl modes --format csv`.
std::map<std::string, double> modes(const std::string& args) {
  const auto r = test::whirl("modes " + kDeck + kStructure + " --format csv" + args);
  EXPECT_EQ(r.code, 0) << r.err;
  std::map<std::string, double> out;
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    const auto c1 = line.find(','), c2 = line.find(',', c1 + 1), c3 = line.find(',', c2 + 1);
    const std::string name = line.substr(c1 + 1, c2 - c1 - 1);
    if (!out.count(name)) out[name] = std::stod(line.substr(c2 + 1, c3 - c2 - 1));
  }
  return out;
}

double rel(double a, double b) { return a / b - 1; }

TEST(BeamDynBlades, Nrel5mwAgainstElastoDynParked) {
  const auto bd = modes(" --rpm 0"), ed = modes(" --rpm 0" + kElastoDyn);
  ASSERT_TRUE(bd.count("flap 1 collective") && bd.count("edge 1 sin") && bd.count("torsion 1 collective"));
  EXPECT_NEAR(rel(bd.at("flap 1 collective"), ed.at("flap 1 collective")), 0, 5e-3);
  EXPECT_NEAR(rel(bd.at("flap 1 cos"), ed.at("flap 1 cos")), 0, 5e-3);
  EXPECT_NEAR(rel(bd.at("edge 1 sin"), ed.at("edge 1 sin")), 0, 3e-2);
  EXPECT_NEAR(rel(bd.at("edge 1 cos"), ed.at("edge 1 cos")), 0, 3e-2);
  // ElastoDyn has no torsion; BeamDyn's first torsion mode sits above the second edge modes.
  EXPECT_EQ(ed.count("torsion 1 collective"), 0u);
  EXPECT_GT(bd.at("torsion 1 collective"), 5.0);
  EXPECT_LT(bd.at("torsion 1 collective"), 6.5);
}

TEST(BeamDynBlades, Nrel5mwAgainstElastoDynRated) {
  const auto bd0 = modes(" --rpm 0"), ed0 = modes(" --rpm 0" + kElastoDyn);
  const auto bd = modes(" --rpm 12.1"), ed = modes(" --rpm 12.1" + kElastoDyn);
  for (const char* m : {"flap 1 BW", "flap 1 collective", "flap 1 FW"})
    EXPECT_NEAR(rel(bd.at(m), ed.at(m)), 0, 5e-3) << m;
  for (const char* m : {"edge 1 BW", "edge 1 FW"}) EXPECT_NEAR(rel(bd.at(m), ed.at(m)), 0, 3e-2) << m;
  // Centrifugal stiffening: the collective flap mode rises by 7.3 % from 0 to 12.1 rpm with either blade,
  // through the axial shortening of the bent FE blade's modes.
  const double rise_bd = bd.at("flap 1 collective") / bd0.at("flap 1 collective");
  const double rise_ed = ed.at("flap 1 collective") / ed0.at("flap 1 collective");
  EXPECT_GT(rise_bd, 1.05);
  EXPECT_NEAR(rise_bd / rise_ed, 1, 2e-3);
}

TEST(BeamDynBlades, BladeModesAndElementsAreOptions) {
  // Fewer modes: no torsion mode left among 4 fixed-root modes (flap 1, edge 1, flap 2, edge 2).
  const auto four = modes(" --rpm 0 --set blade_modes=4");
  EXPECT_EQ(four.count("torsion 1 collective"), 0u);
  EXPECT_TRUE(four.count("edge 2 collective") || four.count("edge 2 cos") || four.count("edge 2 sin"));
  const auto r = test::whirl("modes " + kDeck + kStructure + " --set blade_modes=0");
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, ::testing::HasSubstr("blade_modes=0': blade_modes: expected a positive integer"));
}

// Axial modes are not kept (the blade body has no axial shapes): 16 and 24 modes per blade, which reach
// past the first axial mode, run and converge (flap 1 collective 0.704894 / 0.7048928 / 0.7048927 Hz with
// 8 / 16 / 24 modes, edge 1 sin 1.0822313 / 1.0822313 / 1.0822313 Hz); before, an axial mode scaled
// by its tiny transverse motion stopped the equilibrium ("no stiffness" along tower SS 2).
TEST(BeamDynBlades, MoreModesSkipTheAxialOnes) {
  const auto eight = modes(" --rpm 0"), sixteen = modes(" --rpm 0 --set blade_modes=16");
  ASSERT_TRUE(sixteen.count("flap 1 collective") && sixteen.count("edge 1 sin"));
  EXPECT_NEAR(rel(sixteen.at("flap 1 collective"), eight.at("flap 1 collective")), 0, 1e-5);
  EXPECT_NEAR(rel(sixteen.at("edge 1 sin"), eight.at("edge 1 sin")), 0, 1e-5);
  EXPECT_EQ(sixteen.count("axial 1 collective"), 0u);
  const auto r = test::whirl("modes " + kDeck + kStructure + " --set blade_elements=2 --set blade_modes=12");
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, ::testing::HasSubstr("blade_modes: 12 bending and torsion modes asked, the blade's 2 elements "
                                          "give 10 among their lowest modes"));
}

// IEA-3.4 (cases/iea34_beamdyn, structure): the deck's BeamDyn blade against its ElastoDyn blade. The two
// files do not carry the same properties: an FE blade built from the ElastoDyn file's EI, mass and
// stations (IEA-3.4-130-RWT_BeamDyn_ElastoDynProperties.fst, stiff in shear, extension and torsion)
// reproduces the ElastoDyn blade (with FE shapes, `--set shapes=fem`) to 0.5 % (1.2 % for flap 1 BW
// at 11.75 rpm), and the BeamDyn file's blade is 4.3 % below that in flap and edge alike: its 6 × 6
// sections (flap stiffness 13 % below ElastoDyn's FlpStff at η = 0.2, shear 1.2–1.7 %, couplings).
// Measured (Hz): parked flap 1 collective / edge 1 sin: BeamDyn file 0.7892 / 0.9852, FE of the ElastoDyn
// properties 0.8246 / 1.0291, ElastoDyn FE shapes 0.8282 / 1.0338, ElastoDyn polynomials 0.8344 / 1.0417;
// at 11.75 rpm flap 1 BW / edge 1 BW / flap 1 collective 0.5949 / 0.8046 / 0.8275, 0.6277 / 0.8489 /
// 0.8628, 0.6355 / 0.8523 / 0.8659. First torsion (BeamDyn file) 8.763 Hz.
std::map<std::string, double> ieaModes(const std::string& fst, const std::string& args) {
  const auto r = test::whirl("modes cases/iea34_beamdyn/" + fst +
                             " --set FlapDOF1=True --set FlapDOF2=True --set EdgeDOF=True --azimuths 8 --format csv" +
                             args);
  EXPECT_EQ(r.code, 0) << r.err;
  std::map<std::string, double> out;
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    const auto c1 = line.find(','), c2 = line.find(',', c1 + 1), c3 = line.find(',', c2 + 1);
    const std::string name = line.substr(c1 + 1, c2 - c1 - 1);
    if (!out.count(name)) out[name] = std::stod(line.substr(c2 + 1, c3 - c2 - 1));
  }
  return out;
}

TEST(BeamDynBlades, Iea34FeBladeOfTheElastoDynPropertiesMatchesTheElastoDynBlade) {
  const std::string bd = "IEA-3.4-130-RWT_BeamDyn_structure.fst",
                    fe = "IEA-3.4-130-RWT_BeamDyn_ElastoDynProperties.fst";
  const std::string ed = " --set CompElast=1 --set shapes=fem";
  for (const char* rpm : {" --rpm 0", " --rpm 11.75"}) {
    const auto a = ieaModes(fe, rpm), b = ieaModes(bd, std::string(rpm) + ed), c = ieaModes(bd, rpm);
    for (const auto* m : {"flap 1 collective", rpm[7] == '0' ? "edge 1 sin" : "edge 1 BW"}) {
      ASSERT_TRUE(a.count(m) && b.count(m) && c.count(m)) << m << rpm;
      EXPECT_NEAR(rel(a.at(m), b.at(m)), 0, 1e-2) << m << rpm;
      EXPECT_NEAR(rel(c.at(m), a.at(m)), -0.043, 1e-2) << m << rpm;  // the files' difference
    }
  }
}

// Rotating-frame consistency: OpenFAST's BeamDyn linearization flags Jacobians of a frozen frame as
// rotating, and MBC then adds spin softening that lowers the NREL 5MW tower side-side mode from 0.3221 Hz
// to 0.2915 Hz at 25 rpm (issue 46). whirl's equations are in the inertial frame: the first tower modes
// keep their frequency to the physical coupling with the rotor. Measured (Test26 structure, 8 azimuths):
// tower SS 1 0.32194 / 0.32182 / 0.32259 Hz at 0 / 12.1 / 25 rpm (+0.20 % at 25 rpm), with ElastoDyn
// blades 0.32105 / 0.32090 / 0.32157 Hz (+0.16 %); tower FA 1 0.32563 → 0.32004 Hz (ElastoDyn blades
// 0.32444 → 0.31846 Hz).
TEST(BeamDynBlades, TowerFrequenciesDoNotSoftenWithRotorSpeed) {
  const auto parked = modes(" --rpm 0 --azimuths 8"), fast = modes(" --rpm 25 --azimuths 8");
  const auto ed0 = modes(" --rpm 0 --azimuths 8" + kElastoDyn), ed25 = modes(" --rpm 25 --azimuths 8" + kElastoDyn);
  EXPECT_NEAR(rel(fast.at("tower SS 1"), parked.at("tower SS 1")), 0, 5e-3);
  // The same physical change as with ElastoDyn's blades, to 0.2 % (FA 1 falls by 1.7 % and 1.8 %: the
  // rotor's gyroscopic coupling with the tower-top tilt).
  for (const char* m : {"tower SS 1", "tower FA 1"})
    EXPECT_NEAR(rel(fast.at(m), parked.at(m)), rel(ed25.at(m), ed0.at(m)), 2e-3) << m;
  EXPECT_GT(fast.at("tower SS 1"), 0.30);  // OpenFAST's defect: 0.2915 Hz
}

// Aerodynamic stiffness of torsion on the aeroelastic deck (Main_Aero_BD.fst: NREL 5MW with these BeamDyn
// blades and AeroDyn): AeroDyn's aerodynamic centres lie ahead of BeamDyn's axis (BlSwpAC < 0, towards the
// leading edge), so the lift a nose-up twist adds turns the section further nose up: the torsion
// frequency falls with the dynamic pressure. Measured at 12.1 rpm, 8 azimuths: torsion 1 collective
// 5.5785 Hz without aerodynamics, 5.1618 Hz in still air, 5.1615 Hz at 11.4 m/s (−7.5 %: the rotation's
// dynamic pressure dominates); along the trimmed wind 4 → 24 m/s it falls from 5.52 to 5.08 Hz. With the
// sections' whole rotational inertia (flap and edge rotary inertia, M45) 5.5800 and 5.1635 Hz.
// Without the airfoils' Cm (--set UseBlCm=False) it is 5.0116 Hz (−10.2 %): the nose-down Cm slope stiffens
// torsion back by 3 %, so both the arms and Cm are in the bracket below.
TEST(BeamDynBlades, TorsionSoftensWithTheAerodynamicStiffness) {
  const std::string aero = "cases/nrel5mw_beamdyn/Main_Aero_BD.fst --rpm 12.1 --azimuths 8 --format csv";
  auto torsion = [](const std::string& args) {
    const auto r = test::whirl("modes " + args);
    EXPECT_EQ(r.code, 0) << r.err;
    const auto at = r.out.find(",torsion 1 collective,");
    if (at == std::string::npos) {
      ADD_FAILURE() << "no torsion 1 collective: " << r.out;
      return 0.0;
    }
    return std::stod(r.out.substr(at + 22));
  };
  const double structure = torsion(aero + kStructure), still = torsion(aero + " --set HWindSpeed=0");
  EXPECT_NEAR(structure, 5.5800, 1e-3);  // the structural model's value (Test26 above, same files)
  EXPECT_LT(still / structure - 1, -0.05);
  EXPECT_GT(still / structure - 1, -0.10);
}

}  // namespace
}  // namespace whirl
