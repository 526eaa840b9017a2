#include "src/io/openfast/offshore/hydrodyn_input.hpp"

#include <cmath>
#include <sstream>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_lines.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/refusals.hpp"

namespace whirl::io {
namespace {

// The first n numbers of a line; nullopt when it has fewer or one of them is not a finite number.
std::optional<std::vector<double>> leadingNumbers(const std::string& line, int n) {
  std::istringstream ss(line);
  std::vector<double> v;
  for (std::string tok; static_cast<int>(v.size()) < n && ss >> tok;) {
    const std::optional<double> x = parseFortranDouble(tok);
    if (!x || !std::isfinite(*x)) return std::nullopt;
    v.push_back(*x);
  }
  if (static_cast<int>(v.size()) < n) return std::nullopt;
  return v;
}

// A 6×6 matrix written as the key's line (row 1, value before the key) and the 5 lines below it.
Mat6 matrixAt(const OpenFastFile& f, const OpenFastLines& lines, const char* key) {
  const OpenFastEntry* e = f.find(key);
  if (!e) throw InputError(f.where(key, "key not found in this file"));
  Mat6 M;
  const std::vector<double> first = f.getDoubles(key);
  if (first.size() != 6) throw InputError(f.where(key, "expected 6 numbers on the first row of the 6×6 matrix"));
  for (int c = 0; c < 6; ++c) M(0, c) = first[c];
  for (int r = 1; r < 6; ++r) {
    const int line = e->line + r;  // 1-based
    const std::optional<std::vector<double>> row = leadingNumbers(lines.line(line), 6);
    if (!row)
      throw InputError(f.where(key, "row " + std::to_string(r + 1) + " of the 6×6 matrix (line " +
                                        std::to_string(line) + ") is not 6 numbers"));
    for (int c = 0; c < 6; ++c) M(r, c) = (*row)[c];
  }
  return M;
}

// AddF0: six numbers on the key's line (HydroDyn v2, FAST v8) or a column, one number per line from the
// key's line down (OpenFAST v3+, HydroDyn_Input.f90, HydroDyn_ParseInput: one ParseAry of NBody numbers
// per row).
Vec6 preload(const OpenFastFile& f, const OpenFastLines& lines) {
  const OpenFastEntry* e = f.find("AddF0");
  if (!e) throw InputError(f.where("AddF0", "key not found in this file"));
  const std::vector<double> first = f.getDoubles("AddF0");
  Vec6 f0;
  if (first.size() == 6) {
    for (int k = 0; k < 6; ++k) f0(k) = first[static_cast<std::size_t>(k)];
    return f0;
  }
  if (first.size() != 1)
    throw InputError(f.where("AddF0", "expected 6 numbers on the line, or one per line on 6 lines (is " +
                                          std::to_string(first.size()) + " numbers)"));
  f0(0) = first.front();
  for (int r = 1; r < 6; ++r) {
    const int line = e->line + r;
    const std::optional<std::vector<double>> row = leadingNumbers(lines.line(line), 1);
    if (!row)
      throw InputError(f.where("AddF0", "row " + std::to_string(r + 1) + " of the 6 preloads (line " +
                                            std::to_string(line) + ") is not a number"));
    f0(r) = row->front();
  }
  return f0;
}

}  // namespace

HydroDynInput readHydroDyn(const std::filesystem::path& file, OverrideSet* overrides) {
  const OpenFastLines lines = OpenFastLines::read(file);  // the file opened once: keys and tables
  HydroDynInput h;
  h.source = OpenFastFile::parse(lines.text(), file);
  h.source.checkLayout(hydroDynLayout());
  if (overrides) overrides->applyTo(h.source);
  const OpenFastFile& f = h.source;
  h.geometry = readHydroDynMembers(f, lines);
  // `default` is the .fst's value (HydroDyn_Input.f90 of OpenFAST v3, HydroDyn_ParseInput:
  // ParseVarWDefault 'WtrDens' with defWtrDens, the glue code's): nullopt here, the .fst's value later.
  h.WtrDens = f.isDefault("WtrDens") ? std::nullopt : f.findDouble("WtrDens");
  h.WtrDpth = f.isDefault("WtrDpth") ? std::nullopt : f.findDouble("WtrDpth");
  if (h.WtrDens) requirePositive(f, "WtrDens", *h.WtrDens);
  if (h.WtrDpth) requirePositive(f, "WtrDpth", *h.WtrDpth);
  h.PotMod = f.getInt("PotMod");
  h.NBody = f.findInt("NBody");
  Refusals r(f);
  r.addIf(h.PotMod == 2, "PotMod", "fluid-impulse theory (FIT) is not modelled", "PotMod = 0 or 1 (WAMIT)");
  r.addIf(h.PotMod != 0 && h.PotMod != 1 && h.PotMod != 2, "PotMod", "unknown potential-flow model", "PotMod = 0 or 1");
  r.addIf(h.NBody.value_or(1) != 1, "NBody", "several potential-flow bodies are not modelled", "NBody = 1");
  if (h.PotMod == 1) {
    h.PotFile = f.has("PotFile") ? f.getPath("PotFile") : f.getPath("PotFile(1)");
    h.WAMITULEN = f.getDouble("WAMITULEN");
    requirePositive(f, "WAMITULEN", h.WAMITULEN);
    h.PtfmVol0 = f.getDouble("PtfmVol0");
    requireNonnegative(f, "PtfmVol0", h.PtfmVol0);
    h.PtfmCOBxt = f.getDouble("PtfmCOBxt");
    h.PtfmCOByt = f.getDouble("PtfmCOByt");
    h.RdtnMod = f.getInt("RdtnMod");
    r.addIf(h.RdtnMod == 1, "RdtnMod",
            "the radiation convolution has no linearization (OpenFAST refuses it too); --set RdtnMod=0 leaves "
            "the radiation memory out, keeping the infinite-frequency added mass",
            "RdtnMod = 0 or 2 (state space)");
    r.addIf(h.RdtnMod < 0 || h.RdtnMod > 2, "RdtnMod", "not a radiation model (0 none, 1 convolution, 2 state space)",
            "RdtnMod = 0 or 2");
    for (const char* key : {"PtfmRefxt", "PtfmRefyt", "PtfmRefzt", "PtfmRefztRot"})
      r.addIf(f.findDouble(key).value_or(0.0) != 0.0, key,
              "a WAMIT body away from the platform reference point is not modelled", "0");
  }
  for (const char* key : {"MnDrift", "NewmanApp", "DiffQTF", "SumQTF"})
    if (f.findInt(key).value_or(0) != 0)
      h.notes.push_back(f.where(key, "second-order wave forces ignored (no waves in a linearization)"));
  // WaveMod may carry a phase ("1P0.0"): any value but 0 means waves.
  if (const OpenFastEntry* e = f.find("WaveMod"); e && e->raw != "0")
    h.notes.push_back(f.where("WaveMod", "incident waves ignored: the linearization is about still water"));
  if (f.findInt("CurrMod").value_or(0) != 0)
    h.notes.push_back(f.where("CurrMod", "current ignored: the linearization is about still water"));
  // HydroDyn v2's force flags: False switches a platform direction's hydrodynamic loads off.
  for (const char* key : {"PtfmSgF", "PtfmSwF", "PtfmHvF", "PtfmRF", "PtfmPF", "PtfmYF"})
    if (const OpenFastEntry* e = f.find(key)) {
      const std::string v = toLower(e->raw);
      r.addIf(v != "true" && v != "t" && v != "default" && v != "\"default\"", key,
              "switching a direction's hydrodynamic loads off is not modelled", "True or DEFAULT");
    }
  throwIfAny(r.take());

  h.AddF0 = preload(f, lines);
  h.AddCLin = matrixAt(f, lines, "AddCLin");
  h.AddBLin = matrixAt(f, lines, "AddBLin");
  h.AddBQuad = matrixAt(f, lines, "AddBQuad");
  return h;
}

}  // namespace whirl::io
