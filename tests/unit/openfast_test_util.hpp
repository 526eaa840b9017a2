#pragma once
// Helpers for the OpenFAST reader tests: paths of the copied inputs, and scratch files written at test
// time into a fresh folder under std::filesystem::temp_directory_path().
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "src/base/error.hpp"

namespace whirl::test {

inline std::filesystem::path sourceDir() { return std::filesystem::path(WHIRL_SOURCE_DIR); }
inline std::filesystem::path nrel5mwDir() { return sourceDir() / "cases" / "nrel5mw"; }
inline std::filesystem::path openfastDataDir() { return sourceDir() / "tests" / "data" / "openfast"; }

inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A fresh folder per test (named after the test), removed when the object goes out of scope.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("whirl_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return dir_; }

  /// Writes `text` to `name` inside the folder and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path p = dir_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  /// Copies `from` into the folder under `name` (default: same file name).
  std::filesystem::path copy(const std::filesystem::path& from, const std::string& name = "") const {
    return write(name.empty() ? from.filename().string() : name, readText(from));
  }

 private:
  std::filesystem::path dir_;
};

/// Replaces the first occurrence of `from` in `text` (the test fails when it is absent).
inline std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' not found";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Removes the whole line that contains `fragment` (the test fails when it is absent).
inline std::string removeLine(std::string text, const std::string& fragment) {
  const std::size_t at = text.find(fragment);
  EXPECT_NE(at, std::string::npos) << "'" << fragment << "' not found";
  if (at == std::string::npos) return text;
  const std::size_t b = text.rfind('\n', at);
  const std::size_t e = text.find('\n', at);
  const std::size_t from = b == std::string::npos ? 0 : b + 1;
  text.erase(from, e == std::string::npos ? std::string::npos : e - from + 1);
  return text;
}

/// Runs `f`, expects an InputError, and returns its message ("" when nothing was thrown).
template <class F>
std::string inputErrorMessage(F&& f) {
  try {
    f();
  } catch (const whirl::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return "";
}

}  // namespace whirl::test
