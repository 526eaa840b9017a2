#pragma once
// Helpers for the aerodynamic-input tests: the copied decks under tests/data/openfast/aero/ (an OpenFAST
// v3 toolbox deck in toolbox/, an OpenFAST v5 deck in v5/, the NREL 5MW blade and airfoil files both name
// as "../5MW_Baseline/…"), and a scratch copy of that tree to edit.
#include <filesystem>
#include <string>

#include "tests/unit/openfast_test_util.hpp"

namespace whirl::test {

inline std::filesystem::path aero_dir() { return openfast_data_dir() / "aero"; }
inline std::filesystem::path airfoil_dir() { return aero_dir() / "5MW_Baseline" / "Airfoils"; }
inline std::filesystem::path aero_blade_file() { return aero_dir() / "5MW_Baseline" / "NRELOffshrBsline5MW_AeroDyn_blade.dat"; }

/// `message` with every occurrence of `file`'s path replaced by "<file>" (scratch paths differ per run).
inline std::string with_file_placeholder(std::string message, const std::filesystem::path& file) {
  const std::string p = file.string();
  for (std::size_t at = message.find(p); at != std::string::npos; at = message.find(p, at + 6))
    message.replace(at, p.size(), "<file>");
  return message;
}

/// The whole aero tree copied into a scratch folder; edit a file (path relative to the tree), then read.
class AeroScratch {
 public:
  AeroScratch() {
    for (const auto& e : std::filesystem::recursive_directory_iterator(aero_dir()))
      if (e.is_regular_file()) dir_.copy(e.path(), std::filesystem::relative(e.path(), aero_dir()).string());
  }
  std::filesystem::path path(const std::string& rel) const { return dir_.path() / rel; }
  /// Replaces `from` by `to` (first occurrence) in file `rel`.
  void edit(const std::string& rel, const std::string& from, const std::string& to) const {
    dir_.write(rel, replace_once(read_text(path(rel)), from, to));
  }
  /// Keeps the first `n` lines of file `rel`.
  void truncate(const std::string& rel, int n) const {
    const std::string text = read_text(path(rel));
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
