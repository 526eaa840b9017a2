#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "linearize/linearize.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/text/csv.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct LinearizeOptions {
  ModelOptions model;
  std::string out;
};

// [q; q̇; z]: the coordinates, their rates, the first-order states (HydroDyn radiation, unsteady airfoils).
std::vector<std::string> stateNames(const LinearModel& lin) {
  std::vector<std::string> s = lin.dof_names;
  for (const auto& d : lin.dof_names) s.push_back("d(" + d + ")/dt");
  s.insert(s.end(), lin.first_order_names.begin(), lin.first_order_names.end());
  return s;
}

nlohmann::json namedValues(const Model& m, const VecX& v) {
  nlohmann::json j = nlohmann::json::object();
  for (int i = 0; i < m.ndof(); ++i) j[m.dofs[i].name] = v(i);
  return j;
}

void run(const LinearizeOptions& opt) {
  const Model m = loadModel(opt.model, true);
  const OperatingPoint op = solveOperatingPoint(m, startPoint(m, opt.model));
  const std::vector<std::string> problems = checkSolvedPoints(opt.model, m, {op});
  const LinearModel lin = linearize(m, op);  // with the deck's UA states (unless --quasi-steady-aero)
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);
  OutputSet files(dir);  // the seven files appear together, or none
  const auto states = stateNames(lin);
  files.write("M.csv", matrixCsv(lin.M, "dof", lin.dof_names, lin.dof_names));
  files.write("C.csv", matrixCsv(lin.C, "dof", lin.dof_names, lin.dof_names));
  files.write("K.csv", matrixCsv(lin.K, "dof", lin.dof_names, lin.dof_names));
  files.write("Q.csv", matrixCsv(lin.Q, "dof", lin.dof_names, lin.input_names));
  files.write("A.csv", matrixCsv(lin.A, "state", states, states));
  files.write("B.csv", matrixCsv(lin.B, "state", states, lin.input_names));
  nlohmann::json j;
  j["case"] = opt.model.case_path;
  j["model"] = m.name;
  j["dofs"] = lin.dof_names;
  j["states"] = states;
  j["inputs"] = lin.input_names;
  j["frozen_dofs"] = nlohmann::json::array();
  for (const auto& d : m.dofs)
    if (d.frozen) j["frozen_dofs"].push_back(d.name);
  j["operating_point"]["q"] = namedValues(m, op.q);
  j["operating_point"]["qd"] = namedValues(m, op.qd);
  j["operating_point"]["u"] = nlohmann::json::object();
  for (int i = 0; i < m.ninput(); ++i) j["operating_point"]["u"][m.inputs[i].name] = op.u(i);
  j["operating_point"]["first_order"] = nlohmann::json::object();
  for (size_t k = 0; k < lin.first_order_names.size(); ++k)
    j["operating_point"]["first_order"][lin.first_order_names[k]] = lin.first_order_values(
        static_cast<Eigen::Index>(k));
  j["equilibrium"]["solved_dofs"] = nlohmann::json::array();
  for (int i : op.solved) j["equilibrium"]["solved_dofs"].push_back(m.dofs[i].name);
  j["equilibrium"]["held_dofs"] = nlohmann::json::array();  // unrestrained: held at their value
  for (int i : op.held) j["equilibrium"]["held_dofs"].push_back(m.dofs[i].name);
  j["equilibrium"]["iterations"] = op.iterations;
  j["equilibrium"]["residual_norm"] = op.residual_norm;
  j["equilibrium"]["max_abs_residual_active"] = op.residual_max_active;
  j["equilibrium"]["max_abs_residual_dof"] = op.residual_max_dof;
  j["validity"] = {{"valid", problems.empty()}, {"problems", problems}};
  j["residual"] = nlohmann::json::object();
  for (size_t k = 0; k < lin.dof_names.size(); ++k) j["residual"][lin.dof_names[k]] = lin.residual(k);
  j["files"] = {"M.csv", "C.csv", "K.csv", "Q.csv", "A.csv", "B.csv"};
  files.write("linearization.json", j.dump(2) + "\n");
  files.commit();
  std::printf(
      "wrote %s/{M,C,K,Q,A,B}.csv and linearization.json (%d DOFs, %d inputs; equilibrium in %d "
      "iterations, residual %.3g)\n",
      dir.c_str(), static_cast<int>(lin.dofs.size()), m.ninput(), op.iterations, op.residual_norm);
}

}  // namespace

void addLinearizeCommand(CLI::App& app) {
  auto opt = std::make_shared<LinearizeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "linearize", "solve the operating point and write M, C, K, Q, A, B (CSV) and linearization.json");
  addModelOptions(*cmd, opt->model);
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  addAeroStateOptions(*cmd, opt->model);
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
