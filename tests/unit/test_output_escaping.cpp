// Generated files stay what they are whatever the names in them, even names that bypassed the
// readers' checks (built through the C++ API): campbell.gp runs no command of a title (Gnuplot runs
// `!cmd` lines and `...` backquotes in double-quoted strings through a shell), campbell.dat keeps its
// blocks, a .lin keeps its table rows, CSV and JSON fields read back as written.
#include <gtest/gtest.h>
#include <matio.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "src/io/lin/openfast_lin.hpp"
#include "src/io/text/csv.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/state_space_files.hpp"
#include "test_util.hpp"

namespace whirl {
namespace {

namespace fs = std::filesystem;

// Each would run `touch` if it escaped its string: a newline ending the string and a `!` line, a
// carriage return, backquotes (command substitution in double-quoted Gnuplot strings), quotes of
// both kinds, a trailing backslash (continues a Gnuplot line, comments included).
const std::vector<std::string> kHostile = {"a\n!touch pwned_newline\n#",
                                           "b\r!touch pwned_cr\r#",
                                           "x`touch pwned_backquote`y",
                                           "it's \"quoted\" 'twice'",
                                           "ends with backslash\\",
                                           "c'\n!touch pwned_quote\n#'",
                                           "d, e; f # g @h"};

bool hasControlCharacter(const std::string& s) {
  for (char c : s)
    if (static_cast<unsigned char>(c) < 0x20 && c != '\n') return true;
  return false;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

/// A diagram whose title and every line name are hostile; one mode per line at two points.
CampbellDiagram hostileDiagram() {
  CampbellDiagram d;
  d.title = "Campbell diagram: a\n!touch pwned_title\n#`touch pwned_title_bq`";
  const int n = static_cast<int>(kHostile.size());
  for (int p = 0; p < 2; ++p) {
    CampbellPoint pt;
    pt.rpm = 5.0 * (p + 1);
    for (int k = 0; k < n; ++k) {
      pt.coordinates.push_back("q" + std::to_string(k));
      Mode m;
      m.freq_hz = 0.1 * (k + 1);
      m.damped_freq_hz = m.freq_hz;
      m.damping_ratio = 0.01;
      m.name = kHostile[k];
      m.shape = Eigen::VectorXcd::Unit(n, k);
      m.participation = Eigen::VectorXd::Unit(n, k);
      pt.modes.push_back(m);
    }
    d.points.push_back(pt);
  }
  for (int k = 0; k < n; ++k) d.lines.push_back({kHostile[k], {k, k}});
  return d;
}

/// The Gnuplot single-quoted literal of `s` as campbell.gp must write it: control characters
/// become spaces, a quote is doubled.
std::string gnuplotLiteral(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) q += ' ';
    else if (c == '\'') q += "''";
    else q += c;
  }
  return q + "'";
}

TEST(GnuplotEscaping, TitlesAreSingleQuotedLiteralsOnOneLine) {
  const auto d = hostileDiagram();
  const std::string gp = campbellGnuplotScript(d);
  EXPECT_NE(gp.find("\ntitle = " + gnuplotLiteral(d.title) + "\n"), std::string::npos) << gp;
  for (const auto& name : kHostile) {
    const std::string item = " title " + gnuplotLiteral(name);  // then ", \" or, last item, the end of the line
    const auto at = gp.find(item);
    ASSERT_NE(at, std::string::npos) << name;
    EXPECT_TRUE(gp.compare(at + item.size(), 4, ", \\\n") == 0 || gp[at + item.size()] == '\n') << name;
  }
  for (const auto& line : linesOf(gp)) {
    const auto first = line.find_first_not_of(' ');
    EXPECT_FALSE(first != std::string::npos && line[first] == '!') << "a shell line: " << line;
    EXPECT_FALSE(hasControlCharacter(line)) << line;
    // A comment must not continue onto the next line.
    if (first != std::string::npos && line[first] == '#') {
      EXPECT_NE(line.back(), '\\') << line;
    }
  }
}

TEST(GnuplotEscaping, DataFileKeepsItsBlocks) {
  // Every line of campbell.dat is blank, a comment or four numbers: no name starts a data line.
  for (const auto& line : linesOf(campbellGnuplotData(hostileDiagram()))) {
    if (line.empty() || line[0] == '#') {
      if (!line.empty()) {
        EXPECT_NE(line.back(), '\\') << line;
      }
      continue;
    }
    std::istringstream in(line);
    int numbers = 0;
    for (std::string t; in >> t; ++numbers) {
      char* end = nullptr;
      std::strtod(t.c_str(), &end);  // reads "nan" too (no wind speed)
      EXPECT_EQ(*end, '\0') << "not a data line: " << line;
    }
    EXPECT_EQ(numbers, 4) << line;
  }
}

TEST(GnuplotEscaping, GnuplotRunsNoCommandFromAHostileScript) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot is not installed";
  test::TempDir tmp;
  const std::string dir = (tmp.path / "out").string();
  CampbellPlotOptions opt;  // render: Gnuplot runs the script with `dir` as working directory
  const auto files = writeCampbell(hostileDiagram(), dir, opt);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("pwned"), std::string::npos) << "a title ran: " << e.path();
  for (const auto& e : fs::directory_iterator(fs::current_path()))
    EXPECT_EQ(e.path().filename().string().find("pwned"), std::string::npos) << "a title ran: " << e.path();
  EXPECT_EQ(files.size(), 6u) << "Gnuplot rendered both images";
  EXPECT_TRUE(fs::exists(fs::path(dir) / "campbell.png"));
}

TEST(CsvEscaping, HostileFieldsReadBack) {
  // RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
  for (const auto& name : kHostile) {
    const std::string line = csvField(name) + ",1";
    if (name.find_first_of("\n\r") != std::string::npos) {
      EXPECT_EQ(line.front(), '"') << name;  // one record spanning lines, as RFC 4180 allows
      continue;
    }
    const auto f = splitCsvLine(line);
    ASSERT_EQ(f.size(), 2u) << name;
    EXPECT_EQ(f[0], name);
  }
}

// The one CSV splitter of every reader (tables, schedules, references, tracking overrides): unquoted
// fields trimmed, quoted ones kept as written, a broken quote an error instead of a silently merged row.
TEST(CsvEscaping, SplitterTrimsUnquotedFieldsAndRefusesBrokenQuotes) {
  EXPECT_EQ(splitCsvLine(" a ,\t\"b, c\" , d\r"), (std::vector<std::string>{"a", "b, c", "d"}));
  EXPECT_EQ(splitCsvLine("\" x \",,"), (std::vector<std::string>{" x ", "", ""}));
  EXPECT_THROW(splitCsvLine("\"open,1"), CsvLineError);
  EXPECT_THROW(splitCsvLine("\"a\" b,1"), CsvLineError);
  for (const std::string name : {" lead", "trail ", "\tboth\t"}) {
    const auto f = splitCsvLine(csvField(name) + ",1");
    ASSERT_EQ(f.size(), 2u) << name;
    EXPECT_EQ(f[0], name);  // blanks at the ends survive because csvField quotes them
  }
}

TEST(JsonEscaping, HostileNamesReadBackAndStayOnOneLinePerValue) {
  const auto d = hostileDiagram();
  const std::string text = campbellModesJson(d);
  for (const auto& l : linesOf(text)) EXPECT_FALSE(hasControlCharacter(l)) << l;  // \n, \r written as escapes
  const auto j = nlohmann::json::parse(text);
  EXPECT_EQ(j["title"], d.title);
  for (std::size_t k = 0; k < kHostile.size(); ++k) EXPECT_EQ(j["lines"][k], kHostile[k]);
}

/// A 1-DOF model with hostile state, input and output names and units.
StateSpaceModel hostileStateSpace() {
  StateSpaceModel m;
  m.x = {{"q\nRotor Speed: 99", "m\n", 0.5, -1, -1, false}, {"d(q\nRotor Speed: 99)/dt", "m/s", 0.0, -1, 0, false}};
  m.u = {{"force\n!touch pwned_u", "N", 1.0, -1, -1, false}};
  m.y = {{"tip\r\x1b[2J", "m", 2.0, -1, -1, false}};
  m.xdot_op = VecX::Zero(2);
  m.A = MatX::Identity(2, 2);
  m.B = MatX::Ones(2, 1);
  m.C = MatX::Ones(1, 2);
  m.D = MatX::Ones(1, 1);
  return m;
}

TEST(LinEscaping, HostileNamesStayInTheirRows) {
  test::TempDir tmp;
  const std::string path = tmp.write("hostile.lin", linFileText(hostileStateSpace(), "title\nRotor Speed: 99"));
  const OpenFastLin lin = readOpenFastLin(path);
  EXPECT_EQ(lin.rotor_speed, 0.0) << "the title or a name faked a header line";
  ASSERT_EQ(lin.x.size(), 2u);
  ASSERT_EQ(lin.u.size(), 1u);
  ASSERT_EQ(lin.y.size(), 1u);
  EXPECT_EQ(lin.A, MatX::Identity(2, 2));
  for (const auto* t : {&lin.x, &lin.u, &lin.y})
    for (const auto& v : *t) EXPECT_FALSE(hasControlCharacter(v.description + "\n")) << v.description;
  EXPECT_NE(lin.u[0].description.find("force !touch pwned_u"), std::string::npos) << lin.u[0].description;
}

TEST(MatEscaping, NamesAreCharArraysWithoutControlCharacters) {
  test::TempDir tmp;
  StateSpaceExport e;
  e.source = "hostile.yaml";
  e.model_name = "model\n!touch pwned";
  ExportPoint p;
  p.model = hostileStateSpace();
  e.points.push_back(p);
  const std::string path = (tmp.path / "s.mat").string();
  writeStateSpaceMat(e, path);
  mat_t* mat = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  ASSERT_NE(mat, nullptr);
  for (const char* var : {"x_names", "u_names", "y_names"}) {
    matvar_t* v = Mat_VarRead(mat, var);
    ASSERT_NE(v, nullptr) << var;
    for (size_t i = 0; i < v->dims[0] * v->dims[1]; ++i) {
      const matvar_t* c = Mat_VarGetCell(v, static_cast<int>(i));
      const std::string s(static_cast<const char*>(c->data), c->nbytes);
      EXPECT_FALSE(hasControlCharacter(s) || s.find('\n') != std::string::npos) << var << ": " << s;
    }
    Mat_VarFree(v);
  }
  Mat_Close(mat);
}

// fuzz_writers, first input: a name with a byte that is not UTF-8 made nlohmann's dump() throw
// type_error.316 out of the JSON writers (the readers refuse such names; the writers are the
// backstop): the byte is written as U+FFFD and the file parses.
TEST(JsonEscaping, ByteThatIsNotUtf8BecomesReplacementCharacter) {
  const std::string replacement = "\xef\xbf\xbd";
  StateSpaceExport e;
  e.source = "bad\xff.yaml";
  e.model_name = "m";
  ExportPoint p;
  p.model = hostileStateSpace();
  p.model.u[0].name = "force\xff";
  e.points.push_back(p);
  std::string text;
  ASSERT_NO_THROW(text = stateSpaceJson(e));
  const auto j = nlohmann::json::parse(text);
  EXPECT_EQ(j["source"], "bad" + replacement + ".yaml");
  EXPECT_NE(text.find("force" + replacement), std::string::npos);

  CampbellDiagram d = hostileDiagram();
  d.title = "\xc3(";  // a lead byte without its continuation
  ASSERT_NO_THROW(text = campbellModesJson(d));
  EXPECT_EQ(nlohmann::json::parse(text)["title"], replacement + "(");
}

}  // namespace
}  // namespace whirl
