#pragma once
// Helpers for the aerodynamic-input tests: the copied decks under tests/data/openfast/aero/ (an OpenFAST
// v3 toolbox deck in toolbox/, an OpenFAST v5 deck in v5/, the NREL 5MW blade and airfoil files both name
// as "../5MW_Baseline/…"), and a scratch copy of that tree to edit.
#include <filesystem>
#include <string>

#include "tests/unit/openfast_test_util.hpp"

namespace whirl::test {

inline std::filesystem::path aeroDir() { return openfastDataDir() / "aero"; }
inline std::filesystem::path airfoilDir() { return aeroDir() / "5MW_Baseline" / "Airfoils"; }
inline std::filesystem::path aeroBladeFile() {
  return aeroDir() / "5MW_Baseline" / "NRELOffshrBsline5MW_AeroDyn_blade.dat";
}

/// `message` with every occurrence of `file`'s path replaced by "<file>" (scratch paths differ per run).
inline std::string withFilePlaceholder(std::string message, const std::filesystem::path& file) {
  const std::string p = file.string();
  for (std::size_t at = message.find(p); at != std::string::npos; at = message.find(p, at + 6))
    message.replace(at, p.size(), "<file>");
  return message;
}

/// The whole aero tree copied into a scratch folder; edit a file (path relative to the tree), then read.
class AeroScratch {
 public:
  AeroScratch() {
    for (const auto& e : std::filesystem::recursive_directory_iterator(aeroDir()))
      if (e.is_regular_file()) dir_.copy(e.path(), std::filesystem::relative(e.path(), aeroDir()).string());
  }
  std::filesystem::path path(const std::string& rel) const { return dir_.path() / rel; }
  /// Replaces `from` by `to` (first occurrence) in file `rel`.
  void edit(const std::string& rel, const std::string& from, const std::string& to) const {
    dir_.write(rel, replaceOnce(readText(path(rel)), from, to));
  }
  /// Keeps the first `n` lines of file `rel`.
  void truncate(const std::string& rel, int n) const {
    const std::string text = readText(path(rel));
    std::size_t at = 0;
    for (int i = 0; i < n; ++i) at = text.find('\n', at) + 1;
    dir_.write(rel, text.substr(0, at));
  }
  void remove(const std::string& rel) const { std::filesystem::remove(path(rel)); }
  std::filesystem::path write(const std::string& rel, const std::string& text) const { return dir_.write(rel, text); }

 private:
  ScratchDir dir_;
};

}  // namespace whirl::test
