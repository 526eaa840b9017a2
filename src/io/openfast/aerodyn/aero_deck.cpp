#include "src/io/openfast/aerodyn/aero_deck.hpp"

#include <algorithm>

#include "src/base/error.hpp"
#include "src/io/openfast/aerodyn/aero_deck14.hpp"
#include "src/io/openfast/aerodyn/aero_support.hpp"
#include "src/io/openfast/aerodyn/airfoil14_input.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/refusals.hpp"

namespace whirl::io {
namespace {

// `list_key`: the key of the names in the messages (AFNames, or FoilNm in AeroDyn v14).
template <class Read>
std::vector<AirfoilInput> readAirfoils(const AeroDynInput& ad, const char* list_key, Read read) {
  std::vector<AirfoilInput> out;
  const std::string file = ad.source.path().string();
  for (std::size_t i = 0; i < ad.AFNames.size(); ++i) {
    const std::filesystem::path& p = ad.AFNames[i];
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
      throw InputError(where(file, ad.AFNames_lines[i], indexedKey(list_key, static_cast<int>(i) + 1),
                             "file not found: " + p.string()));
    out.push_back(read(p));
  }
  return out;
}

void checkAirfoilIds(const AeroDynInput& ad, const AeroDynBladeInput& blade) {
  const int n = static_cast<int>(ad.AFNames.size());
  for (std::size_t r = 0; r < blade.BlAFID.size(); ++r)
    if (blade.BlAFID[r] > n)
      throw InputError(where(blade.source.path().string(), blade.row_lines[r], "BlAFID",
                             "is " + std::to_string(blade.BlAFID[r]) + ", beyond NumAFfiles = " + std::to_string(n) +
                                 " (" + ad.source.path().string() + ":" +
                                 std::to_string(ad.source.find("NumAFfiles")->line) + ")"));
}

}  // namespace

namespace {

/// AFTabMod = 3 interpolates an airfoil's tables on AeroDyn's input UserProp (AirfoilInfo.f90,
/// AFI_ComputeAirfoilCoefs2D), which is 0 unless a controller drives it (AeroDyn_IO.f90: the input
/// u%UserProp starts at 0, and ServoDyn sets it only with its flap control, CCmode/AfCmode, which whirl
/// does not model). At UserProp = 0 the interpolation is the table written with UserProp = 0, or the only
/// table: that one is kept. An airfoil with several tables and none at 0 is refused (interpolating two
/// tables' polars on different angle grids is not modelled).
void keepUserPropZero(const AeroDynInput& ad, std::vector<AirfoilInput>& airfoils) {
  for (std::size_t i = 0; i < airfoils.size(); ++i) {
    std::vector<AirfoilTable>& tabs = airfoils[i].tables;
    if (tabs.size() <= 1) continue;
    const auto zero = std::find_if(tabs.begin(), tabs.end(), [](const AirfoilTable& t) { return t.user_prop == 0.0; });
    if (zero == tabs.end())
      throw InputError(where(airfoils[i].path.string(), tabs.front().re_line, "UserProp",
                             "AFTabMod = 3 (" + ad.source.path().filename().string() +
                                 ") interpolates the tables at UserProp = 0, and none of this file's " +
                                 std::to_string(tabs.size()) +
                                 " tables has UserProp = 0: interpolating between "
                                 "tables is not modelled; add a table at UserProp = 0 or use AFTabMod = 1"));
    tabs = {*zero};
  }
}

}  // namespace

AeroDeckInput readAeroDeck(const FstInput& fst, OverrideSet* overrides) {
  throwIfAny(unsupportedAeroOptions(fst));
  const OpenFastFile& f = fst.source;
  const char* aero_key = f.has("AeroFile") || !f.has("ADFile") ? "AeroFile" : "ADFile";
  const std::filesystem::path aero_file = f.getExistingPath(aero_key);
  const std::filesystem::path inflow_file = f.getExistingPath("InflowFile");

  AeroDeckInput deck;
  std::optional<AeroDyn14Input> v14;
  if (fst.CompAero == 1) {
    if (!OpenFastFile::read(aero_file).has("StallMod")) {
      Refusals r(f);
      r.addIf(true, "CompAero",
              "AeroDisk (OpenFAST v4+): " + aero_file.filename().string() + " is not an AeroDyn v14 file (no StallMod)",
              kAeroModules);
      throwIfAny(r.take());
    }
    v14 = readAeroDyn14(aero_file, overrides);
    deck.aerodyn = aerodynFromV14(*v14);
    deck.notes = steadySubstitutes(*v14);
  } else {
    deck.aerodyn = readAeroDyn(aero_file, aerodynEnvironment(fst), overrides);
    requireSupported(deck.aerodyn);
    deck.notes = steadySubstitutes(deck.aerodyn);
  }
  deck.inflow = readInflowWind(inflow_file, overrides);
  requireSupported(deck.inflow);
  for (std::string& n : steadySubstitutes(deck.inflow)) deck.notes.push_back(std::move(n));

  const AeroDynInput& ad = deck.aerodyn;
  if (v14) {
    deck.blades.assign(3, bladeFromV14(*v14));  // one element table serves every blade
    deck.airfoils = readAirfoils(ad, "FoilNm",
                                 [&](const std::filesystem::path& p) { return readAirfoil14(p, v14->UseCm); });
    if (std::optional<std::string> note = multipleTables(*v14, deck.airfoils)) deck.notes.push_back(std::move(*note));
    if (v14->MultiTab == "RENUM") deck.reynolds = aero::ReynoldsInterp::Linear;
    return deck;
  }
  std::vector<std::filesystem::path> read;  // blades sharing a file read it once
  for (std::size_t k = 0; k < ad.ADBlFile.size(); ++k) {
    const std::filesystem::path p = ad.source.getExistingPath(indexedKey("ADBlFile", static_cast<int>(k) + 1));
    const auto same = std::find(read.begin(), read.end(), p);
    deck.blades.push_back(same != read.end() ? deck.blades[static_cast<std::size_t>(same - read.begin())]
                                             : readAeroDynBlade(p, overrides));
    read.push_back(p);
    checkAirfoilIds(ad, deck.blades.back());
  }
  deck.airfoils = readAirfoils(ad, "AFNames", [&](const std::filesystem::path& p) { return readAirfoil(p, ad.InCol); });
  if (ad.AFTabMod == 2) deck.reynolds = aero::ReynoldsInterp::Log;
  if (ad.AFTabMod == 3) keepUserPropZero(ad, deck.airfoils);
  return deck;
}

}  // namespace whirl::io
