// Counts read from input files are bounded (src/base/limits.hpp) with an error naming file, line and
// key, and allocation follows the data actually read (issue 14, item 4).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "src/io/case/case_file.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"
#include "src/io/openfast/elastodyn/elastodyn_tower.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "tests/unit/nrel5mw_scratch.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::test::inputErrorMessage;
using whirl::test::nrel5mwDir;
using whirl::test::readText;
using whirl::test::replaceOnce;
using whirl::test::ScratchDir;

using whirl::test::nrelEd;
using whirl::test::nrelWith;
using whirl::test::turbineError;
const char* kEd = whirl::test::kNrelEd;

// --- bounds -----------------------------------------------------------------------------------

TEST(InputLimits, ElastoDynNodeCountsAreBounded) {
  const std::string msg = turbineError(replaceOnce(nrelEd(), "         20   TwrNodes", "  100000000   TwrNodes"));
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":107: TwrNodes: at most 1000 nodes (is 100000000"));
}

TEST(InputLimits, FemBeamElementsAreBounded) {
  ScratchDir dir;
  const auto path = dir.write("fe.yaml", R"(name: fe
gravity: 0
bodies:
  - name: pile
    type: fem_beam
    length: 10
    elements: 1000000
    uniform: {m: 100, EIy: 1e7, EIz: 1e7}
    dofs: [uy, uz, ry, rz]
    points: [{name: root, x: 0}, {name: top, x: 10}]
    clamped: [root]
    reduction: {type: craig_bampton, interface: [top], modes: 2}
)");
  EXPECT_THAT(inputErrorMessage([&] { whirl::readCase(path.string()); }),
              HasSubstr("fe.yaml:7: bodies.pile.elements: must be between 1 and 500"));
}

// An unreduced FE body brings every free DOF as a coordinate, and its Ritz integrals are dense in them: 300
// elements with all six DOFs are 1800 coordinates (the fuzz finding had 671 elements: 3 GB). Refused at
// the body, before anything of that size is allocated; the same beam reduced reads.
TEST(InputLimits, UnreducedFemBodyCoordinatesAreBounded) {
  ScratchDir dir;
  const std::string text = R"(name: fe
gravity: 0
bodies:
  - name: pile
    type: fem_beam
    length: 10
    elements: 300
    uniform: {m: 100, EA: 1e9, EIy: 1e7, EIz: 1e7, GJ: 1e7, jG: 1}
    points: [{name: root, x: 0}, {name: top, x: 10}]
    clamped: [root]
)";
  const auto path = dir.write("fe.yaml", text);
  const std::string msg = inputErrorMessage([&] { whirl::readCase(path.string()); });
  EXPECT_THAT(msg, HasSubstr("fe.yaml:4: "));
  EXPECT_THAT(msg, HasSubstr("FE body 'pile': 1800 coordinates (every free DOF of the unreduced model), more than "
                             "1200 (src/base/limits.hpp): reduce it"));
  const auto reduced = dir.write("cb.yaml",
                                 text + "    reduction: {type: craig_bampton, interface: [top], modes: 4}\n");
  EXPECT_EQ(whirl::readCase(reduced.string()).ndof(), 10);
}

std::string lin(const std::string& name) {
  return readText(whirl::test::sourceDir() / "tests/data/openfast-lin/rotating-9rpm" / name);
}

TEST(InputLimits, LinHeaderCountsAreBoundedAndNamed) {
  ScratchDir dir;
  const auto p = dir.write("x.lin",
                           replaceOnce(lin("Main.1.lin"), "Number of inputs:", "Number of inputs: 2000000000 "));
  EXPECT_THAT(inputErrorMessage([&] { whirl::readOpenFastLin(p.string()); }),
              HasSubstr("Number of inputs: 2000000000 is above the limit of 100000"));
}

TEST(InputLimits, LinAllocationFollowsTheRowsRead) {
  // A header claiming 90000 states (under the bound) on a file with 20: the reader fails at the
  // first missing row instead of allocating for 90000 (and a 90000 × 90000 A, 65 GB).
  ScratchDir dir;
  std::string text = lin("Main.1.lin");
  const auto at = text.find("Number of continuous states:");
  ASSERT_NE(at, std::string::npos);
  const auto end = text.find('\n', at);
  text.replace(at, end - at, "Number of continuous states: 90000");
  const auto p = dir.write("x.lin", text);
  EXPECT_THAT(inputErrorMessage([&] { whirl::readOpenFastLin(p.string()); }),
              HasSubstr("continuous states: truncated: 20 rows where the header declares 90000"));
}

TEST(InputLimits, LinMatrixSizeOutOfIntRangeIsNamed) {
  ScratchDir dir;
  const auto p = dir.write("x.lin", replaceOnce(lin("Main.1.lin"), "\nA: 20 x", "\nA: 123456789012 x"));
  const std::string msg = inputErrorMessage([&] { whirl::readOpenFastLin(p.string()); });
  EXPECT_THAT(msg, HasSubstr("x.lin:"));
  EXPECT_THAT(msg, HasSubstr("A rows: '123456789012' is out of the integer range"));
}

}  // namespace

namespace {

std::string caseError(const std::string& yaml) {
  ScratchDir dir;
  const auto path = dir.write("c.yaml", yaml);
  return inputErrorMessage([&] { whirl::readCase(path.string()); });
}

TEST(InputLimits, ShapeModeNumbersAndReducedModesAreBounded) {
  const std::string topmass = readText(whirl::test::sourceDir() / "cases/tower_topmass/tower_topmass_eq32.yaml");
  EXPECT_THAT(caseError(replaceOnce(topmass, "type: clamped_topmass, mode: 4,", "type: clamped_topmass, mode: 1001,")),
              HasSubstr("c.yaml:17: bodies.tower.shapes.tower FA 4.mode: the mode number must be from 1 to 1000"));
  EXPECT_THAT(caseError(R"(name: fe
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
    reduction: {type: craig_bampton, interface: [top], modes: 1001}
)"),
              HasSubstr("c.yaml:12: bodies.pile.reduction.modes: must be between 0 and 1000"));
}

}  // namespace
