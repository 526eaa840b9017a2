// The one fuzzing executable's entry points: every harness (fuzz/*.cpp) registers itself by name
// (fuzz_support.hpp, RegisterHarness), each harness name is a link to this executable
// (fuzz/CMakeLists.txt), and the name it is run under picks the harness — one link of the sanitized
// library instead of one per harness.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "fuzz/fuzz_support.hpp"

namespace {

whirl::fuzz::HarnessEntry g_harness = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string name = *argc > 0 ? std::filesystem::path((*argv)[0]).filename().string() : "";
  const auto& all = whirl::fuzz::harnesses();
  const auto it = all.find(name);
  if (it == all.end()) {
    std::fprintf(stderr, "whirl_fuzz: run as one of the harnesses (a link of that name to whirl_fuzz):");
    for (const auto& [n, entry] : all) std::fprintf(stderr, " %s", n.c_str());
    std::fprintf(stderr, "\n");
    std::exit(2);
  }
  g_harness = it->second;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return g_harness(data, size); }
