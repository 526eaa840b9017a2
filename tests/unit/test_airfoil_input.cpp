// AeroDyn airfoil files: the eight NREL 5MW polars (AirfoilInfo v1.01, one table with UA constants,
// NumCoords given as @"coords file"), column choices (InCol_*), several tables with the old `Ctrl`
// spelling, and every malformed case with its "file:line: key: reason" message. Line numbers are those
// of the NREL 5MW files (DU21_A17: Re 14, NumAlf 52, rows 55–196).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "tests/unit/aero_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::io::AirfoilColumns;
using whirl::io::AirfoilInput;
using whirl::io::readAirfoil;
using whirl::test::AeroScratch;
using whirl::test::airfoilDir;
using whirl::test::inputErrorMessage;

const std::string kDU21 = "5MW_Baseline/Airfoils/DU21_A17.dat";
const std::string kCyl1 = "5MW_Baseline/Airfoils/Cylinder1.dat";

TEST(AirfoilInput, DU21ReadsHeaderTableAndUnsteadyConstants) {
  const AirfoilInput a = readAirfoil(airfoilDir() / "DU21_A17.dat");
  EXPECT_EQ(a.name, "DU21_A17");
  EXPECT_EQ(a.path, airfoilDir() / "DU21_A17.dat");
  EXPECT_EQ(a.interp_order, 1);  // "DEFAULT" = linear, as OpenFAST
  EXPECT_TRUE(a.interp_order_default);
  EXPECT_FALSE(a.rel_thickness.has_value());
  EXPECT_DOUBLE_EQ(a.non_dim_area, 1.0);
  EXPECT_FALSE(a.num_coords.has_value());
  ASSERT_TRUE(a.coords_file.has_value());
  EXPECT_EQ(*a.coords_file, airfoilDir() / "DU21_A17_coords.txt");  // named, not read (not copied)
  EXPECT_EQ(a.bl_file, std::optional<std::string>("unused"));
  ASSERT_EQ(a.tables.size(), 1u);

  const whirl::io::AirfoilTable& t = a.tables[0];
  EXPECT_DOUBLE_EQ(t.re, 0.75);
  EXPECT_DOUBLE_EQ(t.user_prop, 0.0);
  EXPECT_EQ(t.re_line, 14);
  EXPECT_EQ(t.num_alf_line, 52);
  ASSERT_EQ(t.alpha_deg.size(), 142u);
  ASSERT_EQ(t.cl.size(), 142u);
  ASSERT_EQ(t.cd.size(), 142u);
  ASSERT_EQ(t.cm.size(), 142u);
  EXPECT_EQ(t.first_row_line, 55);
  EXPECT_EQ(t.row_lines.back(), 196);
  // First rows "-180.00 0.000 0.0185 0.0000", "-175.00 0.394 0.0332 0.1978"; last "180.00 0.000 0.0185 0.0000".
  EXPECT_DOUBLE_EQ(t.alpha_deg.front(), -180.0);
  EXPECT_DOUBLE_EQ(t.cl.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.cd.front(), 0.0185);
  EXPECT_DOUBLE_EQ(t.cm.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.alpha_deg[1], -175.0);
  EXPECT_DOUBLE_EQ(t.cl[1], 0.394);
  EXPECT_DOUBLE_EQ(t.cd[1], 0.0332);
  EXPECT_DOUBLE_EQ(t.cm[1], 0.1978);
  EXPECT_DOUBLE_EQ(t.alpha_deg.back(), 180.0);
  EXPECT_DOUBLE_EQ(t.cd.back(), 0.0185);

  EXPECT_TRUE(t.ua.included);
  EXPECT_EQ(t.ua.alpha0, std::optional<double>(-4.2));
  EXPECT_EQ(t.ua.alpha1, std::optional<double>(8.0));
  EXPECT_EQ(t.ua.C_nalpha, std::optional<double>(6.2047));
  EXPECT_EQ(t.ua.Cn1, std::optional<double>(1.4144));
  EXPECT_EQ(t.ua.Cd0, std::optional<double>(0.006));
  EXPECT_EQ(t.ua.Cm0, std::optional<double>(-0.121));
  EXPECT_FALSE(t.ua.UACutout.has_value());    // "DEFAULT"
  EXPECT_FALSE(t.ua.filtCutOff.has_value());  // "DEFAULT"
  EXPECT_FALSE(t.ua.alphaUpper.has_value());  // absent from this version
}

TEST(AirfoilInput, AllEightNrel5mwAirfoilsRead) {
  const std::pair<const char*, std::size_t> files[] = {{"Cylinder1", 3},  {"Cylinder2", 3},   {"DU40_A17", 136},
                                                       {"DU35_A17", 135}, {"DU30_A17", 143},  {"DU25_A17", 140},
                                                       {"DU21_A17", 142}, {"NACA64_A17", 127}};
  for (const auto& [name, num_alf] : files) {
    SCOPED_TRACE(name);
    const AirfoilInput a = readAirfoil(airfoilDir() / (std::string(name) + ".dat"));
    ASSERT_EQ(a.tables.size(), 1u);
    const whirl::io::AirfoilTable& t = a.tables[0];
    EXPECT_EQ(t.alpha_deg.size(), num_alf);
    EXPECT_EQ(t.cm.size(), num_alf);
    EXPECT_DOUBLE_EQ(t.alpha_deg.front(), -180.0);
    EXPECT_DOUBLE_EQ(t.alpha_deg.back(), 180.0);
  }
  const AirfoilInput cyl = readAirfoil(airfoilDir() / "Cylinder1.dat");
  EXPECT_DOUBLE_EQ(cyl.tables[0].cd[1], 0.5);
  EXPECT_DOUBLE_EQ(cyl.tables[0].alpha_deg[1], 0.0);
}

TEST(AirfoilInput, ColumnChoicesOfTheAeroDynMainFile) {
  // InCol_Cm = 0: no Cm; Cl and Cd taken from swapped columns.
  const AirfoilInput a = readAirfoil(airfoilDir() / "DU21_A17.dat", AirfoilColumns{1, 3, 2, 0});
  const whirl::io::AirfoilTable& t = a.tables[0];
  EXPECT_TRUE(t.cm.empty());
  EXPECT_DOUBLE_EQ(t.cl[1], 0.0332);
  EXPECT_DOUBLE_EQ(t.cd[1], 0.394);
  // A column beyond the rows: named with the first row's line.
  EXPECT_EQ(inputErrorMessage([&] {
              readAirfoil(airfoilDir() / "DU21_A17.dat", AirfoilColumns{1, 2, 3, 5});
            }),
            (airfoilDir() / "DU21_A17.dat").string() +
                ":55: row has 4 numbers, the columns asked for (InCol_Alfa/Cl/Cd/Cm = 1/2/3/5) need 5");
  EXPECT_THAT(inputErrorMessage([&] {
                readAirfoil(airfoilDir() / "DU21_A17.dat", AirfoilColumns{0, 2, 3, 4});
              }),
              HasSubstr("InCol_*: airfoil table columns must be >= 1"));
}

TEST(AirfoilInput, SeveralTablesCtrlSpellingAndCommentedOutKeys) {
  // Two tables, the second with the pre-v3 `Ctrl` key and no UA data; a commented-out NumTabs line
  // (as in the SWRT certification-test airfoils) is ignored.
  AeroScratch s;
  s.edit(kCyl1, "          1   NumTabs ", "!         3   NumTabs\n          2   NumTabs ");
  std::string text = whirl::test::readText(s.path(kCyl1));
  text +=
      "        1.5   Re                ! Reynolds number in millions\n"
      "        0.5   Ctrl              ! Control setting\n"
      "False         InclUAdata        ! no UA constants\n"
      "          2   NumAlf            ! Number of data lines in the following table\n"
      "!    Alpha      Cl      Cd\n"
      "   -180.00      0.000   0.4000   0.1\n"
      "   180.00       0.000   0.4000   0.1\n";
  const AirfoilInput a = readAirfoil(s.write(kCyl1, text));
  ASSERT_EQ(a.tables.size(), 2u);
  EXPECT_DOUBLE_EQ(a.tables[0].re, 0.75);
  EXPECT_EQ(a.tables[0].alpha_deg.size(), 3u);
  EXPECT_EQ(a.tables[0].re_line, 15);  // one line added above
  EXPECT_DOUBLE_EQ(a.tables[1].re, 1.5);
  EXPECT_DOUBLE_EQ(a.tables[1].user_prop, 0.5);
  EXPECT_FALSE(a.tables[1].ua.included);
  EXPECT_EQ(a.tables[1].num_alf_line, 64);
  EXPECT_EQ(a.tables[1].row_lines, (std::vector<int>{66, 67}));
  EXPECT_DOUBLE_EQ(a.tables[1].cd[0], 0.4);
}

/// DU21_A17 in a scratch folder, edited; the error message of reading it, its path shown as "<file>".
std::string du21Error(const std::string& from, const std::string& to) {
  AeroScratch s;
  s.edit(kDU21, from, to);
  return whirl::test::withFilePlaceholder(inputErrorMessage([&] { readAirfoil(s.path(kDU21)); }), s.path(kDU21));
}

TEST(AirfoilInputErrors, MissingFile) {
  const std::filesystem::path p = airfoilDir() / "NoSuchAirfoil.dat";
  EXPECT_EQ(inputErrorMessage([&] { readAirfoil(p); }), p.string() + ": cannot open file");
}

TEST(AirfoilInputErrors, TruncatedTableAtEndOfFile) {
  AeroScratch s;
  s.truncate(kDU21, 194);  // rows 55–194: 140 of 142
  EXPECT_EQ(inputErrorMessage([&] { readAirfoil(s.path(kDU21)); }),
            s.path(kDU21).string() +
                ":52: NumAlf: table has 140 rows, 142 expected: the file ends at line 194 "
                "(truncated table?)");
}

TEST(AirfoilInputErrors, MalformedRow) {
  EXPECT_EQ(du21Error("   -175.00    0.394   0.0332   0.1978", "   -175.00    0.394   0.03x2   0.1978"),
            "<file>:52: NumAlf: table has 1 rows, 142 expected: line 56 is not a row of numbers (truncated table?)");
}

TEST(AirfoilInputErrors, RowWithTooFewNumbers) {
  EXPECT_EQ(du21Error("   -175.00    0.394   0.0332   0.1978", "   -175.00    0.394   0.0332"),
            "<file>:56: row has 3 numbers, the columns asked for (InCol_Alfa/Cl/Cd/Cm = 1/2/3/4) need 4");
}

TEST(AirfoilInputErrors, NaNAndInfinity) {
  EXPECT_EQ(du21Error("   -175.00    0.394   0.0332", "   -175.00    0.394   NaN"), "<file>:56: Cd: value is NaN");
  EXPECT_EQ(du21Error("   -175.00    0.394   0.0332", "   -175.00    inf   0.0332"),
            "<file>:56: Cl: value is infinite");
}

TEST(AirfoilInputErrors, AlphaNotStrictlyIncreasing) {
  EXPECT_EQ(du21Error("   -170.00    0.788", "   -175.00    0.788"),
            "<file>:57: Alpha: must increase from row to row (-175 after -175)");
}

TEST(AirfoilInputErrors, HeaderValues) {
  EXPECT_EQ(du21Error("\"DEFAULT\"     InterpOrd", "          2   InterpOrd"),
            "<file>:6: InterpOrd: must be 1 (linear) or 3 (cubic spline) or \"default\" (is 2)");
  EXPECT_EQ(du21Error("       0.75   Re ", "          0   Re "), "<file>:14: Re: must be positive (is 0)");
  EXPECT_EQ(du21Error("        142   NumAlf", "          0   NumAlf"), "<file>:52: NumAlf: must be at least 1 (is 0)");
  EXPECT_EQ(du21Error("          1   NumTabs", "          0   NumTabs"),
            "<file>:10: NumTabs: must be at least 1 (is 0)");
  EXPECT_EQ(du21Error("          1   NonDimArea", "          x   NonDimArea"),
            "<file>:7: NonDimArea: 'x' is not a number");
  EXPECT_EQ(du21Error("       0.75   Re ", "       0.75   Reynolds "),
            "<file>:14: Reynolds: not a key of an OpenFAST AeroDyn airfoil file (expected Re here): OpenFAST reads by "
            "position, so an extra line shifts every later value; remove it (or check the file type)");
}

TEST(AirfoilInputErrors, FewerTablesThanNumTabs) {
  EXPECT_EQ(du21Error("          1   NumTabs", "          2   NumTabs"),
            "<file>:10: NumTabs: 2 tables announced, no 'Re' line for table 2 after line 196 (truncated file?)");
}

TEST(AirfoilInputErrors, FirstLineMustBeAComment) {
  AeroScratch s;
  const std::string text = whirl::test::readText(s.path(kDU21));
  const std::filesystem::path p = s.write(kDU21, "\"DEFAULT\"     InterpOrd\n" + text.substr(text.find('\n') + 1));
  EXPECT_EQ(inputErrorMessage([&] { readAirfoil(p); }),
            p.string() + ":1: the first line of an airfoil file must be a comment (starting with '!')");
}

}  // namespace
