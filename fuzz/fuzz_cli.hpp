#pragma once
/// \file
/// Runs one whirl subcommand in-process, as src/cli/main.cpp does (CLI11 parse, the command's
/// callback), with its stdout sent to /dev/null. CLI::ParseError counts as an expected error.
#include <fcntl.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include "fuzz/fuzz_support.hpp"

namespace whirl::fuzz {

template <class Add>
void runCommand(Add add, std::vector<std::string> args) {
  static const bool quiet = [] {
    const int fd = open("/dev/null", O_WRONLY);
    return fd >= 0 && dup2(fd, STDOUT_FILENO) >= 0;
  }();
  (void)quiet;
  CLI::App app{"whirl"};
  app.require_subcommand(1);
  add(app);
  args.insert(args.begin(), "whirl");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  expectOnlyInputErrors([&] {
    try {
      app.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError&) {
    }
  });
}

}  // namespace whirl::fuzz
