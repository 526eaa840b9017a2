#include "src/io/openfast_support.hpp"

#include <utility>

#include "src/io/refusals.hpp"
#include "src/model/error.hpp"

namespace whirl::io {

std::vector<std::string> unsupported_options(const FstInput& fst) {
  Refusals r(fst.source);
  r.add_if(fst.CompElast == 2, "CompElast", "BeamDyn blades are not modelled, CompElast = 1 uses the ElastoDyn blade files");
  r.add_if(fst.CompElast != 1 && fst.CompElast != 2, "CompElast", "only ElastoDyn (CompElast = 1) is modelled");
  r.add_if(fst.CompSub != 0, "CompSub", "a flexible substructure is not modelled, the tower base is clamped");
  r.add_if(fst.MHK.value_or(0) != 0, "MHK", "marine turbines need buoyancy and added mass, not modelled");
  r.add_if(fst.NRotors.value_or(1) != 1, "NRotors", "only single-rotor turbines are modelled");
  return r.take();
}

std::vector<std::string> unsupported_options(const ElastoDynInput& ed) {
  Refusals r(ed.source);
  const ElastoDynDofs& d = ed.dof;
  // A teetering hub exists only on 2 blades: one reason, with the teeter named in it.
  r.add_if(ed.config.NumBl != 3, "NumBl",
           d.TeetDOF ? "only 3-bladed rotors are modelled, and no teetering hub: TeetDOF is on too"
                     : "only 3-bladed rotors are modelled");
  r.add_if(ed.Furling, "Furling", "rotor and tail furl are not modelled");
  r.add_if(d.PitchDOF.value_or(false), "PitchDOF", "blade pitch flexibility is not modelled");
  r.add_if(ed.YawFrctMod.value_or(0) != 0, "YawFrctMod", "yaw-bearing friction is not smooth and cannot be linearized");
  // One refusal for all platform DOFs, at the first one that is on: one reason, one clause.
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
               ": no hydrostatics or mooring, the tower base is clamped");
  r.add_if(ed.config.TwrRBHt.value_or(0.0) != 0.0, "TwrRBHt", "a rigid tower-base segment is not modelled");
  return r.take();
}

void require_supported(const ElastoDynInput& ed) { throw_if_any(unsupported_options(ed)); }

void require_supported(const OpenFastTurbine& turbine) {
  std::vector<std::string> issues = unsupported_options(turbine.fst);
  for (std::string& s : unsupported_options(turbine.elastodyn)) issues.push_back(std::move(s));
  throw_if_any(issues);
}

}  // namespace whirl::io
