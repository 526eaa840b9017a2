// `fem_beam` bodies in a case: bad input is one InputError naming the file, line, key and reason.
#include <gtest/gtest.h>

#include <string>

#include "tests/unit/case_file_test_util.hpp"

namespace whirl {
namespace {

const std::string kBase = R"(name: fe
gravity: 0
bodies:
  - name: pile
    type: fem_beam
    length: 10
    elements: 4
    uniform: {m: 100, EIy: 1e7, EIz: 1e7}
    dofs: [uy, uz, ry, rz]
    points: [{name: root, x: 0}, {name: top, x: 10}]
    clamped: [root]
    reduction: {type: craig_bampton, interface: [top], modes: 2}
)";

std::string errorOf(const std::string& text) {
  testing::TempCaseDir dir;
  const std::string path = dir.write("case.yaml", text);
  try {
    readCase(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  s.replace(s.find(from), from.size(), to);
  return s;
}

TEST(CaseFemBeam, ValidCaseReadsWithNamedDofs) {
  testing::TempCaseDir dir;
  const Model m = readCase(dir.write("case.yaml", kBase));
  ASSERT_EQ(m.ndof(), 6);  // top: uy, uz, ry, rz + 2 CB modes
  EXPECT_EQ(m.dofs[0].name, "pile top uy");
  EXPECT_EQ(m.dofs[5].name, "pile CB 2");
}

TEST(CaseFemBeam, BadInputNamesKeyAndReason) {
  {
    const std::string e = errorOf(replaced(kBase, "type: craig_bampton", "type: modal"));
    EXPECT_NE(e.find("case.yaml:12: bodies.pile.reduction.type: unknown reduction 'modal'"), std::string::npos) << e;
  }
  {
    const std::string e = errorOf(replaced(kBase, "clamped: [root]", "clamped: [base]"));
    EXPECT_NE(e.find("bodies.pile.clamped[0]: no point named 'base'"), std::string::npos) << e;
  }
  {
    const std::string e = errorOf(replaced(kBase, "dofs: [uy, uz, ry, rz]", "dofs: [ux, uy, uz, ry, rz]"));
    EXPECT_NE(e.find("DOF ux needs EA > 0"), std::string::npos) << e;
  }
  {
    const std::string e = errorOf(replaced(kBase, "dofs: [uy, uz, ry, rz]", "dofs: [uy, uz, ry, spin]"));
    EXPECT_NE(e.find("unknown DOF 'spin'"), std::string::npos) << e;
  }
  {
    const std::string e = errorOf(replaced(kBase, "type: craig_bampton", "type: guyan"));
    EXPECT_NE(e.find("bodies.pile.reduction.modes: modes only with craig_bampton"), std::string::npos) << e;
  }
}

}  // namespace
}  // namespace whirl
