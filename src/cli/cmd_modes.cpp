#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "linearize/linearize.hpp"
#include "modal/modes.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/csv.hpp"

namespace whirl::cli {
namespace {

struct ModesOptions {
  ModelOptions model;
  std::string format = "table";
};

void run(const ModesOptions& opt) {
  const Model m = loadModel(opt.model);
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const LinearModel lin = linearize(m, op);
  const std::vector<Mode> modes = computeModes(lin.M, lin.C, lin.K, lin.dof_names);
  if (opt.format == "csv") {
    std::string s = "index,name,freq_hz,damped_freq_hz,damping_ratio\n";
    for (size_t k = 0; k < modes.size(); ++k)
      s += std::to_string(k + 1) + "," + csvField(modes[k].name) + "," + formatNumber(modes[k].freq_hz) + "," +
           formatNumber(modes[k].damped_freq_hz) + "," + formatNumber(modes[k].damping_ratio) + "\n";
    std::cout << s;
  } else if (opt.format == "json") {
    nlohmann::json j;
    j["case"] = opt.model.case_path;
    j["dofs"] = lin.dof_names;
    j["modes"] = nlohmann::json::array();
    for (size_t k = 0; k < modes.size(); ++k) {
      nlohmann::json mj;
      mj["index"] = k + 1;
      mj["name"] = modes[k].name;
      mj["freq_hz"] = modes[k].freq_hz;
      mj["damped_freq_hz"] = modes[k].damped_freq_hz;
      mj["damping_ratio"] = modes[k].damping_ratio;
      mj["rigid_body"] = modes[k].rigid_body;
      mj["participation"] = nlohmann::json::object();
      for (size_t i = 0; i < lin.dof_names.size(); ++i) mj["participation"][lin.dof_names[i]] = modes[k].participation(i);
      j["modes"].push_back(mj);
    }
    std::cout << j.dump(2) << "\n";
  } else {
    std::printf("%5s  %-40s %12s %14s %13s\n", "index", "name", "freq [Hz]", "damped [Hz]", "damping [-]");
    for (size_t k = 0; k < modes.size(); ++k)
      std::printf("%5zu  %-40s %12.6f %14.6f %13.6f%s\n", k + 1, modes[k].name.c_str(), modes[k].freq_hz,
                  modes[k].damped_freq_hz,
                  std::abs(modes[k].damping_ratio) < 5e-7 ? 0.0 : modes[k].damping_ratio,  // no "-0.000000"
                  modes[k].rigid_body ? "  (rigid body)" : "");
  }
}

}  // namespace

void addModesCommand(CLI::App& app) {
  auto opt = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand("modes", "solve the operating point and print the modes");
  addModelOptions(*cmd, opt->model);
  cmd->add_option("--format", opt->format, "table, csv or json")->check(CLI::IsMember({"table", "csv", "json"}));
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli
