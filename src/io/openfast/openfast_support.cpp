#include "src/io/openfast/openfast_support.hpp"

#include <string>
#include <utility>

#include "src/base/error.hpp"
#include "src/io/openfast/refusals.hpp"

namespace whirl::io {

std::vector<std::string> unsupportedOptions(const FstInput& fst) {
  Refusals r(fst.source);
  r.addIf(fst.CompElast != 1 && fst.CompElast != 2, "CompElast",
          "only ElastoDyn (CompElast = 1) and ElastoDyn with BeamDyn blades (2) are modelled");
  r.addIf(fst.CompSub == 2, "CompSub", "an external platform (ExtPtfm superelement) is not modelled",
          "CompSub = 0 or 1 (SubDyn)");
  r.addIf(fst.CompSub != 0 && fst.CompSub != 1 && fst.CompSub != 2, "CompSub", "unknown substructure module",
          "CompSub = 0 or 1 (SubDyn)");
  r.addIf(fst.MHK.value_or(0) != 0, "MHK", "marine turbines need buoyancy and added mass, not modelled");
  r.addIf(fst.NRotors.value_or(1) != 1, "NRotors", "only single-rotor turbines are modelled");
  return r.take();
}

namespace {

// One refusal for all platform DOFs, at the first one that is on: one reason, one clause. Floating
// platforms are modelled with HydroDyn and/or a MAP++ mooring; with neither, nothing holds them.
void refusePlatformWithoutSupport(const ElastoDynInput& ed, Refusals& r) {
  const ElastoDynDofs& d = ed.dof;
  const std::pair<bool, const char*> platform[] = {{d.PtfmSgDOF, "PtfmSgDOF"}, {d.PtfmSwDOF, "PtfmSwDOF"},
                                                   {d.PtfmHvDOF, "PtfmHvDOF"}, {d.PtfmRDOF, "PtfmRDOF"},
                                                   {d.PtfmPDOF, "PtfmPDOF"},   {d.PtfmYDOF, "PtfmYDOF"}};
  std::string first, others;
  for (const auto& [on, key] : platform) {
    if (!on) continue;
    if (first.empty()) first = key;
    else others += (others.empty() ? "" : ", ") + std::string(key);
  }
  r.addIf(!first.empty(), first,
          "platform DOFs are not modelled" + (others.empty() ? std::string() : ", and " + others + " are on too") +
              ": no hydrostatics or mooring (CompHydro = 0, CompMooring = 0) holds the platform");
}

}  // namespace

bool hasPlatformDofs(const ElastoDynInput& ed) {
  const ElastoDynDofs& d = ed.dof;
  return d.PtfmSgDOF || d.PtfmSwDOF || d.PtfmHvDOF || d.PtfmRDOF || d.PtfmPDOF || d.PtfmYDOF;
}

std::vector<std::string> unsupportedOptions(const ElastoDynInput& ed) {
  Refusals r(ed.source);
  const ElastoDynDofs& d = ed.dof;
  // A teetering hub exists only on 2 blades (ElastoDyn ignores TeetDOF for 3: a deck that sets it
  // expects a teeter it would not get).
  r.addIf(d.TeetDOF && ed.config.NumBl != 2, "TeetDOF",
          "a teetering hub needs a 2-bladed rotor (NumBl = " + std::to_string(ed.config.NumBl) +
              "); set TeetDOF = False");
  r.addIf(d.TeetDOF && ed.config.NumBl == 2 && ed.teeter.TeetMod.value_or(0) == 2, "TeetMod",
          "a user-defined teeter spring/damper (routine UserTeet) is not modelled", "TeetMod = 0 or 1");
  r.addIf(ed.Furling, "Furling", "rotor and tail furl are not modelled");
  r.addIf(d.PitchDOF.value_or(false), "PitchDOF", "blade pitch flexibility is not modelled");
  r.addIf(ed.YawFrctMod.value_or(0) != 0, "YawFrctMod", "yaw-bearing friction is not smooth and cannot be linearized");
  r.addIf(ed.config.TwrRBHt.value_or(0.0) != 0.0, "TwrRBHt", "a rigid tower-base segment is not modelled");
  return r.take();
}

void requireSupported(const ElastoDynInput& ed) {
  std::vector<std::string> issues = unsupportedOptions(ed);
  Refusals r(ed.source);
  refusePlatformWithoutSupport(ed, r);
  for (std::string& s : r.take()) issues.push_back(std::move(s));
  throwIfAny(issues);
}

void requireSupported(const OpenFastTurbine& turbine) {
  std::vector<std::string> issues = unsupportedOptions(turbine.fst);
  for (std::string& s : unsupportedOptions(turbine.elastodyn)) issues.push_back(std::move(s));
  const FstInput& fst = turbine.fst;
  if (fst.CompSub == 1) {
    // A SubDyn substructure holds the platform; HydroDyn's strip theory acts on its members
    // (src/turbine/hydrodyn_strip.hpp). A mooring on it is another model.
    Refusals r(fst.source);
    r.addIf(fst.CompHydro > 1, "CompHydro", "unknown hydrodynamics module", "CompHydro = 0 or 1 (HydroDyn)");
    r.addIf(fst.CompMooring != 0, "CompMooring", "a mooring on a SubDyn substructure is not modelled",
            "CompMooring = 0");
    for (std::string& s : r.take()) issues.push_back(std::move(s));
  } else if (hasPlatformDofs(turbine.elastodyn)) {
    Refusals r(fst.source);
    r.addIf(fst.CompMooring == 2 || fst.CompMooring > 3, "CompMooring",
            "only MAP++ and MoorDyn mooring files are read: a MAP++ or MoorDyn file of the same lines runs with "
            "--set CompMooring=1 (or 3) --set MooringFile=FILE",
            "CompMooring = 0, 1 (MAP++) or 3 (MoorDyn)");
    r.addIf(fst.CompHydro > 1, "CompHydro", "unknown hydrodynamics module", "CompHydro = 0 or 1 (HydroDyn)");
    for (std::string& s : r.take()) issues.push_back(std::move(s));
    if (fst.CompHydro == 0 && fst.CompMooring == 0) {
      Refusals p(turbine.elastodyn.source);
      refusePlatformWithoutSupport(turbine.elastodyn, p);
      for (std::string& s : p.take()) issues.push_back(std::move(s));
    }
  }
  throwIfAny(issues);
}

}  // namespace whirl::io
