#include "src/cli/common.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <numbers>

#include "src/io/case_file.hpp"
#include "src/model/error.hpp"

namespace whirl::cli {

void addModelOptions(CLI::App& cmd, ModelOptions& opt) {
  cmd.add_option("CASE", opt.case_path, "case file (YAML)")->required();
  cmd.add_option("--set", opt.sets, "override a scalar of the case, KEY=VALUE (repeatable)");
  cmd.add_option("--rpm", opt.rpm, "rotor speed [rpm]: the rate of every DOF marked rotating");
}

void setRotorSpeed(Model& m, double rpm) {
  bool any = false;
  for (auto& d : m.dofs)
    if (d.rotating) {
      d.rate = rpm * 2 * std::numbers::pi / 60;
      any = true;
    }
  if (!any) throw InputError("--rpm: the model has no rotating DOF (mark the azimuth with `rotating: true`)");
}

Model loadModel(const ModelOptions& opt) {
  std::vector<CaseOverride> overrides;
  for (const auto& s : opt.sets) overrides.push_back(parseOverride(s));
  Model m = readCase(opt.case_path, overrides);
  if (opt.rpm) setRotorSpeed(m, *opt.rpm);
  return m;
}

std::string defaultOutputFolder(const std::string& case_path) {
  return (std::filesystem::path("reports") / std::filesystem::path(case_path).stem()).string();
}

}  // namespace whirl::cli
