// `whirl modes --solver`, PETSc option pass-through, and `whirl study`.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "src/io/text/csv.hpp"
#include "tests/cli/cli_support.hpp"

namespace whirl::test {
namespace {

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) rows.push_back(splitCsvLine(line));
  return rows;
}

const std::string kCase = "cases/tower_topmass/tower_topmass_eq32.yaml";

#ifdef WHIRL_HAVE_PETSC

TEST(CliSparse, SparseModesEqualDenseModes) {
  const test::Run dense = whirl("modes " + kCase + " --solver dense --format csv");
  const test::Run sparse = whirl("modes " + kCase + " --solver sparse --nmodes 3 --format csv");
  ASSERT_EQ(dense.code, 0) << dense.err;
  ASSERT_EQ(sparse.code, 0) << sparse.err;
  const auto d = csvRows(dense.out), s = csvRows(sparse.out);
  ASSERT_EQ(s.size(), 4u);  // header + 3 modes
  EXPECT_EQ(s[0].back(), "residual");
  for (size_t k = 1; k < s.size(); ++k) {
    EXPECT_EQ(s[k][1], d[k][1]);  // same names
    const double fd = std::stod(d[k][2]), fs = std::stod(s[k][2]);
    EXPECT_NEAR(fs, fd, 1e-8 * fd) << s[k][1];
    EXPECT_LT(std::stod(s[k].back()), 1e-12);
  }
  EXPECT_NE(sparse.err.find("EPS krylovschur, ST sinvert"), std::string::npos) << sparse.err;
}

TEST(CliSparse, PetscOptionsPassThrough) {
  // after a lone "--"
  const test::Run a = whirl("modes " + kCase + " --solver sparse --nmodes 2 -- -eps_type arnoldi -eps_target -1");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_NE(a.err.find("EPS arnoldi"), std::string::npos) << a.err;
  EXPECT_NE(a.err.find("target -1,"), std::string::npos) << a.err;
  // and in --petsc "…"
  const test::Run b = whirl("modes " + kCase + " --solver sparse --nmodes 2 --petsc '-eps_type subspace'");
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.err.find("EPS subspace"), std::string::npos) << b.err;
  // a PETSc option without "--" is still CLI11's to refuse
  const test::Run c = whirl("modes " + kCase + " --solver sparse -eps_type lanczos");
  EXPECT_NE(c.code, 0);
}

TEST(CliSparse, RotorModelsRefuseTheSparseSolver) {
  const test::Run r = whirl("modes cases/nrel5mw/Main_Onshore.fst --solver sparse");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--solver sparse"), std::string::npos) << r.err;
}

#else

TEST(CliSparse, SparseSolverUnavailableWithoutPetsc) {
  const test::Run r = whirl("modes " + kCase + " --solver sparse");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unavailable"), std::string::npos) << r.err;
}

#endif

/// Each parameter set's rows in study.csv are exactly the campbell.csv of that set on its own.
TEST(CliStudy, SetsTimesPointsInOneTable) {
  const auto dir = freshDir("study");
  {
    std::ofstream f(dir / "sets.csv");
    f << "gravity,TwrFADmp(1)\n0,1\n9.80665,2\n";
  }
  const std::string common = " --rpm 6:3:12 --azimuths 8 ";
  const test::Run st = whirl("study cases/nrel5mw/Main_Onshore.fst --params '" + (dir / "sets.csv").string() + "'" +
                             common + "--out '" + (dir / "study").string() + "'");
  ASSERT_EQ(st.code, 0) << st.err;
  const test::Run c2 = whirl("campbell cases/nrel5mw/Main_Onshore.fst --set gravity=9.80665 --set 'TwrFADmp(1)=2'" +
                             common + "--no-plot --out '" + (dir / "two").string() + "'");
  ASSERT_EQ(c2.code, 0) << c2.err;
  const auto study = csvRows(slurp(dir / "study" / "study.csv"));
  const auto camp = csvRows(slurp(dir / "two" / "campbell.csv"));
  ASSERT_FALSE(study.empty());
  EXPECT_EQ(study[0], (std::vector<std::string>{"set", "gravity", "TwrFADmp(1)", "rpm", "wind_speed", "mode", "freq_hz",
                                                "damping_ratio"}));
  std::vector<std::vector<std::string>> set2;
  size_t set1 = 0;
  for (size_t k = 1; k < study.size(); ++k) {
    if (study[k][0] == "1") ++set1;
    if (study[k][0] != "2") continue;
    EXPECT_EQ(study[k][1], "9.80665");
    set2.emplace_back(study[k].begin() + 3, study[k].end());
  }
  EXPECT_GT(set1, 0u);
  ASSERT_EQ(set2.size() + 1, camp.size());
  for (size_t k = 0; k < set2.size(); ++k) EXPECT_EQ(set2[k], camp[k + 1]);
}

TEST(CliStudy, BadParameterKeyNamesTheRow) {
  const auto dir = freshDir("study_bad");
  {
    std::ofstream f(dir / "sets.csv");
    f << "gravity,NoSuchKey\n9.8,1\n";
  }
  const test::Run r = whirl("study cases/nrel5mw/Main_Onshore.fst --params '" + (dir / "sets.csv").string() +
                            "' --rpm 6:3:9 --azimuths 4 --out '" + (dir / "o").string() + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("sets.csv:2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("NoSuchKey"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o" / "study.csv"));
}

}  // namespace
}  // namespace whirl::test
