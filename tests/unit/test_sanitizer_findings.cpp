// Inputs found with the fuzz harnesses (fuzz/, README.md *Reliability*: run by the fuzzer, or found
// while writing a harness and reproduced through it) that ran out of memory, let an unexpected
// exception type escape or tripped a sanitizer; each test failed before its fix (the first one only
// under -DWHIRL_SANITIZE=ON, where undefined behaviour stops the program).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/simulate.hpp"
#include "linearize/state_space.hpp"
#include "modal/mbc_lin.hpp"
#include "src/base/error.hpp"
#include "src/io/case/case_file.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/state_space_files.hpp"
#include "test_util.hpp"

namespace whirl {
namespace {

// fuzz_case_yaml, first input: every case without `inputs` made linearize() take J.row(k) of the
// empty input Jacobian, an offset applied to Eigen's null data pointer (UBSan: pointer-overflow).
TEST(SanitizerFindings, LinearizeModelWithoutInputs) {
  const Model m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/tower_topmass/tower_topmass.yaml");
  ASSERT_EQ(m.ninput(), 0);
  const LinearModel lin = linearize(m, solveOperatingPoint(m, initialPoint(m)));
  EXPECT_EQ(lin.Q.rows(), lin.K.rows());
  EXPECT_EQ(lin.Q.cols(), 0);
  EXPECT_GT(lin.K.rows(), 0);
}

// The sanitized test suite (SimulateFloating3Dof, 2026-11-27): simulate() recorded the inputs of every
// instant as sim.u.row(k) also for a model without inputs, an offset applied to Eigen's null data
// pointer from the second instant on (UBSan: pointer-overflow).
TEST(SanitizerFindings, SimulateModelWithoutInputs) {
  const Model m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/tower_topmass/tower_topmass.yaml");
  ASSERT_EQ(m.ninput(), 0);
  SimulationOptions o;
  o.t_end = 0.05;
  const Simulation sim = simulate(m, solveOperatingPoint(m, initialPoint(m)), o);
  EXPECT_EQ(sim.time.size(), 6u);
  EXPECT_EQ(sim.u.cols(), 0);
  EXPECT_EQ(sim.q.rows(), 6);
}

// fuzz_writers: the .lin of a model with inputs and outputs but no states reordered the inputs of its
// 0 × nu B and scaled the rows of its ny × 0 C, blocks that offset Eigen's null data pointer
// (UBSan: pointer-overflow; fails only under -DWHIRL_SANITIZE=ON).
TEST(SanitizerFindings, LinFileOfAModelWithoutStates) {
  StateSpaceModel m;
  m.u = {{"generator torque", "N m", 1.0, -1, -1, false}, {"wind speed", "m/s", 8.0, -1, -1, false}};
  m.y = {{"GenSpeed", "rad/s", 1.0, -1, -1, false}, {"RtAeroFxh", "N", 2.0, -1, -1, false}};
  m.xdot_op = VecX::Zero(0);
  m.A = MatX::Zero(0, 0);
  m.B = MatX::Zero(0, 2);
  m.C = MatX::Zero(2, 0);
  m.D = MatX::Ones(2, 2);
  const std::string text = linFileText(m, "no states");
  EXPECT_NE(text.find("B: 0 x 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("C: 2 x 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("D: 2 x 2\n"), std::string::npos) << text;
}

// fuzz_writers: a Campbell line at 1.75e308 Hz made the frequency axis 1.05 × 1.75e308 = inf, whose
// log10 was cast to int (UBSan: float-cast-overflow; fails only under -DWHIRL_SANITIZE=ON).
TEST(SanitizerFindings, CampbellScriptOfAHugeFrequency) {
  CampbellDiagram d;
  CampbellPoint p;
  p.rpm = 5;
  p.coordinates = {"q"};
  Mode m;
  m.freq_hz = 1.75e308;  // 1.05 × this is inf
  m.shape = Eigen::VectorXcd::Ones(1);
  m.participation = VecX::Ones(1);
  p.modes = {m};
  d.points = {p};
  d.lines = {{"q", {0}}};
  const std::string gp = campbellGnuplotScript(d);
  EXPECT_NE(gp.find("fmax = inf"), std::string::npos) << gp;
}

// fuzz_cli (`export cases/floating_3dof/floating_3dof.yaml --format mat --drop-azimuth`): dropping the
// azimuth of a model without inputs took rows of its nx × 0 B, offsets of Eigen's null data pointer
// (UBSan: pointer-overflow; fails only under -DWHIRL_SANITIZE=ON).
TEST(SanitizerFindings, DropAzimuthOfAModelWithoutInputs) {
  StateSpaceModel m;
  m.x = {{"azimuth", "rad", 0.0, -1, -1, true},
         {"surge", "m", 0.0, -1, -1, false},
         {"d(azimuth)/dt", "rad/s", 1.0, -1, 0, false},
         {"d(surge)/dt", "m/s", 0.0, -1, 1, false}};
  m.xdot_op = VecX::Zero(4);
  m.A = MatX::Identity(4, 4);
  m.B = MatX::Zero(4, 0);
  m.C = MatX::Zero(0, 4);
  m.D = MatX::Zero(0, 0);
  const StateSpaceModel r = dropAzimuth(m);
  EXPECT_EQ(r.x.size(), 3u);
  EXPECT_EQ(r.A.rows(), 3);
  EXPECT_EQ(r.B.rows(), 3);
  EXPECT_EQ(r.B.cols(), 0);
  EXPECT_EQ(r.C.cols(), 3);
}

// The NREL 5MW .lin at 9 rpm of tests/data with one line replaced.
std::string linWith(const test::TempDir& tmp, const std::string& from, const std::string& to) {
  const std::string text = test::slurp(std::string(WHIRL_SOURCE_DIR) +
                                       "/tests/data/openfast-lin/rotating-9rpm/Main.1.lin");
  const std::string changed = std::regex_replace(text, std::regex(from), to, std::regex_constants::format_first_only);
  EXPECT_NE(changed, text) << from;
  return tmp.write("f.lin", changed);
}

// Expects InputError whose message starts with "<path>:<line>: <key>:".
template <class F>
void expectInputError(F&& f, const std::string& prefix) {
  try {
    f();
    ADD_FAILURE() << "no exception, expected " << prefix;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
  }
}

// fuzz_lin: a header count sized the state table before any row was read (2e9 states: 160 GB,
// std::bad_alloc or an ASan out-of-memory report instead of "truncated").
TEST(SanitizerFindings, LinHugeStateCountIsATruncatedTable) {
  test::TempDir tmp;
  const std::string f = linWith(tmp, "Number of continuous states: +20",
                                "Number of continuous states:        2000000000");
  // (The bounds of src/base/limits.hpp, added alongside, now refuse the count at its header line.)
  expectInputError([&] { readOpenFastLin(f); },
                   f + ":12: Number of continuous states: 2000000000 is above the limit of 100000");
}

// fuzz_lin: matrix dimensions were read with std::stoi (std::out_of_range escaped as "stoi") and
// sized the matrix before its rows were read (20 x 2e9: 320 GB).
TEST(SanitizerFindings, LinMatrixDimensionsOutOfRange) {
  test::TempDir tmp;
  const std::string big = linWith(tmp, "\nA: 20 x 20", "\nA: 99999999999 x 20");
  // (The bounds of src/base/limits.hpp, added alongside, now refuse both at the title line.)
  expectInputError([&] { readOpenFastLin(big); }, big + ":70: A rows: '99999999999' is out of the integer range");
  const std::string wide = linWith(tmp, "\nA: 20 x 20", "\nA: 20 x 2000000000");
  expectInputError([&] { readOpenFastLin(wide); }, wide + ":70: A columns: 2000000000 is above the limit of");
}

// fuzz_lin: blade numbers were read with std::stoi (std::out_of_range) and the highest one sized
// the per-blade tables of the MBC layout ("blade 2000000000": 48 GB).
TEST(SanitizerFindings, LinBladeNumberOutOfRange) {
  test::TempDir tmp;
  for (const std::string number : {"99999999999", "2000000000"}) {
    const std::string f = linWith(tmp, "bending-mode DOF of blade 3 \\(internal DOF index = DOF_BF\\(3,1\\)\\), m\\n",
                                  "bending-mode DOF of blade " + number + " (internal DOF index = DOF_BF(3,1)), m\n");
    const OpenFastLin lin = readOpenFastLin(f);
    expectInputError([&] { mbcLayoutFromLin(lin); }, f + ":25: continuous states: blade number");
  }
}

// fuzz_aerodyn: an AeroDyn file with ADBlFile(1) and (2) only, for ElastoDyn's 3 blades, let
// std::out_of_range ("vector::_M_range_check") escape from the third blade's lookup.
TEST(SanitizerFindings, AeroDynMissingBladeFile) {
  test::TempDir tmp;
  const std::filesystem::path src = std::filesystem::path(WHIRL_SOURCE_DIR) / "cases/nrel5mw";
  std::filesystem::copy(src, tmp.path, std::filesystem::copy_options::recursive);
  const std::string text = test::slurp((tmp.path / "aero/AeroDyn.dat").string());
  const std::string changed = std::regex_replace(text, std::regex("\n[^\n]*ADBlFile\\(3\\)[^\n]*"), "");
  ASSERT_NE(changed, text);
  tmp.write("aero/AeroDyn.dat", changed);
  try {
    readElastoDynModel((tmp.path / "Main_Aero.fst").string());
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("AeroDyn.dat: ADBlFile(3): key not found in this file (ElastoDyn NumBl = 3"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace whirl
