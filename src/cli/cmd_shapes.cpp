// `whirl shapes CASE`: the FE mode shapes of each flexible beam body from its distributed properties
// (src/fem/mode_shapes.hpp), their ElastoDyn polynomial fits and how the model's current shapes compare.
#include <CLI/CLI.hpp>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/case/case_file.hpp"
#include "src/io/text/csv.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct ShapesOptions {
  ModelOptions model;
  std::string format = "table";
  std::string out;
};

std::vector<fem::FlexibleBeam> loadBeams(const ModelOptions& opt) {
  std::vector<fem::FlexibleBeam> beams;
  if (isYamlCase(opt.case_path)) {
    // A case's rotor speed for the FE modes is the `rotor_speed_rpm` of its `shapes: {from: fem}`.
    if (opt.rpm)
      throw InputError(
          "--rpm: for a YAML case set the beam's FE rotor speed with "
          "--set bodies.<beam>.shapes.rotor_speed_rpm=R");
    std::vector<CaseOverride> overrides;
    for (const auto& s : opt.sets) overrides.push_back(parseOverride(s));
    readCase(opt.case_path, overrides, &beams, opt.allow_outside_files);
  } else {
    beams = readElastoDynFlexibleBeams(opt.case_path, opt.sets, opt.rpm);
  }
  if (beams.empty()) throw InputError(opt.case_path + ": no flexible beam body (type: beam) to compute shapes for");
  return beams;
}

const char* kCsvHeader =
    "body,shape,direction,mode,freq_hz,a2,a3,a4,a5,a6,fit_rms,fit_max_deviation,mac,max_deviation\n";

std::string csvRows(const std::vector<fem::ShapeComparison>& rows) {
  std::string s = kCsvHeader;
  for (const auto& r : rows) {
    s += csvField(r.body) + "," + csvField(r.shape) + "," + r.direction + "," + std::to_string(r.index) + "," +
         formatNumber(r.freq_hz);
    for (double a : r.fit.coeffs) s += "," + formatNumber(a);
    s += "," + formatNumber(r.fit.rms) + "," + formatNumber(r.fit.max_deviation) + "," + formatNumber(r.mac) + "," +
         formatNumber(r.max_deviation) + "\n";
  }
  return s;
}

nlohmann::json jsonRows(const std::vector<fem::ShapeComparison>& rows, const std::string& case_path) {
  nlohmann::json j;
  j["case"] = case_path;
  j["polynomial"] = "u(x/L) = a2 (x/L)^2 + ... + a6 (x/L)^6, sum a_k = 1 (ElastoDyn)";
  for (const auto& r : rows)
    j["shapes"].push_back({{"body", r.body},
                           {"shape", r.shape},
                           {"direction", std::string(1, r.direction)},
                           {"mode", r.index},
                           {"freq_hz", r.freq_hz},
                           {"coefficients", r.fit.coeffs},
                           {"fit_rms", r.fit.rms},
                           {"fit_max_deviation", r.fit.max_deviation},
                           {"mac", r.mac},
                           {"max_deviation", r.max_deviation}});
  return j;
}

std::string table(const std::vector<fem::ShapeComparison>& rows) {
  std::string s = fmt::format("{:<10} {:<12} {:>3} {:>10}  {:>9} {:>9} {:>9} {:>9} {:>9}  {:>8} {:>9} {:>8}\n", "body",
                              "shape", "dir", "FE Hz", "a2", "a3", "a4", "a5", "a6", "fit rms", "MAC", "max dev");
  for (const auto& r : rows) {
    s += fmt::format(
        "{:<10} {:<12} {:>3} {:>10.5f}  {:>9.4f} {:>9.4f} {:>9.4f} {:>9.4f} {:>9.4f}  {:>8.1e} {:>9.6f} {:>8.4f}\n",
        r.body, r.shape, std::string(1, r.direction) + std::to_string(r.index), r.freq_hz, r.fit.coeffs[0],
        r.fit.coeffs[1], r.fit.coeffs[2], r.fit.coeffs[3], r.fit.coeffs[4], r.fit.rms, r.mac, r.max_deviation);
  }
  s += "a2..a6: ElastoDyn mode-shape polynomial fitted to the FE mode; MAC, max dev: FE mode vs the model's shape\n";
  return s;
}

// The FE mode at its nodes, as a `table` shape file of cases/README.md.
std::string shapeCsv(const fem::BeamMode& m) {
  std::string s = "x,uy,uz,uy1,uz1,uy2,uz2\n";
  const ShapeTable& t = m.table;
  for (Eigen::Index i = 0; i < t.x.size(); ++i)
    s += formatNumber(t.x(i)) + "," + formatNumber(t.uy(i)) + "," + formatNumber(t.uz(i)) + "," +
         formatNumber(t.uy1(i)) + "," + formatNumber(t.uz1(i)) + "," + formatNumber(t.uy2(i)) + "," +
         formatNumber(t.uz2(i)) + "\n";
  return s;
}

std::string fileName(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

void run(const ShapesOptions& opt) {
  std::vector<fem::ShapeComparison> rows;
  for (const fem::FlexibleBeam& b : loadBeams(opt.model)) {
    std::vector<fem::ShapeComparison> r = fem::compareShapes(b);
    rows.insert(rows.end(), r.begin(), r.end());
  }
  if (opt.format == "csv") std::fputs(csvRows(rows).c_str(), stdout);
  else if (opt.format == "json") std::fputs((jsonRows(rows, opt.model.case_path).dump(2) + "\n").c_str(), stdout);
  else std::fputs(table(rows).c_str(), stdout);
  if (opt.out.empty()) return;
  prepareOutputFolder(opt.out);
  OutputSet files(opt.out);
  files.write("shapes.csv", csvRows(rows));
  files.write("shapes.json", jsonRows(rows, opt.model.case_path).dump(2) + "\n");
  for (const auto& r : rows) files.write("shape_" + fileName(r.body + " " + r.shape) + ".csv", shapeCsv(r.mode));
  files.commit();
  std::fprintf(stderr, "shapes: wrote %zu files to %s\n", files.paths().size(), opt.out.c_str());
}

}  // namespace

void addShapesCommand(CLI::App& app) {
  auto opt = std::make_shared<ShapesOptions>();
  CLI::App* cmd =
      app.add_subcommand("shapes",
                         "FE mode shapes of each flexible beam from its distributed properties: frequencies, ElastoDyn "
                         "polynomial fits (x^2..x^6), MAC and deviation against the model's current shapes");
  cmd->add_option("CASE", opt->model.case_path, "case: YAML case file, OpenFAST .fst or ElastoDyn .dat")->required();
  cmd->add_option("--set", opt->model.sets,
                  "override KEY=VALUE (repeatable): a dotted path of the YAML case, or an OpenFAST key; "
                  "gravity=G, shapes=fem|polynomial (OpenFAST: the model's current shapes)");
  cmd->add_option("--rpm", opt->model.rpm, "OpenFAST: rotor speed of the blade FE modes [rpm] (default RotSpeed)")
      ->check(CLI::Range(0.0, 1000.0));
  cmd->add_option("--format", opt->format, "table, csv or json")->check(CLI::IsMember({"table", "csv", "json"}));
  cmd->add_option("--out", opt->out,
                  "also write shapes.csv, shapes.json and one table per FE mode (x, uy, uz, slopes, curvatures) here");
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli
