// Tokenizer of OpenFAST input files: value/key lines, lists, tables, OutList blocks, typed getters,
// overrides, and the place (file:line: key) named in every error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "src/io/openfast/openfast_input.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::io::OpenFastFile;
using whirl::test::inputErrorMessage;

const char* kSmall =
    "------- TEST INPUT FILE -------------------------------------------\n"
    "A title line with 5.0 numbers and words\n"
    "---------------------- SECTION -------------------------------------\n"
    "False         Echo        - Echo input data (flag)\n"
    "\"default\"     DT          - Integration time step (s)\n"
    "    default   DT2         - unquoted default\n"
    "    9.80665   Gravity     - Gravitational acceleration (m/s^2)\n"
    "          3   NumBl       - Number of blades (-)\n"
    "TRUE          YawDOF      - Yaw DOF (flag)\n"
    "t             ShortFlag   - Fortran short logical\n"
    "\"sub dir\\blade file.dat\"  BldFile(1)  - quoted path with a space and a backslash\n"
    "         10,         19,         28    TwrGagNd    - List of tower nodes\n"
    "          5,  BldGagNd        - trailing comma\n"
    "     1.5D+03  FortranD    - Fortran exponent\n"
    "          0   PrescribedForcesCoord- key glued to the dash\n"
    "              OutList     - The next line(s) contains a list of output parameters\n"
    "\"BldPitch1\"               - Pitch angle\n"
    "LSSGagPxa                   - unquoted channel\n"
    "END of input file (the word \"END\" must appear in the first 3 columns of this last OutList line)\n"
    "---------------------- DISTRIBUTED PROPERTIES ----------------------\n"
    "  HtFract       TMassDen         TwFAStif\n"
    "   (-)           (kg/m)           (N m^2)\n"
    "0.0000000E+00  5.5908700E+03  6.1434300E+11\n"
    "1.0000000E+00  2.5362700E+03  1.1582000E+11\n"
    "---------------------- MODE SHAPES ---------------------------------\n"
    "     0.7004   TwFAM1Sh(2) - Mode 1, coefficient of x^2 term\n"
    "         12   NumBl       - duplicated key: the first one wins\n";

OpenFastFile small() { return OpenFastFile::parse(kSmall, "/cases/x/small.dat"); }

TEST(OpenFastInput, ValueLinesAndTypes) {
  const OpenFastFile f = small();
  EXPECT_EQ(f.title(), "A title line with 5.0 numbers and words");
  EXPECT_FALSE(f.getBool("Echo"));
  EXPECT_TRUE(f.getBool("YawDOF"));
  EXPECT_TRUE(f.getBool("ShortFlag"));
  EXPECT_FALSE(f.getDoubleOrDefault("DT").has_value());
  EXPECT_FALSE(f.getDoubleOrDefault("DT2").has_value());
  EXPECT_DOUBLE_EQ(*f.getDoubleOrDefault("Gravity"), 9.80665);
  EXPECT_DOUBLE_EQ(f.getDouble("gravity"), 9.80665);  // keys are case-insensitive
  EXPECT_EQ(f.getInt("NumBl"), 3);                    // first of two NumBl lines
  EXPECT_DOUBLE_EQ(f.getDouble("FortranD"), 1500.0);
  EXPECT_EQ(f.getInt("PrescribedForcesCoord"), 0);
  EXPECT_EQ(f.getPath("BldFile(1)"), std::filesystem::path("/cases/x/sub dir/blade file.dat"));
  EXPECT_EQ(f.getDoubles("TwrGagNd"), (std::vector<double>{10, 19, 28}));
  EXPECT_EQ(f.getDoubles("BldGagNd"), (std::vector<double>{5}));
  EXPECT_DOUBLE_EQ(f.getDouble("TwFAM1Sh(2)"), 0.7004);
}

TEST(OpenFastInput, RawValueAndLineKept) {
  const OpenFastFile f = small();
  const whirl::io::OpenFastEntry* e = f.find("TwrGagNd");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->raw, "10,         19,         28");
  EXPECT_EQ(e->line, 12);
  EXPECT_EQ(f.find("DT")->raw, "\"default\"");
  EXPECT_EQ(f.find("TwFAM1Sh(2)")->line, 26);
}

TEST(OpenFastInput, OutListBlockIsSkipped) {
  const OpenFastFile f = small();
  EXPECT_FALSE(f.has("OutList"));
  EXPECT_FALSE(f.has("LSSGagPxa"));
  EXPECT_FALSE(f.has("-"));
  EXPECT_TRUE(f.has("TwFAM1Sh(2)"));  // parsing resumes after END
}

TEST(OpenFastInput, TableWithHeaderAndUnits) {
  const OpenFastFile f = small();
  const whirl::io::OpenFastTable* t = f.findTable("twfastif");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->columns, (std::vector<std::string>{"HtFract", "TMassDen", "TwFAStif"}));
  EXPECT_EQ(t->units, (std::vector<std::string>{"(-)", "(kg/m)", "(N m^2)"}));
  EXPECT_EQ(t->header_line, 21);
  ASSERT_EQ(t->rows.size(), 2u);
  EXPECT_EQ(t->row_lines, (std::vector<int>{23, 24}));
  EXPECT_DOUBLE_EQ(t->rows[1][2], 1.1582e11);
  EXPECT_EQ(t->end_line, 25);
  EXPECT_FALSE(t->ends_at_eof);
  EXPECT_EQ(f.findTable("NoSuchColumn"), nullptr);
}

TEST(OpenFastInput, TitleAfterTwoSeparators) {
  // FAST v7 files open with two separator lines; the title is the third line.
  const OpenFastFile f = OpenFastFile::parse(
      "--------------------\n---- FAST TOWER FILE ----\nFAST v7.02 tower file for turbine \"WP1.5\"\n"
      "---- TOWER PARAMETERS ----\n  10        NTwInpSt    - Number of input stations\n",
      "t.dat");
  EXPECT_EQ(f.title(), "FAST v7.02 tower file for turbine \"WP1.5\"");
  EXPECT_EQ(f.entries().size(), 1u);
  EXPECT_EQ(f.getInt("NTwInpSt"), 10);
}

TEST(OpenFastInput, CrLfLineEndings) {
  const OpenFastFile f = OpenFastFile::parse("---\r\ntitle\r\n  2.5  X  - x\r\nTrue  Y - y\r\n", "w.dat");
  EXPECT_DOUBLE_EQ(f.getDouble("X"), 2.5);
  EXPECT_TRUE(f.getBool("Y"));
}

TEST(OpenFastInput, ParseFortranDouble) {
  using whirl::io::parseFortranDouble;
  EXPECT_DOUBLE_EQ(*parseFortranDouble("+2"), 2.0);
  EXPECT_DOUBLE_EQ(*parseFortranDouble("-1.25d-2"), -0.0125);
  EXPECT_DOUBLE_EQ(*parseFortranDouble("8.67637E+08"), 8.67637e8);
  EXPECT_TRUE(std::isnan(*parseFortranDouble("NaN")));
  EXPECT_TRUE(std::isinf(*parseFortranDouble("inf")));
  EXPECT_FALSE(parseFortranDouble("1.0e").has_value());
  EXPECT_FALSE(parseFortranDouble("default").has_value());
  EXPECT_FALSE(parseFortranDouble("12abc").has_value());
}

TEST(OpenFastInput, ErrorsNameFileLineKeyAndReason) {
  const OpenFastFile f = OpenFastFile::parse(
      "---\ntitle\n  abc  Mass  - m\n  nan  Stiff - k\n  -inf  Damp - c\n  3.5  Count - n\n"
      "  maybe  Flag - f\n  1, 2  Scalar - s\n",
      "bad.dat");
  EXPECT_EQ(inputErrorMessage([&] { f.getDouble("Mass"); }), "bad.dat:3: Mass: 'abc' is not a number");
  EXPECT_EQ(inputErrorMessage([&] { f.getDouble("Stiff"); }), "bad.dat:4: Stiff: value is NaN");
  EXPECT_EQ(inputErrorMessage([&] { f.getDouble("Damp"); }), "bad.dat:5: Damp: value is infinite");
  EXPECT_EQ(inputErrorMessage([&] { f.getInt("Count"); }), "bad.dat:6: Count: '3.5' is not an integer");
  EXPECT_EQ(inputErrorMessage([&] { f.getBool("Flag"); }), "bad.dat:7: Flag: 'maybe' is not True or False");
  EXPECT_EQ(inputErrorMessage([&] { f.getDouble("Scalar"); }), "bad.dat:8: Scalar: expected one number, found '1, 2'");
  EXPECT_EQ(inputErrorMessage([&] { f.getDouble("NacMass"); }), "bad.dat: NacMass: key not found in this file");
  EXPECT_EQ(inputErrorMessage([&] { f.getExistingPath("Mass"); }), "bad.dat:3: Mass: file not found: abc");
  EXPECT_FALSE(f.findDouble("Missing").has_value());
  EXPECT_THAT(inputErrorMessage([&] { f.findDouble("Mass"); }), HasSubstr("bad.dat:3: Mass:"));
}

TEST(OpenFastInput, MissingFile) {
  EXPECT_EQ(inputErrorMessage([] { OpenFastFile::read("/nonexistent/whirl/x.dat"); }),
            "/nonexistent/whirl/x.dat: cannot open file");
}

TEST(OpenFastInput, SetValueReplacesAndMarksOverride) {
  OpenFastFile f = small();
  f.setValue("gravity", "9.81");
  EXPECT_DOUBLE_EQ(f.getDouble("Gravity"), 9.81);
  EXPECT_TRUE(f.find("Gravity")->overridden);
  EXPECT_EQ(f.find("Gravity")->line, 7);
  f.setValue("TwrGagNd", "1,2");
  EXPECT_EQ(f.getDoubles("TwrGagNd"), (std::vector<double>{1, 2}));
  f.setValue("NumBl", "x");
  EXPECT_EQ(inputErrorMessage([&] { f.getInt("NumBl"); }),
            "/cases/x/small.dat:8: NumBl: 'x' is not an integer (value set by override)");
  EXPECT_EQ(inputErrorMessage([&] { f.setValue("NoSuchKey", "1"); }),
            "/cases/x/small.dat: NoSuchKey: unknown key (not in this file)");
}

TEST(OpenFastOverrides, ParseAndApplyAcrossFiles) {
  using whirl::io::OverrideSet;
  using whirl::io::parseOverride;
  const whirl::io::KeyOverride o = parseOverride(" NacMass = 250000 ");
  EXPECT_EQ(o.key, "NacMass");
  EXPECT_EQ(o.value, "250000");
  EXPECT_THAT(inputErrorMessage([] { parseOverride("NacMass"); }), HasSubstr("expected KEY=VALUE"));
  EXPECT_THAT(inputErrorMessage([] { parseOverride("=3"); }), HasSubstr("empty key"));
  EXPECT_THAT(inputErrorMessage([] { parseOverride("NacMass="); }), HasSubstr("empty value"));

  OverrideSet set({{"Gravity", "9.81"}, {"NoSuchKey", "1"}});
  OpenFastFile f = small();
  OpenFastFile g = OpenFastFile::parse("---\ntitle\n 1 Other - o\n", "other.dat");
  set.applyTo(f);
  set.applyTo(g);
  EXPECT_DOUBLE_EQ(f.getDouble("Gravity"), 9.81);
  EXPECT_EQ(inputErrorMessage([&] { set.requireAllUsed(); }),
            "NoSuchKey: unknown key (not in any file read: /cases/x/small.dat, other.dat)");
  OverrideSet ok(std::vector<whirl::io::KeyOverride>{{"Other", "2"}});
  ok.applyTo(g);
  EXPECT_NO_THROW(ok.requireAllUsed());
  EXPECT_DOUBLE_EQ(g.getDouble("Other"), 2.0);
}

TEST(OpenFastInput, ReadsTheNrel5mwElastoDynFile) {
  const OpenFastFile f = OpenFastFile::read(whirl::test::nrel5mwDir() / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat");
  EXPECT_DOUBLE_EQ(f.getDouble("TowerHt"), 87.6);
  EXPECT_EQ(f.find("TowerHt")->line, 64);
  EXPECT_DOUBLE_EQ(f.getDouble("RotSpeed"), 10.0);
  EXPECT_EQ(f.find("RotSpeed")->line, 33);
  EXPECT_FALSE(f.getDoubleOrDefault("DT").has_value());
  // Keys after the first OutList block (which lists quoted and unquoted channels) are read again.
  EXPECT_EQ(f.getInt("BldNd_BladesOut"), 1);
  EXPECT_FALSE(f.has("BldPitch1"));
  EXPECT_EQ(f.getPath("TwrFile"),
            (whirl::test::nrel5mwDir() / "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat").lexically_normal());
}

}  // namespace
