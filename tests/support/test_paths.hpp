#pragma once
/// \file
/// Where this build's sources and `whirl` executable are. Every test file sees WHIRL_SOURCE_DIR and
/// WHIRL_BINARY as calls of these functions (tests/CMakeLists.txt); only tests/support/test_paths.cpp
/// is compiled with the absolute paths, so every other test object is the same in any clone or
/// worktree and ccache reuses it (CI builds in a fresh clone).

namespace whirl_test_paths {

/// The repository root of this build (no trailing slash).
const char* sourceDir();

/// The `whirl` executable of this build.
const char* whirlBinary();

}  // namespace whirl_test_paths
