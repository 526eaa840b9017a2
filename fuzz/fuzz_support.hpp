#pragma once
/// \file
/// What the libFuzzer harnesses share: a private sandbox folder holding the files a fuzzed input may
/// reference (the NREL 5MW OpenFAST files, the YAML cases' property tables), writing the input there
/// as a file (the readers take paths, as the CLI does), and the rule of what counts as a finding.
///
/// Expected outcomes of any input: success, InputError or ComputeError (the CLI prints their
/// one-line message and exits 1), and CLI::ParseError for the harnesses that drive a CLI command.
/// Anything else is a finding: a crash or sanitizer report (libFuzzer stops by itself), a hang
/// (-timeout), and any other exception type (std::out_of_range, std::invalid_argument from stod,
/// YAML::Exception, std::bad_alloc, ...), which would reach the user as a message without
/// file, line and key: the harness aborts so that libFuzzer saves the reproducer.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <typeinfo>
#include <vector>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "src/base/error.hpp"
#include "src/model/model.hpp"

namespace whirl::fuzz {

namespace fs = std::filesystem;

/// One harness of the fuzzing executable (fuzz/CMakeLists.txt builds one, `whirl_fuzz`, with every
/// harness; each harness name is a link to it, and the name it runs under picks the harness:
/// fuzz_main.cpp). What libFuzzer's LLVMFuzzerTestOneInput would be in a one-harness executable.
using HarnessEntry = int (*)(const uint8_t* data, size_t size);

/// Every harness linked in, by name.
inline std::map<std::string, HarnessEntry>& harnesses() {
  static std::map<std::string, HarnessEntry> all;
  return all;
}

/// A file-scope `static const RegisterHarness h("fuzz_name", entry);` adds a harness.
struct RegisterHarness {
  RegisterHarness(const char* name, HarnessEntry entry) { harnesses()[name] = entry; }
};

/// This process' sandbox: <tmp>/whirl-fuzz-XXXXXX/run with copies of the auxiliary files (cases/nrel5mw
/// with its aero files, the property and aero tables of the YAML cases, the ElastoDyn files the test
/// .fst files name), and
/// <tmp>/whirl-fuzz-XXXXXX/5MW_Baseline for the test files that reference "../5MW_Baseline/...".
/// Created on first use, removed at exit.
inline const fs::path& sandbox() {
  static const fs::path dir = [] {
    std::string tmpl = (fs::temp_directory_path() / "whirl-fuzz-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) {
      std::perror("whirl fuzz: mkdtemp");
      std::abort();
    }
    const fs::path root(tmpl), run = root / "run", base = root / "5MW_Baseline";
    fs::create_directories(run);
    fs::create_directories(base);
    const fs::path src(WHIRL_SOURCE_DIR);
    // With its aero/ and 5MW_Baseline/ folders (AeroDyn, InflowWind, ServoDyn, blade, airfoils).
    fs::copy(src / "cases/nrel5mw", run, fs::copy_options::recursive);
    for (const char* f : {"cases/nrel5mw_monopile/tower_properties.csv", "cases/rotating_blade/blade_properties.csv",
                          "cases/aero_rotor/blade_aero.csv", "tests/data/openfast/rotating-9rpm/ElastoDyn.dat",
                          "tests/data/openfast/ws03/ws03.0_ED.dat"})
      fs::copy_file(src / f, run / fs::path(f).filename());
    fs::copy(src / "cases/aero_rotor/airfoils", run / "airfoils", fs::copy_options::recursive);
    for (const auto& e : fs::directory_iterator(src / "tests/data/openfast/5MW_Baseline"))
      if (e.is_regular_file()) fs::copy_file(e.path(), base / e.path().filename());
    static const std::string remove_at_exit = root.string();
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(remove_at_exit, ec);
    });
    return run;
  }();
  return dir;
}

/// Writes the fuzzer's bytes as sandbox()/name and returns the path.
inline std::string writeInput(const std::string& name, const uint8_t* data, size_t size) {
  const fs::path p = sandbox() / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "whirl fuzz: cannot write %s\n", p.c_str());
    std::abort();
  }
  return p.string();
}

/// Runs f; returns normally on success or an expected error, aborts (a finding) on any other exception.
/// WHIRL_FUZZ_VERBOSE=1 prints the message of every expected error (to see how deep inputs get).
template <class F>
void expectOnlyInputErrors(F&& f) {
  static const bool verbose = std::getenv("WHIRL_FUZZ_VERBOSE") != nullptr;
  try {
    f();
  } catch (const InputError& e) {
    if (verbose) std::fprintf(stderr, "whirl fuzz: InputError: %s\n", e.what());
  } catch (const ComputeError& e) {
    if (verbose) std::fprintf(stderr, "whirl fuzz: ComputeError: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "whirl fuzz: FINDING: unexpected exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "whirl fuzz: FINDING: unexpected non-std exception\n");
    std::abort();
  }
}

/// The step after a successful read, as `whirl modes` / `whirl linearize` do: equilibrium from the
/// initial point (a few Newton iterations: the point is the parser, not convergence) and one
/// linearization, for models small enough to keep the harness fast. Models without an active
/// coordinate are skipped: linearize() crashes on them today (known, fixed on branch `sec`).
inline void solveAndLinearize(const Model& m, int max_dofs = 40) {
  if (m.ndof() > max_dofs || m.activeDofs().empty()) return;
  EquilibriumOptions eo;
  eo.max_iterations = 4;
  OperatingPoint op;
  try {
    op = solveOperatingPoint(m, initialPoint(m), eo);
  } catch (const ComputeError&) {
    op = initialPoint(m);  // not converged in 4 iterations: linearize where we are
  }
  (void)linearize(m, op);
}

}  // namespace whirl::fuzz
