#pragma once
// Runs the whirl executable and captures exit code, stdout and stderr.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace whirl::test {

struct Run {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// What a library's exception says (`std::bad_alloc`, nlohmann's `[json.exception.type_error.316]`,
/// yaml-cpp's `yaml-cpp: error at line …`, a `what()` quoted): never for a user's eyes. Every run of every CLI test
/// checks its messages (issue 48, item 5), so the bad-input suites check all of theirs.
inline void expectNoLibraryText(const std::string& err, const std::string& args) {
  for (const char* text : {"json.exception", "std::", "what()", "yaml-cpp", "YAML::"})
    if (err.find(text) != std::string::npos)
      ADD_FAILURE() << "'" << text << "' in the messages of whirl " << args << ":\n" << err;
}

/// Runs `whirl <args>` from `cwd` (default: the source tree), arguments already shell-quoted.
inline Run whirl(const std::string& args, const std::string& cwd = WHIRL_SOURCE_DIR) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() / ("whirl_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto out = dir / ("out" + std::to_string(counter));
  const auto err = dir / ("err" + std::to_string(counter++));
  const std::string cmd = "cd '" + cwd + "' && '" + std::string(WHIRL_BINARY) + "' " + args + " > '" + out.string() +
                          "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  expectNoLibraryText(r.err, args);
  return r;
}

inline std::filesystem::path freshDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("whirl_cli_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace whirl::test
