#pragma once
// Helpers for the case-file tests: a fresh temporary folder per test to write small cases into,
// and the message of the InputError a call throws.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "src/base/error.hpp"
#include "src/io/case/case_file.hpp"

namespace whirl::testing {

class TempCaseDir {
 public:
  TempCaseDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() /
          ("whirl_case_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~TempCaseDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  TempCaseDir(const TempCaseDir&) = delete;
  TempCaseDir& operator=(const TempCaseDir&) = delete;

  /// Writes `text` to `name` in the folder; returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = dir / name;
    std::ofstream(p) << text;
    return p.string();
  }

  std::filesystem::path dir;
};

/// The message of the InputError `f` throws; fails the test when it throws nothing else.
template <class F>
std::string inputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected InputError, nothing thrown";
  return "";
}

/// 1-based line of the first occurrence of `needle` in `text` (0 if absent).
inline int lineOf(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  if (pos == std::string::npos) return 0;
  int line = 1;
  for (size_t i = 0; i < pos; ++i) line += text[i] == '\n';
  return line;
}

/// `text` with the first `from` replaced by `to` (fails the test when `from` is absent).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << "'" << from << "' not in the case";
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

/// A small land-based turbine: beam tower, nacelle at its top, rotor on a revolute joint.
inline const std::string& smallTurbineCase() {
  static const std::string text = R"(name: small turbine
gravity: 9.81
inputs:
  - {name: thrust, value: 1.0e5}
bodies:
  - name: tower
    type: beam
    rotation: {y_deg: -90}
    length: 80
    uniform: {m: 5000, EIy: 1.0e11, EIz: 1.0e11}
    shapes:
      - {name: tower FA 1, type: one_minus_cos, direction: z}
    points:
      - {name: top, x: 80}
  - name: nacelle
    type: rigid
    parent: tower
    at: top
    rotation: {y_deg: 90}
    mass: 2.4e5
    inertia: [1.0e6, 2.0e6, 2.0e6]
    points:
      - {name: hub, position: [-5, 0, 2]}
  - name: rotor
    type: rigid
    parent: nacelle
    at: hub
    mass: 1.1e5
    inertia: [3.8e7, 1.9e7, 1.9e7]
    joint: {type: revolute, axis: [1, 0, 0], dof: azimuth}
dofs:
  azimuth: {rotating: true, rate_rpm: 12.1}
loads:
  - {type: point, body: nacelle, point: hub, force: [1, 0, 0], input: thrust}
)";
  return text;
}

}  // namespace whirl::testing
