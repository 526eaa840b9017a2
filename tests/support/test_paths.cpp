#include "tests/support/test_paths.hpp"

namespace whirl_test_paths {

const char* sourceDir() { return WHIRL_TEST_SOURCE_DIR; }

const char* whirlBinary() { return WHIRL_TEST_BINARY; }

}  // namespace whirl_test_paths
