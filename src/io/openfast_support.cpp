#include "src/io/openfast_support.hpp"

#include <string>
#include <utility>

#include "src/io/refusals.hpp"
#include "src/model/error.hpp"

namespace whirl::io {

std::vector<std::string> unsupported_options(const FstInput& fst) {
  Refusals r(fst.source);
  r.add_if(fst.CompElast == 2, "CompElast", "BeamDyn blades are not modelled, CompElast = 1 uses the ElastoDyn blade files");
  r.add_if(fst.CompElast != 1 && fst.CompElast != 2, "CompElast", "only ElastoDyn (CompElast = 1) is modelled");
  r.add_if(fst.CompSub == 2, "CompSub", "an external platform (ExtPtfm superelement) is not modelled",
           "CompSub = 0 or 1 (SubDyn)");
  r.add_if(fst.CompSub != 0 && fst.CompSub != 1 && fst.CompSub != 2, "CompSub", "unknown substructure module",
           "CompSub = 0 or 1 (SubDyn)");
  r.add_if(fst.MHK.value_or(0) != 0, "MHK", "marine turbines need buoyancy and added mass, not modelled");
  r.add_if(fst.NRotors.value_or(1) != 1, "NRotors", "only single-rotor turbines are modelled");
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
    if (first.empty())
      first = key;
    else
      others += (others.empty() ? "" : ", ") + std::string(key);
  }
  r.add_if(!first.empty(), first,
           "platform DOFs are not modelled" + (others.empty() ? std::string() : ", and " + others + " are on too") +
               ": no hydrostatics or mooring (CompHydro = 0, CompMooring = 0) holds the platform");
}

}  // namespace

bool has_platform_dofs(const ElastoDynInput& ed) {
  const ElastoDynDofs& d = ed.dof;
  return d.PtfmSgDOF || d.PtfmSwDOF || d.PtfmHvDOF || d.PtfmRDOF || d.PtfmPDOF || d.PtfmYDOF;
}

std::vector<std::string> unsupported_options(const ElastoDynInput& ed) {
  Refusals r(ed.source);
  const ElastoDynDofs& d = ed.dof;
  // A teetering hub exists only on 2 blades (ElastoDyn ignores TeetDOF for 3: a deck that sets it
  // expects a teeter it would not get).
  r.add_if(d.TeetDOF && ed.config.NumBl != 2, "TeetDOF", "a teetering hub needs a 2-bladed rotor (NumBl = " +
                                                             std::to_string(ed.config.NumBl) + "); set TeetDOF = False");
  r.add_if(d.TeetDOF && ed.config.NumBl == 2 && ed.teeter.TeetMod.value_or(0) == 2, "TeetMod",
           "a user-defined teeter spring/damper (routine UserTeet) is not modelled", "TeetMod = 0 or 1");
  r.add_if(ed.Furling, "Furling", "rotor and tail furl are not modelled");
  r.add_if(d.PitchDOF.value_or(false), "PitchDOF", "blade pitch flexibility is not modelled");
  r.add_if(ed.YawFrctMod.value_or(0) != 0, "YawFrctMod", "yaw-bearing friction is not smooth and cannot be linearized");
  r.add_if(ed.config.TwrRBHt.value_or(0.0) != 0.0, "TwrRBHt", "a rigid tower-base segment is not modelled");
  return r.take();
}

void require_supported(const ElastoDynInput& ed) {
  std::vector<std::string> issues = unsupported_options(ed);
  Refusals r(ed.source);
  refusePlatformWithoutSupport(ed, r);
  for (std::string& s : r.take()) issues.push_back(std::move(s));
  throw_if_any(issues);
}

void require_supported(const OpenFastTurbine& turbine) {
  std::vector<std::string> issues = unsupported_options(turbine.fst);
  for (std::string& s : unsupported_options(turbine.elastodyn)) issues.push_back(std::move(s));
  const FstInput& fst = turbine.fst;
  if (fst.CompSub == 1) {
    // A SubDyn substructure holds the platform. Its hydrodynamics (HydroDyn's strip-theory members on the
    // substructure's members) and a mooring on it are another model.
    Refusals r(fst.source);
    r.add_if(fst.CompHydro != 0, "CompHydro",
             "HydroDyn on a SubDyn substructure (strip-theory members: added mass and buoyancy of the "
             "substructure's members) is not modelled; --set CompHydro=0 leaves the hydrodynamics out");
    r.add_if(fst.CompMooring != 0, "CompMooring", "a mooring on a SubDyn substructure is not modelled",
             "CompMooring = 0");
    for (std::string& s : r.take()) issues.push_back(std::move(s));
  } else if (has_platform_dofs(turbine.elastodyn)) {
    Refusals r(fst.source);
    r.add_if(fst.CompMooring > 1, "CompMooring", "only MAP++ mooring files are read", "CompMooring = 0 or 1 (MAP++)");
    r.add_if(fst.CompHydro > 1, "CompHydro", "unknown hydrodynamics module", "CompHydro = 0 or 1 (HydroDyn)");
    for (std::string& s : r.take()) issues.push_back(std::move(s));
    if (fst.CompHydro == 0 && fst.CompMooring == 0) {
      Refusals p(turbine.elastodyn.source);
      refusePlatformWithoutSupport(turbine.elastodyn, p);
      for (std::string& s : p.take()) issues.push_back(std::move(s));
    }
  }
  throw_if_any(issues);
}

}  // namespace whirl::io
