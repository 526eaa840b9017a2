#pragma once
// The NREL 5MW case copied into a scratch folder with its ElastoDyn main file replaced, for tests of
// what the readers refuse in it.
#include <filesystem>
#include <string>

#include "src/io/openfast/openfast_turbine.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl::test {

inline const char* kNrelEd = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
inline const char* kNrelTower = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
inline const char* kNrelBlade = "NRELOffshrBsline5MW_Blade.dat";

/// The NREL 5MW case in `dir` with the ElastoDyn main file replaced by `ed`; returns the .fst.
inline std::filesystem::path nrelWith(const ScratchDir& dir, const std::string& ed) {
  dir.copy(nrel5mwDir() / kNrelTower);
  dir.copy(nrel5mwDir() / kNrelBlade);
  dir.write(kNrelEd, ed);
  return dir.copy(nrel5mwDir() / "Main_Onshore.fst");
}

/// The NREL 5MW ElastoDyn main file as text.
inline std::string nrelEd() { return readText(nrel5mwDir() / kNrelEd); }

/// The InputError message of reading the turbine whose ElastoDyn main file is `ed`.
inline std::string turbineError(const std::string& ed) {
  ScratchDir dir;
  const auto fst = nrelWith(dir, ed);
  return inputErrorMessage([&] { io::readOpenFastTurbine(fst); });
}

}  // namespace whirl::test
