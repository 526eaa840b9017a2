// Inputs the fuzzers (fuzz/, README.md *Reliability*) found to crash, hang, leak an unexpected
// exception type or trip a sanitizer; each test failed before its fix (most of them only under
// -DWHIRL_SANITIZE=ON, where undefined behaviour stops the program).
#include <gtest/gtest.h>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "src/io/case_file.hpp"
#include "src/model/error.hpp"
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

}  // namespace
}  // namespace whirl
