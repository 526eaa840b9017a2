#include "tests/support/test_paths.hpp"

namespace whirl::test {

const char* sourceDir() { return WHIRL_TEST_SOURCE_DIR; }

const char* whirlBinary() { return WHIRL_TEST_BINARY; }

}  // namespace whirl::test
