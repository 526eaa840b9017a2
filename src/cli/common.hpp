#pragma once
/// \file
/// What the subcommands share: loading a model from a case path with overrides and a rotor speed,
/// and output folders.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "linearize/operating_point.hpp"
#include "src/model/model.hpp"
#include "src/model/operating_condition.hpp"
#include "src/model/rosco_controller.hpp"
#include "src/writers/campbell_output.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace whirl::cli {

/// Options every model-taking subcommand accepts.
struct ModelOptions {
  std::string case_path;
  std::vector<std::string> sets;  ///< "key=value"
  std::optional<double> rpm;
  bool allow_invalid_point = false;  ///< --allow-invalid-point: warn instead of stopping (point_validity.hpp)
  bool allow_outside_files = false;  ///< --allow-outside-files: a YAML case's `file:` may leave its folder
  bool unsteady_aero = false;        ///< --unsteady-aero: the deck's UA states asked for explicitly (refused without)
  bool quasi_steady_aero = false;    ///< --quasi-steady-aero: the deck's UA states left out of the linear models
};

/// Registers CASE, --set, --allow-invalid-point, --allow-outside-files and (when with_rpm) --rpm.
void addModelOptions(CLI::App& cmd, ModelOptions& opt, bool with_rpm = true);

/// --quasi-steady-aero and --unsteady-aero (exclusive) of the commands that build linear models: the
/// blade elements' unsteady-airfoil states are in them when the deck's AeroDyn asks for them (UA_Mod 4 or
/// 6), unless --quasi-steady-aero; --unsteady-aero insists on them (loadModel refuses a deck without).
void addAeroStateOptions(CLI::App& cmd, ModelOptions& opt);

/// `--azimuths N` of the commands that linearize a rotor over a revolution and average it in multiblade
/// coordinates: one help text and range (1–3600) for all of them.
CLI::Option* addMultibladeAzimuths(CLI::App& cmd, int& azimuths);
/// `--azimuths N` of the commands that trim: equilibria per point over one blade passage (1–360).
CLI::Option* addTrimAzimuths(CLI::App& cmd, int& azimuths);

/// Loads the case — a YAML case file (.yaml, .yml), or an OpenFAST .fst / ElastoDyn .dat — with
/// --set applied before the model is built. --rpm does not change the model: see operatingCondition.
/// The reader's notes go to stderr. With `linear_model` (the command builds linear models, which carry the
/// deck's unsteady-airfoil states: LinearizeOptions::unsteady_aero) and a model that has such states,
/// without the note that they are left out; with --quasi-steady-aero the model loses its UA data
/// (removeUnsteadyAirfoils) and the note stays.
/// \throws InputError "CASE: --unsteady-aero: the deck's AeroDyn has no unsteady-airfoil states to add …"
///   when --unsteady-aero is given and the model has no element with states.
Model loadModel(const ModelOptions& opt, bool linear_model = false);

/// "a, b,c" → {"a", "b", "c"}: a comma-separated list of names (--inputs, --outputs), blanks trimmed.
std::vector<std::string> splitList(const std::string& s);

/// Checks solved operating points against the model's range of validity (checkPointValidity).
/// Problems are printed on stderr as "whirl: warning: CASE: <where>: <problem>" and returned (for
/// the metadata of the outputs) when --allow-invalid-point is given; otherwise the first one is a
/// ComputeError "CASE: <where>: operating point outside the model's range of validity: …".
/// \param[in] where  the point, e.g. "" or "12 rpm"
std::vector<std::string> checkSolvedPoints(const ModelOptions& opt, const Model& model,
                                           const std::vector<OperatingPoint>& points, const std::string& where = "");

/// Runs a model command; a ComputeError (no equilibrium, singular matrix, …) is rethrown prefixed
/// with the case file it came from: "CASE: operating point did not converge …".
void runWithCaseSource(const std::string& case_path, const std::function<void()>& run);

/// True for a YAML case path (.yaml, .yml), false for OpenFAST / ElastoDyn files.
bool isYamlCase(const std::string& path);

/// The operating condition of a single-point command: the model's own (modelCondition), with the
/// rotor speed of --rpm when given (InputError "--rpm: the model has no rotating DOF …" when the
/// model has none).
OperatingCondition operatingCondition(const Model& model, const ModelOptions& opt);

/// Where a single-point command starts: the model's initial point, or, with --rpm, the model at
/// operatingCondition(model, opt).
OperatingPoint startPoint(const Model& model, const ModelOptions& opt);

/// Progress of a sweep for MapOptions::progress, on stderr: "<command>: 3/10 operating points (1.2 s)"
/// (under mpirun: rank 0's share, "on rank 0 of K"). Only when stderr is a terminal; sweeps shorter
/// than a second stay quiet; the clock starts when this is called.
std::function<void(int, int)> sweepProgress(const std::string& command);

/// The deck's ROSCO controller for a `--closed-loop` command (Model::deck_controller of the loaded deck).
/// \throws InputError "CASE: --closed-loop needs ROSCO's controller: …" when the deck names none.
RoscoController closedLoopController(const Model& m, const ModelOptions& opt);

/// reports/<case file stem>, the default output folder of a case.
std::string defaultOutputFolder(const std::string& case_path);

/// One `whirl: note:` line on stderr when lines of first-order states' roots (HydroDyn radiation) are
/// left out of the plot (campbellLineShown), naming one of them and the option that draws them.
void noteHiddenFirstOrderLines(const CampbellDiagram& d, const CampbellPlotOptions& plot);

}  // namespace whirl::cli
