// `whirl export`: the .mat of the NREL 5MW .fst (its per-azimuth A is `whirl linearize`'s A), .lin
// files that `whirl lin` reads back into the modes `whirl modes` prints, JSON, selections, and
// one-line errors with a non-zero exit and nothing written on bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <matio.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

const std::string kFst = "cases/nrel5mw/Main_Onshore.fst";

// Rows of a whirl CSV matrix (header row, first column = names) as numbers.
std::vector<std::vector<double>> csvMatrix(const fs::path& p) {
  std::istringstream in(test::slurp(p));
  std::vector<std::vector<double>> rows;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<double> r;
    std::istringstream ls(line);
    std::string cell;
    std::getline(ls, cell, ',');
    while (std::getline(ls, cell, ',')) r.push_back(std::stod(cell));
    rows.push_back(r);
  }
  return rows;
}

size_t fileCount(const fs::path& d) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(d)) ++n;
  return n;
}

TEST(CliExport, MatOfTheFstMatchesLinearize) {
  const auto dir = test::freshDir("export_mat");
  const auto r = test::whirl("export " + kFst + " --format mat --azimuths 6 --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("32 states, 9 inputs, 22 outputs (multiblade average over 6 azimuths)"));
  const auto lin = test::whirl("linearize " + kFst + " --out " + (dir / "lin").string());
  ASSERT_EQ(lin.code, 0) << lin.err;
  const auto A = csvMatrix(dir / "lin" / "A.csv");
  mat_t* mat = Mat_Open((dir / "statespace.mat").c_str(), MAT_ACC_RDONLY);
  ASSERT_NE(mat, nullptr);
  matvar_t* v = Mat_VarRead(mat, "A_az");  // azimuth 1 = the model's own azimuth, as `linearize`
  ASSERT_NE(v, nullptr);
  const matvar_t* a1 = Mat_VarGetCell(v, 0);  // one layout for one or many points: 1 x n cells
  ASSERT_NE(a1, nullptr);
  const size_t n = a1->dims[0];
  ASSERT_EQ(n, A.size());
  const double* a = static_cast<const double*>(a1->data);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) EXPECT_EQ(a[i + j * n], A[i][j]) << i << "," << j;  // CSV at %.17g: exact
  Mat_VarFree(v);
  Mat_Close(mat);
}

TEST(CliExport, LinFilesReadBackIntoTheSameModes) {
  const auto dir = test::freshDir("export_lin");
  const auto r = test::whirl("export " + kFst + " --rpm 9 --azimuths 12 --format lin --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(fileCount(dir), 12u);
  std::string files;
  for (int k = 1; k <= 12; ++k) files += " " + (dir / ("statespace." + std::to_string(k) + ".lin")).string();
  const auto back = test::whirl("lin" + files + " --format json");
  ASSERT_EQ(back.code, 0) << back.err;
  const auto own = test::whirl("modes " + kFst + " --rpm 9 --azimuths 12 --format json");
  ASSERT_EQ(own.code, 0) << own.err;
  const auto jb = nlohmann::json::parse(back.out), jo = nlohmann::json::parse(own.out);
  ASSERT_EQ(jb["modes"].size(), jo["modes"].size());
  for (size_t i = 0; i < jo["modes"].size(); ++i) {
    const double fb = jb["modes"][i]["freq_hz"], fo = jo["modes"][i]["freq_hz"];
    // The rotor's rigid-body mode is a pair of eigenvalues at the origin (a Jordan block), fixed by the
    // data only to √(ε‖A‖) (‖A‖₂ ≈ 2e5 here: 7e-6 rad/s, against its 6.5e-4 rad/s); the two paths agree on it
    // to 1.1e-8 relative, depending on the machine's rounding, the other modes to 1e-11.
    const bool rigid = jo["modes"][i]["rigid_body"];
    EXPECT_NEAR(fb, fo, rigid ? 1e-6 * fo : 1e-9 * std::max(fo, 1e-3)) << i;
    const double zb = jb["modes"][i]["damping_ratio"], zo = jo["modes"][i]["damping_ratio"];
    EXPECT_NEAR(zb, zo, 1e-7) << i;
  }
}

TEST(CliExport, JsonWithSelectedInputsOutputsAndNoAzimuth) {
  const auto dir = test::freshDir("export_json");
  const auto r = test::whirl("export " + kFst +
                             " --format json --azimuths 3 --drop-azimuth --inputs "
                             "'generator torque,collective pitch' --outputs GenSpeed,YawBrTAxp --out " +
                             dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::slurp(dir / "statespace.json"));
  const auto& m = j["operating_points"][0]["model"];
  EXPECT_EQ(m["states"].size(), 31u);
  EXPECT_EQ(m["inputs"][1]["name"], "collective pitch");
  EXPECT_EQ(m["outputs"][1]["name"], "YawBrTAxp");
  EXPECT_EQ(m["B"][0].size(), 2u);
}

TEST(CliExport, ScheduleGivesOneModelPerOperatingPoint) {
  const auto dir = test::freshDir("export_schedule");
  const auto r = test::whirl("export " + kFst +
                             " --schedule cases/nrel5mw/NREL5MW_Oper.csv --azimuths 3 --format lin "
                             "--out " +
                             dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("26 operating points"));
  EXPECT_TRUE(fs::exists(dir / "statespace_26.3.lin"));
  EXPECT_THAT(test::slurp(dir / "statespace_26.3.lin"), HasSubstr("Wind Speed:"));
}

void expectOneLineError(const test::Run& r, const std::string& what, const fs::path& dir) {
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr(what));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  if (fs::exists(dir)) {
    EXPECT_EQ(fileCount(dir), 0u) << "nothing may be written";
  }
}

TEST(CliExport, BadInputFailsWithOneLineAndWritesNothing) {
  const auto dir = test::freshDir("export_bad");
  expectOneLineError(test::whirl("export " + kFst + " --format mat --inputs 'blade pitch' --out " + dir.string()),
                     "unknown input 'blade pitch'", dir);
  expectOneLineError(test::whirl("export " + kFst + " --format mat --outputs RootMyb1 --out " + dir.string()),
                     "unknown output 'RootMyb1'", dir);
  expectOneLineError(test::whirl("export cases/tower_topmass/tower_topmass.yaml --format mat --outputs x --out " +
                                 dir.string()),
                     "defines no outputs", dir);
  expectOneLineError(test::whirl("export " + kFst + " --format lin --inputs 'blade 1 pitch' --out " + dir.string()),
                     "select the rotating-frame inputs/outputs of every blade", dir);
  expectOneLineError(test::whirl("export " + kFst +
                                 " --format mat --rpm 9 --schedule cases/nrel5mw/NREL5MW_Oper.csv "
                                 "--out " +
                                 dir.string()),
                     "at most one of --rpm, --schedule and --wind", dir);
  const auto file = dir / "a_file";
  std::ofstream(file) << "x";
  const auto r = test::whirl("export " + kFst + " --format mat --out " + (file / "sub").string());
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("output folder"));
  fs::remove(file);
}

}  // namespace
}  // namespace whirl
