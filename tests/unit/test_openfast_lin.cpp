// OpenFAST .lin reader: the example files of tests/data/openfast-lin (OpenFAST output, see
// tests/data/openfast/README.md), a synthetic v5-style file with inputs, outputs and B, C, D, and
// broken files (missing, truncated, non-numeric) written at test time.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "src/base/error.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "tests/unit/test_util.hpp"

namespace {

const std::string kData = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast-lin/";

using whirl::test::slurp;
using whirl::test::TempDir;

/// Message of the InputError thrown by reading `path` ("" if none).
std::string readError(const std::string& path) {
  try {
    whirl::readOpenFastLin(path);
  } catch (const whirl::InputError& e) {
    return e.what();
  }
  return "";
}

struct Expected {
  std::string file;
  int n_x;
  double time, rotor_speed, azimuth, wind_speed;
  double a_10_0, a_last;  // A(n_x/2, 0) and A(n_x-1, n_x-1) as printed
};

class LinExample : public ::testing::TestWithParam<Expected> {};

TEST_P(LinExample, HeaderTablesAndMatrix) {
  const Expected& e = GetParam();
  const auto f = whirl::readOpenFastLin(kData + e.file);
  EXPECT_EQ(f.path, kData + e.file);
  EXPECT_NE(f.generator.find("OpenFAST"), std::string::npos);
  EXPECT_EQ(f.n_x, e.n_x);
  EXPECT_EQ(f.n_xd + f.n_z + f.n_u + f.n_y, 0);
  EXPECT_FALSE(f.has_jacobians);
  EXPECT_DOUBLE_EQ(f.time, e.time);
  EXPECT_DOUBLE_EQ(f.rotor_speed, e.rotor_speed);
  EXPECT_DOUBLE_EQ(f.azimuth, e.azimuth);
  ASSERT_TRUE(f.wind_speed.has_value());
  EXPECT_DOUBLE_EQ(*f.wind_speed, e.wind_speed);
  EXPECT_EQ(f.non_finite_values, 0);

  ASSERT_EQ(f.x.size(), static_cast<std::size_t>(e.n_x));
  ASSERT_EQ(f.xdot.size(), static_cast<std::size_t>(e.n_x));
  EXPECT_TRUE(f.u.empty() && f.y.empty());
  int rotating = 0;
  for (const auto& v : f.x) {
    EXPECT_EQ(v.derivative_order, 2);
    EXPECT_TRUE(v.op_values.empty());
    EXPECT_TRUE(std::isfinite(v.op));
    rotating += v.rotating;
    EXPECT_EQ(v.rotating, v.description.find("blade") != std::string::npos) << v.description;
  }
  EXPECT_EQ(rotating, 18);  // 3 blades x (flap 1, edge 1, flap 2) x (q, q dot)
  const int n = e.n_x / 2;
  EXPECT_EQ(f.x[n].description.rfind("ED First time derivative of ", 0), 0u) << f.x[n].description;
  EXPECT_EQ(f.xdot[0].description.rfind("First time derivative of ED ", 0), 0u);
  EXPECT_EQ(
      f.x.back().description,
      "ED First time derivative of 2nd flapwise bending-mode DOF of blade 3 (internal DOF index = DOF_BF(3,2)), m/s");
  EXPECT_EQ(f.x[0].line, 22);

  ASSERT_EQ(f.A.rows(), e.n_x);
  ASSERT_EQ(f.A.cols(), e.n_x);
  EXPECT_TRUE(f.B.size() == 0 && f.C.size() == 0 && f.D.size() == 0);
  // Kinematic rows: d/dt q = q dot.
  EXPECT_EQ(f.A.topLeftCorner(n, n).norm(), 0.0);
  EXPECT_EQ((f.A.topRightCorner(n, n) - Eigen::MatrixXd::Identity(n, n)).norm(), 0.0);
  EXPECT_DOUBLE_EQ(f.A(n, 0), e.a_10_0);
  EXPECT_DOUBLE_EQ(f.A(e.n_x - 1, e.n_x - 1), e.a_last);
}

INSTANTIATE_TEST_SUITE_P(
    Files, LinExample,
    ::testing::Values(Expected{"rotating-9rpm/Main.1.lin", 20, 119.92, 0.9425, 0.0092, 8.0, 8.885e-04, -3.715},
                      Expected{"rotating-9rpm/Main.12.lin", 20, 121.95, 0.9425, 1.9224, 8.0, 7.697e-04, -3.905},
                      Expected{"rotating-9rpm/Main.24.lin", 20, 124.17, 0.9425, 4.0147, 8.0, 7.676e-04, -3.916},
                      // ws03: A(15,0) is the first value of row 16; printed with 13 digits (E-003 exponents).
                      Expected{"ws03/ws03.0.1.lin", 30, 413.09, 0.7301, 0.0067, 3.0, -4.571735886246, -3.253592101136},
                      Expected{"ws03/ws03.0.13.lin", 30, 415.95, 0.7301, 2.0948, 3.0, -4.571735724989, -3.180672661438},
                      Expected{"ws03/ws03.0.34.lin", 30, 420.97, 0.7301, 5.7600, 3.0, -4.571769457696,
                               -3.150582214435}),
    [](const auto& p) {
      std::string s = p.param.file;
      for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return s;
    });

// A small file in the v5 layout: inputs and outputs with "Column"/"Row" titles, an orientation
// output with three comma-separated operating-point values, overflowed fields (****), a 3-digit
// exponent without 'E', Jacobians (dUdu, dUdy) before the state matrices, no wind speed line.
const char* kSynthetic = R"(
Linearized model: Predictions were generated on 01-Jan-2025 at 00:00:00 using OpenFAST, compiled as a 64-bit application using double precision at commit v5.0.0
 linked with  NWTC Subroutine Library; ElastoDyn; ServoDyn

Description from the FAST input file: synthetic test file. Azimuth: 99 rad (not a header key)

Simulation information:
   Simulation time:                    10.0000 s
   Rotor Speed:                         1.2000 rad/s
   Azimuth:                             3.1000 rad
   Number of continuous states:     2
   Number of discrete states:       0
   Number of constraint states:     0
   Number of inputs:                3
   Number of outputs:               4
   Jacobians included in this file?   Yes

Order of continuous states:
   Row/Column Operating Point                     Rotating Frame? Derivative Order Description
   ---------- ---------------                     --------------- ---------------- -----------
          1    1.000E-01                                 T               2         ED 1st flapwise bending-mode DOF of blade 1 (internal DOF index = DOF_BF(1,1)), m
          2    2.000E-01                                 T               2         ED First time derivative of 1st flapwise bending-mode DOF of blade 1 (internal DOF index = DOF_BF(1,1)), m/s

Order of continuous state derivatives:
   Row/Column Operating Point                     Rotating Frame? Derivative Order Description
   ---------- ---------------                     --------------- ---------------- -----------
          1    2.000E-01                                 T               2         First time derivative of ED 1st flapwise bending-mode DOF of blade 1 (internal DOF index = DOF_BF(1,1)), m/s
          2   -3.000E+00                                 T               2         First time derivative of ED First time derivative of 1st flapwise bending-mode DOF of blade 1 (internal DOF index = DOF_BF(1,1)), m/s/s

Order of inputs:
       Column Operating Point                     Rotating Frame? Derivative Order Description
   ---------- ---------------                     --------------- ---------------- -----------
          1    4.000E+01                                 F               0         ED Generator torque, Nm
          2    1.000E-02                                 T               0         ED Blade 1 pitch command, rad
          3    ********                                  F               0         ED Extended input: collective blade-pitch command, rad

Order of outputs:
          Row Operating Point                     Rotating Frame? Derivative Order Description
   ---------- ---------------                     --------------- ---------------- -----------
          1    5.000E+00                                 T               0         ED RootMxc1, (kN-m)
          2    1.000E+00, 0.000E+00, 0.000E+00           F               0         ED Nacelle orientation, row 1
          3    0.000E+00, 1.000E+00, 0.000E+00           F               0         ED Nacelle orientation, row 2
          4    0.000E+00, 0.000E+00, 1.000E+00           F               0         ED Nacelle orientation, row 3


Jacobian matrices:

dUdu: 3 x 3
    1.000E+00  0.000E+00  0.000E+00
    0.000E+00  1.000E+00  0.000E+00
    0.000E+00  0.000E+00  1.000E+00
dUdy: 3 x 4
    0.000E+00  0.000E+00  0.000E+00  0.000E+00
    0.000E+00  0.000E+00  0.000E+00  0.000E+00
    0.000E+00  0.000E+00  0.000E+00  0.000E+00


Linearized state matrices:

A: 2 x 2
    0.000E+00  1.000E+00
   -4.000E+01 -2.000E-01
B: 2 x 3
    0.000E+00  0.000E+00  0.000E+00
    1.000E-03  5.000E+00 -1.234567-100
C: 4 x 2
    7.000E+00  ********
    0.000E+00  0.000E+00
    0.000E+00  0.000E+00
    0.000E+00  0.000E+00
D: 4 x 3
    0.000E+00  2.000E+00  0.000E+00
    0.000E+00  0.000E+00  0.000E+00
    0.000E+00  0.000E+00  0.000E+00
    0.000E+00  0.000E+00  0.000E+00
)";

TEST(OpenFastLin, SyntheticWithInputsOutputsAndJacobians) {
  TempDir dir;
  const auto f = whirl::readOpenFastLin(dir.write("synthetic.lin", kSynthetic));
  EXPECT_EQ(f.generator.rfind("Predictions were generated", 0), 0u);
  EXPECT_DOUBLE_EQ(f.azimuth, 3.1);
  EXPECT_DOUBLE_EQ(f.rotor_speed, 1.2);
  EXPECT_FALSE(f.wind_speed.has_value());
  EXPECT_TRUE(f.has_jacobians);
  ASSERT_EQ(f.u.size(), 3u);
  ASSERT_EQ(f.y.size(), 4u);
  EXPECT_TRUE(f.u[1].rotating);
  EXPECT_EQ(f.u[1].description, "ED Blade 1 pitch command, rad");
  EXPECT_EQ(f.u[0].derivative_order, 0);
  EXPECT_TRUE(std::isnan(f.u[2].op));
  EXPECT_EQ(f.y[0].description, "ED RootMxc1, (kN-m)");
  EXPECT_DOUBLE_EQ(f.y[2].op, 0.0);
  ASSERT_EQ(f.y[2].op_values.size(), 3u);
  EXPECT_DOUBLE_EQ(f.y[2].op_values[1], 1.0);
  EXPECT_EQ(f.y[2].description, "ED Nacelle orientation, row 2");
  EXPECT_EQ(f.xdot[1].op, -3.0);

  ASSERT_EQ(f.A.rows(), 2);
  EXPECT_DOUBLE_EQ(f.A(1, 0), -40.0);
  ASSERT_EQ(f.B.rows(), 2);
  ASSERT_EQ(f.B.cols(), 3);
  EXPECT_DOUBLE_EQ(f.B(1, 1), 5.0);
  EXPECT_NEAR(f.B(1, 2), -1.234567e-100, 1e-112);
  ASSERT_EQ(f.C.rows(), 4);
  EXPECT_DOUBLE_EQ(f.C(0, 0), 7.0);
  EXPECT_TRUE(std::isnan(f.C(0, 1)));
  ASSERT_EQ(f.D.cols(), 3);
  EXPECT_DOUBLE_EQ(f.D(0, 1), 2.0);
  EXPECT_EQ(f.non_finite_values, 2);  // the **** in the inputs table and in C
}

TEST(OpenFastLin, MissingFileNamesTheFile) {
  const std::string msg = readError(kData + "no-such-folder/Main.1.lin");
  EXPECT_NE(msg.find("no-such-folder/Main.1.lin"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
}

TEST(OpenFastLin, TruncatedMatrixNamesFileAndLine) {
  TempDir dir;
  // Main.1.lin has 90 lines; A occupies lines 71-90. Keep 85 lines: 15 of its 20 rows.
  std::istringstream in(slurp(kData + "rotating-9rpm/Main.1.lin"));
  std::string text, line;
  for (int i = 0; i < 85 && std::getline(in, line); ++i) text += line + "\n";
  const std::string path = dir.write("Main.1.lin", text);
  const std::string msg = readError(path);
  EXPECT_NE(msg.find(path + ":85"), std::string::npos) << msg;
  EXPECT_NE(msg.find("A: truncated"), std::string::npos) << msg;
  EXPECT_NE(msg.find("15 of 20 rows"), std::string::npos) << msg;

  // Cut inside the states table: the header declares 20 rows.
  std::istringstream in2(slurp(kData + "rotating-9rpm/Main.1.lin"));
  text.clear();
  for (int i = 0; i < 30 && std::getline(in2, line); ++i) text += line + "\n";
  const std::string msg2 = readError(dir.write("cut.lin", text));
  EXPECT_NE(msg2.find("cut.lin:30"), std::string::npos) << msg2;
  EXPECT_NE(msg2.find("9 rows where the header declares 20"), std::string::npos) << msg2;

  // A row with a missing value.
  std::string short_row = slurp(kData + "rotating-9rpm/Main.1.lin");
  short_row.erase(short_row.rfind(" -3.715E+00"));
  const std::string msg3 = readError(dir.write("short.lin", short_row + "\n"));
  EXPECT_NE(msg3.find("short.lin:90: A: 19 values in row 20, expected 20"), std::string::npos) << msg3;
}

TEST(OpenFastLin, NonNumericValueNamesFileAndLine) {
  TempDir dir;
  std::string text = slurp(kData + "rotating-9rpm/Main.1.lin");
  const std::size_t at = text.find("8.885E-04");  // A(10,0), line 81
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 9, "8.885X-04");
  const std::string path = dir.write("bad.lin", text);
  const std::string msg = readError(path);
  EXPECT_NE(msg.find(path + ":81: A: '8.885X-04' is not a number"), std::string::npos) << msg;

  std::string header = slurp(kData + "rotating-9rpm/Main.1.lin");
  header.replace(header.find("0.9425 rad/s"), 6, "fast  ");
  const std::string msg2 = readError(dir.write("header.lin", header));
  EXPECT_NE(msg2.find("header.lin:9: Rotor Speed: 'fast' is not a number"), std::string::npos) << msg2;
}

}  // namespace
