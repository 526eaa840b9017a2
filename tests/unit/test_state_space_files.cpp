// Round trips of the state-space files: .mat read back through matio bit for bit, .lin read back by
// whirl's OpenFAST reader (same matrices, same multiblade modes), JSON, and scipy.io.loadmat when a
// python with scipy is installed.
#include <gtest/gtest.h>
#include <matio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "modal/mbc_lin.hpp"
#include "modal/rotor_modes.hpp"
#include "openfast_test_util.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/writers/state_space_files.hpp"
#include "state_space_test_util.hpp"

namespace whirl {
namespace {

StateSpaceExport rotorExport(int azimuths, double rpm = 9) {
  const Model m = testing::nrel5mw();
  OperatingCondition at;
  at.rotor_speed = rpm * std::numbers::pi / 30;
  ExportOptions opt;
  opt.azimuths = azimuths;
  StateSpaceExport e;
  e.source = testing::kNrel5mwFst;
  e.model_name = "NREL 5MW";
  e.points.push_back(exportOperatingPoint(m, at, opt));
  e.points.back().rpm = rpm;
  return e;
}

struct MatReader {
  explicit MatReader(const std::string& path) : mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY)) {}
  ~MatReader() {
    if (mat) Mat_Close(mat);
  }
  matvar_t* read(const char* name) const { return Mat_VarRead(mat, name); }
  mat_t* mat;
};

// Bit-for-bit equality of a double variable with an Eigen matrix (column-major both).
void expectSameBits(const matvar_t* v, const MatX& M, const std::string& what) {
  ASSERT_NE(v, nullptr) << what;
  ASSERT_EQ(v->class_type, MAT_C_DOUBLE) << what;
  ASSERT_EQ(v->dims[0], static_cast<size_t>(M.rows())) << what;
  ASSERT_EQ(v->dims[1], static_cast<size_t>(M.cols())) << what;
  EXPECT_EQ(std::memcmp(v->data, M.data(), sizeof(double) * M.size()), 0) << what;
}

std::vector<std::string> cellStrings(const matvar_t* v) {
  std::vector<std::string> s;
  const size_t n = v->dims[0] * v->dims[1];
  for (size_t i = 0; i < n; ++i) {
    const matvar_t* c = Mat_VarGetCell(const_cast<matvar_t*>(v), static_cast<int>(i));
    s.emplace_back(static_cast<const char*>(c->data), c->dims[1]);
  }
  return s;
}

// One operating point has the layout of several (n = 1): ROSCO's cell arrays (issue 41: a separate
// layout made ROSCO fail with KeyError: 'u_ops').
TEST(StateSpaceFiles, MatReadsBackBitForBit) {
  const StateSpaceExport e = rotorExport(6);
  test::ScratchDir dir;
  const std::string path = (dir.path() / "ss.mat").string();
  writeStateSpaceMat(e, path);
  MatReader r(path);
  ASSERT_NE(r.mat, nullptr);
  const StateSpaceModel& m = e.points[0].model;
  for (const auto& [name, M] : {std::pair{"A", &m.A}, {"B", &m.B}, {"C", &m.C}, {"D", &m.D}}) {
    matvar_t* v = r.read(name);
    ASSERT_NE(v, nullptr) << name;
    ASSERT_EQ(v->class_type, MAT_C_CELL) << name;
    ASSERT_EQ(v->dims[1], 1u) << name;
    expectSameBits(Mat_VarGetCell(v, 0), *M, name);
    Mat_VarFree(v);
  }
  VecX yop(m.y.size());
  for (size_t i = 0; i < m.y.size(); ++i) yop(i) = m.y[i].op;
  matvar_t* v = r.read("y_ops");
  ASSERT_NE(v, nullptr);
  expectSameBits(Mat_VarGetCell(v, 0), yop, "y_ops");
  Mat_VarFree(v);
  v = r.read("y_names");
  ASSERT_NE(v, nullptr);
  const auto names = cellStrings(v);
  Mat_VarFree(v);
  ASSERT_EQ(names.size(), m.y.size());
  for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], m.y[i].name);
  // OpenFAST's channel texts beside whirl's names, so a .mat user can pick channels by either.
  v = r.read("y_desc");
  ASSERT_NE(v, nullptr);
  const auto desc = cellStrings(v);
  Mat_VarFree(v);
  ASSERT_EQ(desc.size(), m.y.size());
  EXPECT_EQ(desc[0], "ED GenSpeed");
  // Per-azimuth models: nx × nx × N, slice k = model k in the rotating frame.
  v = r.read("A_az");
  ASSERT_NE(v, nullptr);
  const matvar_t* a = Mat_VarGetCell(v, 0);
  ASSERT_EQ(a->rank, 3);
  ASSERT_EQ(a->dims[2], e.points[0].azimuths.size());
  const MatX& A2 = e.points[0].azimuths[2].A;
  EXPECT_EQ(std::memcmp(static_cast<const double*>(a->data) + 2 * A2.size(), A2.data(), sizeof(double) * A2.size()), 0);
  Mat_VarFree(v);
}

TEST(StateSpaceFiles, MatWithSeveralOperatingPointsHasRoscosLayout) {
  StateSpaceExport e = rotorExport(3, 9);
  e.points[0].wind_speed = 8;
  e.points.push_back(rotorExport(3, 11).points[0]);
  e.points[1].wind_speed = 10;
  test::ScratchDir dir;
  const std::string path = (dir.path() / "ss.mat").string();
  writeStateSpaceMat(e, path);
  MatReader r(path);
  matvar_t* A = r.read("A");
  ASSERT_NE(A, nullptr);
  ASSERT_EQ(A->class_type, MAT_C_CELL);
  ASSERT_EQ(A->dims[0], 1u);
  ASSERT_EQ(A->dims[1], 2u);
  expectSameBits(Mat_VarGetCell(A, 1), e.points[1].model.A, "A{2}");
  Mat_VarFree(A);
  matvar_t* u = r.read("u_ops");
  const matvar_t* u2 = Mat_VarGetCell(u, 1);
  ASSERT_EQ(u2->dims[0], e.points[1].model.u.size() + 1);  // wind speed first, as ROSCO schedules on it
  EXPECT_EQ(static_cast<const double*>(u2->data)[0], 10.0);
  Mat_VarFree(u);
  matvar_t* ind = r.read("indInps");
  ASSERT_EQ(ind->dims[1], e.points[0].model.u.size());
  ASSERT_EQ(ind->class_type, MAT_C_INT32);                  // integers: numpy indexes with them as loaded
  EXPECT_EQ(static_cast<const int32_t*>(ind->data)[0], 2);  // 1-based, after the wind speed
  Mat_VarFree(ind);
}

// .lin at full precision: the reader gets the same numbers back, OpenFAST's multiblade analysis of the
// files (mbcLayoutFromLin, as `whirl lin` does) gives the modes of whirl's own Campbell analysis.
TEST(StateSpaceFiles, LinReadsBackWithTheSameMatricesAndModes) {
  const StateSpaceExport e = rotorExport(12);
  const auto& az = e.points[0].azimuths;
  test::ScratchDir dir;
  std::vector<MbcSample> samples;
  OpenFastLin first;
  for (size_t k = 0; k < az.size(); ++k) {
    const std::string path = (dir.path() / ("ss." + std::to_string(k + 1) + ".lin")).string();
    std::ofstream(path) << linFileText(az[k], "NREL 5MW");
    const OpenFastLin lin = readOpenFastLin(path);
    // B, C and D are in OpenFAST's input order and output units in the file (checked channel by channel
    // in test_lin_openfast_rules.cpp); A is whirl's, bit for bit.
    EXPECT_EQ(lin.A, az[k].A);
    EXPECT_EQ(lin.B.rows(), az[k].B.rows());
    EXPECT_EQ(lin.C.rows(), az[k].C.rows());
    EXPECT_EQ(lin.azimuth, az[k].azimuth);
    ASSERT_EQ(lin.y.size(), az[k].y.size());
    EXPECT_EQ(lin.y[9].rotating, true);   // RootMFlp1
    EXPECT_EQ(lin.y[0].rotating, false);  // GenSpeed
    EXPECT_EQ(lin.x[0].derivative_order, 2);
    samples.push_back(mbcSampleFromLin(lin));
    if (k == 0) first = lin;
  }
  const MbcLayout layout = mbcLayoutFromLin(first);
  EXPECT_EQ(layout.num_blades, 3);
  const MbcResult mbc = mbcAverage(layout, samples);
  const StateSpaceModel& avg = e.points[0].model;
  // Ω̇ from the state-derivative table is the residual's (≈ 0 at the periodic point): tiny differences.
  EXPECT_LE((mbc.A - avg.A).cwiseAbs().maxCoeff(), 1e-9 * avg.A.cwiseAbs().maxCoeff());

  const Model m = testing::nrel5mw();
  OperatingCondition at;
  at.rotor_speed = 9 * std::numbers::pi / 30;
  PeriodicOptions popt;
  popt.azimuths = 12;
  const RotorModes own = rotorModes(m, linearizePeriodic(m, at, popt));
  const Eigen::EigenSolver<MatX> es(mbc.A);
  std::vector<double> f;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i)
    if (es.eigenvalues()(i).imag() > 0) f.push_back(std::abs(es.eigenvalues()(i)) / (2 * std::numbers::pi));
  std::sort(f.begin(), f.end());
  std::vector<double> g;
  for (const auto& md : own.modes)
    if (md.damped_freq_hz > 0) g.push_back(md.freq_hz);
  std::sort(g.begin(), g.end());
  ASSERT_EQ(f.size(), g.size());
  for (size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i], g[i], 1e-8 * g[i]);
}

TEST(StateSpaceFiles, LinHeaderAndDescriptionsFollowOpenFast) {
  const StateSpaceExport e = rotorExport(3);
  const std::string t = linFileText(e.points[0].azimuths[0], "NREL 5MW");
  EXPECT_NE(t.find("ED Variable speed generator DOF (internal DOF index = DOF_GeAz), rad"), std::string::npos);
  EXPECT_NE(t.find("ED First time derivative of 1st flapwise bending-mode DOF of blade 2 (internal DOF index = "
                   "DOF_BF(2,1)), m/s"),
            std::string::npos);
  EXPECT_NE(t.find("Jacobians included in this file?"), std::string::npos);
  EXPECT_NE(t.find("\nA: 32 x 32\n"), std::string::npos);
  EXPECT_NE(t.find("\nD: 22 x 9\n"), std::string::npos);
}

TEST(StateSpaceFiles, JsonHasTheSameContent) {
  const StateSpaceExport e = rotorExport(3);
  const auto j = nlohmann::json::parse(stateSpaceJson(e));
  const auto& m = j["operating_points"][0]["model"];
  const StateSpaceModel& s = e.points[0].model;
  ASSERT_EQ(m["A"].size(), static_cast<size_t>(s.A.rows()));
  EXPECT_EQ(m["A"][5][7].get<double>(), s.A(5, 7));
  EXPECT_EQ(m["C"][1][3].get<double>(), s.C(1, 3));
  EXPECT_EQ(m["outputs"][0]["name"], "GenSpeed");
  EXPECT_EQ(j["operating_points"][0]["azimuths"].size(), 3u);
}

// Debian's python3-scipy is in scripts/install-deps.sh; a pyenv python3 on PATH may lack it, so
// /usr/bin/python3 is probed first. Skipped (not passed) when no python with scipy is found.
TEST(StateSpaceFiles, ScipyLoadsOneAndSeveralPointsWithTheSameKeys) {
  std::string python;
  for (const char* p : {"/usr/bin/python3", "python3"})
    if (std::system((std::string(p) + " -c 'import scipy.io' > /dev/null 2>&1").c_str()) == 0) {
      python = p;
      break;
    }
  if (python.empty()) GTEST_SKIP() << "no python3 with scipy (apt-get install python3-scipy)";
  StateSpaceExport e = rotorExport(3);
  StateSpaceExport two = e;
  two.points.push_back(rotorExport(3, 11).points[0]);
  two.points[0].wind_speed = 8;
  two.points[1].wind_speed = 10;
  test::ScratchDir dir;
  const std::string mat = (dir.path() / "ss.mat").string(), mat2 = (dir.path() / "ss2.mat").string(),
                    ref = (dir.path() / "A.txt").string();
  writeStateSpaceMat(e, mat);
  writeStateSpaceMat(two, mat2);
  {
    std::ofstream out(ref);
    out.precision(17);
    out << e.points[0].model.A << "\n";
  }
  // The reading of ROSCO's LinearTurbineModel(fromMat=True) (rosco/toolbox/linear/linear_models.py):
  // the cells of u_ops side by side, the wind speed their first row, indInps/indOuts 1-based.
  const std::string script = (dir.path() / "check.py").string();
  std::ofstream(script) << "import sys, numpy as np, scipy.io as sio\n"
                           "one, two = sio.loadmat(sys.argv[1]), sio.loadmat(sys.argv[2])\n"
                           "keys = lambda d: sorted(k for k in d if not k.startswith('__'))\n"
                           "assert keys(one) == keys(two), (keys(one), keys(two))\n"
                           "A = np.loadtxt(sys.argv[3])\n"
                           "assert np.array_equal(one['A'][0][0], A), 'A differs'\n"
                           "for d, n in ((one, 1), (two, 2)):\n"
                           "    u_ops = np.concatenate([u for u in d['u_ops'][0]], axis=1)\n"
                           "    assert u_ops.shape[1] == n and d['A'].shape == (1, n)\n"
                           "    B = d['B'][0][0]; C = d['C'][0][0]\n"
                           "    assert B.shape[1] == len(d['indInps'][0]) and C.shape[0] == len(d['indOuts'][0])\n"
                           "    assert u_ops[d['indInps'][0] - 1].shape[0] == B.shape[1]\n"
                           "assert list(np.concatenate([u for u in two['u_ops'][0]], axis=1)[0]) == [8.0, 10.0]\n"
                           "assert one['B'][0][0].shape == (32, 9) and one['C'][0][0].shape[1] == 32\n"
                           "assert [str(n[0]) for n in one['y_names'].ravel()][:2] == ['GenSpeed', 'RotSpeed']\n"
                           "assert [str(n[0]) for n in one['y_desc'].ravel()][:2] == ['ED GenSpeed', 'ED RotSpeed']\n"
                           "assert one['x_ops'][0][0].shape == (32, 1) and one['A_az'][0][0].shape == (32, 32, 3)\n"
                           "print('ok')\n";
  const std::string out = (dir.path() / "out.txt").string();
  const int rc = std::system(
      (python + " " + script + " " + mat + " " + mat2 + " " + ref + " > " + out + " 2>&1").c_str());
  EXPECT_EQ(rc, 0) << test::readText(out);
}

}  // namespace
}  // namespace whirl
