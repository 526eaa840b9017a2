#include "src/cli/common.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "src/io/case_file.hpp"
#include "src/model/elastodyn_model.hpp"
#include "src/model/error.hpp"
#include "src/parallel/session.hpp"

namespace whirl::cli {

void addModelOptions(CLI::App& cmd, ModelOptions& opt, bool with_rpm) {
  cmd.add_option("CASE", opt.case_path, "case: YAML case file, OpenFAST .fst or ElastoDyn .dat")->required();
  cmd.add_option("--set", opt.sets,
                 "override KEY=VALUE (repeatable): a dotted path of the YAML case, or an OpenFAST key; "
                 "gravity=G for both");
  if (with_rpm) cmd.add_option("--rpm", opt.rpm, "rotor speed [rpm]: the rate of every DOF marked rotating");
}

OperatingCondition operatingCondition(const Model& m, const ModelOptions& opt) {
  OperatingCondition c = modelCondition(m);
  if (opt.rpm) {
    if (m.roles.azimuth.empty())
      throw InputError("--rpm: the model has no rotating DOF (mark the azimuth with `rotating: true`)");
    c.rotor_speed = rpmToRadPerSec(*opt.rpm);
  }
  return c;
}

OperatingPoint startPoint(const Model& m, const ModelOptions& opt) {
  return opt.rpm ? initialPoint(m, operatingCondition(m, opt)) : initialPoint(m);
}

bool isYamlCase(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

Model loadModel(const ModelOptions& opt) {
  Model m;
  if (isYamlCase(opt.case_path)) {
    std::vector<CaseOverride> overrides;
    for (const auto& s : opt.sets) overrides.push_back(parseOverride(s));
    m = readCase(opt.case_path, overrides);
  } else {
    m = readElastoDynModel(opt.case_path, opt.sets);
  }
  return m;
}

std::function<void(int, int)> sweepProgress(const std::string& command) {
  const auto start = std::chrono::steady_clock::now();
  auto printed = std::make_shared<bool>(false);
  return [=](int done, int total) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (s < 1.0 && !*printed) return;
    if (parallel::size() > 1)
      std::fprintf(stderr, "\r%s: %d/%d operating points on rank 0 of %d (%.1f s)", command.c_str(), done, total,
                   parallel::size(), s);
    else
      std::fprintf(stderr, "\r%s: %d/%d operating points (%.1f s)", command.c_str(), done, total, s);
    *printed = true;
    if (done == total) std::fprintf(stderr, "\n");
  };
}

std::string defaultOutputFolder(const std::string& case_path) {
  return (std::filesystem::path("reports") / std::filesystem::path(case_path).stem()).string();
}

}  // namespace whirl::cli
