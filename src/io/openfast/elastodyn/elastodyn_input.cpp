#include "src/io/openfast/elastodyn/elastodyn_input.hpp"

#include <algorithm>

#include <cmath>
#include <utility>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// Keys of ElastoDyn files, all versions whirl reads (FAST 8 ElastoDyn v1.00 to OpenFAST v5), arrays written Name(k).
const OpenFastLayout& layout() {
  static const OpenFastLayout l{
      "ElastoDyn",
      {"Echo",       "Method",          "DT",           "Gravity",    "FlapDOF1",   "FlapDOF2",
       "EdgeDOF",    "PitchDOF",        "TeetDOF",      "DrTrDOF",    "GenDOF",     "YawDOF",
       "TwFADOF1",   "TwFADOF2",        "TwSSDOF1",     "TwSSDOF2",   "PtfmSgDOF",  "PtfmSwDOF",
       "PtfmHvDOF",  "PtfmRDOF",        "PtfmPDOF",     "PtfmYDOF",   "OoPDefl",    "IPDefl",
       "BlPitch(k)", "TeetDefl",        "Azimuth",      "RotSpeed",   "NacYaw",     "TTDspFA",
       "TTDspSS",    "PtfmSurge",       "PtfmSway",     "PtfmHeave",  "PtfmRoll",   "PtfmPitch",
       "PtfmYaw",    "NumBl",           "TipRad",       "HubRad",     "PreCone(k)", "HubCM",
       "UndSling",   "Delta3",          "AzimB1Up",     "OverHang",   "ShftGagL",   "ShftTilt",
       "NacCMxn",    "NacCMyn",         "NacCMzn",      "NcIMUxn",    "NcIMUyn",    "NcIMUzn",
       "Twr2Shft",   "TowerHt",         "TowerBsHt",    "TwrRBHt",    "TwrDraft",   "PtfmCMxt",
       "PtfmCMyt",   "PtfmCMzt",        "PtfmRefxt",    "PtfmRefyt",  "PtfmRefzt",  "PtfmRef",
       "TipMass(k)", "PBrIner(k)",      "BlPIner(k)",   "HubMass",    "HubIner",    "HubIner_Teeter",
       "GenIner",    "NacMass",         "NacYIner",     "YawBrMass",  "PtfmMass",   "PtfmRIner",
       "PtfmPIner",  "PtfmYIner",       "PtfmXYIner",   "PtfmYZIner", "PtfmXZIner", "BldNodes",
       "BldFile(k)", "TeetMod",         "TeetDmpP",     "TeetDmp",    "TeetCDmp",   "TeetSStP",
       "TeetHStP",   "TeetSSSp",        "TeetHSSp",     "YawFrctMod", "M_CSmax",    "M_CD",
       "sig_v",      "sig_v2",          "OmgCut",       "M_FCSmax",   "M_MCSmax",   "M_FCD",
       "M_MCD",      "GBoxEff",         "GBRatio",      "DTTorSpr",   "DTTorDmp",   "Furling",
       "FurlFile",   "TwrNodes",        "TwrFile",      "SumPrint",   "OutFile",    "TabDelim",
       "OutFmt",     "TStart",          "DecFact",      "NTwGages",   "TwrGagNd",   "NBlGages",
       "BldGagNd",   "BldNd_BladesOut", "BldNd_BlOutNd"},
      {},
      false};
  return l;
}

ElastoDynDofs readDofs(const OpenFastFile& f) {
  ElastoDynDofs d;
  d.FlapDOF1 = f.getBool("FlapDOF1");
  d.FlapDOF2 = f.getBool("FlapDOF2");
  d.EdgeDOF = f.getBool("EdgeDOF");
  d.PitchDOF = f.findBool("PitchDOF");
  d.TeetDOF = f.getBool("TeetDOF");
  d.DrTrDOF = f.getBool("DrTrDOF");
  d.GenDOF = f.getBool("GenDOF");
  d.YawDOF = f.getBool("YawDOF");
  d.TwFADOF1 = f.getBool("TwFADOF1");
  d.TwFADOF2 = f.getBool("TwFADOF2");
  d.TwSSDOF1 = f.getBool("TwSSDOF1");
  d.TwSSDOF2 = f.getBool("TwSSDOF2");
  d.PtfmSgDOF = f.getBool("PtfmSgDOF");
  d.PtfmSwDOF = f.getBool("PtfmSwDOF");
  d.PtfmHvDOF = f.getBool("PtfmHvDOF");
  d.PtfmRDOF = f.getBool("PtfmRDOF");
  d.PtfmPDOF = f.getBool("PtfmPDOF");
  d.PtfmYDOF = f.getBool("PtfmYDOF");
  return d;
}

ElastoDynInitialConditions readInitialConditions(const OpenFastFile& f) {
  ElastoDynInitialConditions c;
  c.OoPDefl = f.getDouble("OoPDefl");
  c.IPDefl = f.getDouble("IPDefl");
  c.BlPitch = getIndexed<3>(f, "BlPitch");
  c.TeetDefl = f.getDouble("TeetDefl");
  c.Azimuth = f.getDouble("Azimuth");
  c.RotSpeed = f.getDouble("RotSpeed");
  // ElastoDyn_IO.f90, ValidatePrimaryData: "RotSpeed must not be negative" (a rotor turning the other
  // way is MirrorRotor's business in OpenFAST v5).
  requireNonnegative(f, "RotSpeed", c.RotSpeed);
  c.NacYaw = f.getDouble("NacYaw");
  c.TTDspFA = f.getDouble("TTDspFA");
  c.TTDspSS = f.getDouble("TTDspSS");
  c.PtfmSurge = f.getDouble("PtfmSurge");
  c.PtfmSway = f.getDouble("PtfmSway");
  c.PtfmHeave = f.getDouble("PtfmHeave");
  c.PtfmRoll = f.getDouble("PtfmRoll");
  c.PtfmPitch = f.getDouble("PtfmPitch");
  c.PtfmYaw = f.getDouble("PtfmYaw");
  return c;
}

ElastoDynConfiguration readConfiguration(const OpenFastFile& f) {
  ElastoDynConfiguration c;
  c.NumBl = f.getInt("NumBl");
  if (c.NumBl < 1 || c.NumBl > 3)
    throw InputError(f.where("NumBl", "must be 1, 2 or 3 (is " + std::to_string(c.NumBl) + ")"));
  c.TipRad = f.getDouble("TipRad");
  c.HubRad = f.getDouble("HubRad");
  requireNonnegative(f, "HubRad", c.HubRad);
  if (!(c.TipRad > c.HubRad))
    throw InputError(
        f.where("TipRad", "must be larger than HubRad (" + numberText(c.TipRad) + " <= " + numberText(c.HubRad) + ")"));
  c.PreCone = getIndexed<3>(f, "PreCone");
  // ElastoDyn_IO.f90, ValidatePrimaryData: PreCone(K) "must be in the range (-pi/2, pi/2)".
  for (int k = 1; k <= c.NumBl; ++k)
    if (!(std::abs(c.PreCone[k - 1]) < 90.0))
      throw InputError(
          f.where(indexedKey("PreCone", k), "must be in (-90, 90) deg (is " + numberText(c.PreCone[k - 1]) + ")"));
  c.HubCM = f.getDouble("HubCM");
  c.UndSling = f.getDouble("UndSling");
  c.Delta3 = f.getDouble("Delta3");
  c.AzimB1Up = f.getDouble("AzimB1Up");
  c.OverHang = f.getDouble("OverHang");
  c.ShftGagL = f.getDouble("ShftGagL");
  c.ShftTilt = f.getDouble("ShftTilt");
  // ElastoDyn_IO.f90, ValidatePrimaryData: "ABS( ShftTilt ) > PiBy2" is an error.
  if (!(std::abs(c.ShftTilt) <= 90.0))
    throw InputError(f.where("ShftTilt", "must be in [-90, 90] deg (is " + numberText(c.ShftTilt) + ")"));
  c.NacCMxn = f.getDouble("NacCMxn");
  c.NacCMyn = f.getDouble("NacCMyn");
  c.NacCMzn = f.getDouble("NacCMzn");
  c.NcIMUxn = f.getDouble("NcIMUxn");
  c.NcIMUyn = f.getDouble("NcIMUyn");
  c.NcIMUzn = f.getDouble("NcIMUzn");
  c.Twr2Shft = f.getDouble("Twr2Shft");
  c.TowerHt = f.getDouble("TowerHt");
  c.TowerBsHt = f.findDouble("TowerBsHt");
  if (c.TowerBsHt && !(c.TowerHt > *c.TowerBsHt))
    throw InputError(f.where("TowerHt", "must be above TowerBsHt (" + numberText(c.TowerHt) +
                                            " <= " + numberText(*c.TowerBsHt) + ")"));
  c.PtfmCMxt = f.findDouble("PtfmCMxt");
  c.PtfmCMyt = f.findDouble("PtfmCMyt");
  c.PtfmCMzt = f.findDouble("PtfmCMzt");
  c.PtfmRefxt = f.findDouble("PtfmRefxt");
  c.PtfmRefyt = f.findDouble("PtfmRefyt");
  c.PtfmRefzt = f.findDouble("PtfmRefzt");
  c.TwrRBHt = f.findDouble("TwrRBHt");
  c.TwrDraft = f.findDouble("TwrDraft");
  c.PtfmRef = f.findDouble("PtfmRef");
  return c;
}

ElastoDynMassInertia readMass(const OpenFastFile& f) {
  ElastoDynMassInertia m;
  m.TipMass = getIndexed<3>(f, "TipMass");
  for (int k = 1; k <= 3; ++k) requireNonnegative(f, indexedKey("TipMass", k), m.TipMass[k - 1]);
  m.PBrIner = findIndexed<3>(f, "PBrIner");
  m.BlPIner = findIndexed<3>(f, "BlPIner");
  struct Scalar {
    const char* key;
    double* value;
  };
  const Scalar required[] = {{"HubMass", &m.HubMass},    {"HubIner", &m.HubIner},     {"GenIner", &m.GenIner},
                             {"NacMass", &m.NacMass},    {"NacYIner", &m.NacYIner},   {"YawBrMass", &m.YawBrMass},
                             {"PtfmMass", &m.PtfmMass},  {"PtfmRIner", &m.PtfmRIner}, {"PtfmPIner", &m.PtfmPIner},
                             {"PtfmYIner", &m.PtfmYIner}};
  for (const Scalar& s : required) {
    *s.value = f.getDouble(s.key);
    requireNonnegative(f, s.key, *s.value);
  }
  m.HubIner_Teeter = f.findDouble("HubIner_Teeter");
  if (m.HubIner_Teeter) requireNonnegative(f, "HubIner_Teeter", *m.HubIner_Teeter);
  m.PtfmXYIner = f.findDouble("PtfmXYIner");
  m.PtfmYZIner = f.findDouble("PtfmYZIner");
  m.PtfmXZIner = f.findDouble("PtfmXZIner");
  return m;
}

// The ROTOR-TEETER section: optional for 3 blades (ElastoDyn ignores it), required and checked as
// ElastoDyn's ValidatePrimaryData checks it for 2 blades (every version has all eight keys).
ElastoDynTeeter readTeeter(const OpenFastFile& f, int num_blades) {
  ElastoDynTeeter t;
  const bool two = num_blades == 2;
  auto need = [&](const char* key) {
    if (two && !f.has(key))
      throw InputError(f.where(key,
                               "key not found: a 2-bladed rotor (NumBl = 2) needs the ROTOR-TEETER section "
                               "(TeetMod, TeetDmpP, TeetDmp, TeetCDmp, TeetSStP, TeetHStP, TeetSSSp, TeetHSSp)"));
  };
  for (const char* key : {"TeetMod", "TeetDmpP", "TeetDmp", "TeetCDmp", "TeetSStP", "TeetHStP", "TeetSSSp", "TeetHSSp"})
    need(key);
  t.TeetMod = f.findInt("TeetMod");
  t.TeetDmpP = f.findDouble("TeetDmpP");
  t.TeetDmp = f.findDouble("TeetDmp");
  t.TeetCDmp = f.findDouble("TeetCDmp");
  t.TeetSStP = f.findDouble("TeetSStP");
  t.TeetHStP = f.findDouble("TeetHStP");
  t.TeetSSSp = f.findDouble("TeetSSSp");
  t.TeetHSSp = f.findDouble("TeetHSSp");
  if (!two) return t;
  if (*t.TeetMod < 0 || *t.TeetMod > 2)
    throw InputError(f.where("TeetMod", "must be 0 (none), 1 (standard) or 2 (user-defined) (is " +
                                            std::to_string(*t.TeetMod) + ")"));
  const std::pair<const char*, double> angles[] = {{"TeetDmpP", *t.TeetDmpP}, {"TeetSStP", *t.TeetSStP}};
  for (const auto& [key, value] : angles)
    if (!(value >= 0.0 && value <= 180.0))
      throw InputError(f.where(key, "must be in [0, 180] deg (is " + numberText(value) + ")"));
  if (!(*t.TeetHStP >= *t.TeetSStP && *t.TeetHStP <= 180.0))
    throw InputError(f.where("TeetHStP", "must be in [TeetSStP, 180] deg = [" + numberText(*t.TeetSStP) +
                                             ", 180] (is " + numberText(*t.TeetHStP) + ")"));
  for (const char* key : {"TeetDmp", "TeetCDmp", "TeetSSSp", "TeetHSSp"}) requireNonnegative(f, key, f.getDouble(key));
  if (*t.TeetCDmp != 0.0)  // ElastoDyn refuses it too ("TeetCDmp must be 0 in this version")
    throw InputError(f.where("TeetCDmp", "must be 0, as ElastoDyn requires (Coulomb teeter damping is not modelled)"));
  return t;
}

ElastoDynDrivetrain readDrivetrain(const OpenFastFile& f) {
  ElastoDynDrivetrain d;
  d.GBoxEff = f.getDouble("GBoxEff");
  if (!(d.GBoxEff > 0.0 && d.GBoxEff <= 100.0))
    throw InputError(f.where("GBoxEff", "must be in (0, 100] % (is " + numberText(d.GBoxEff) + ")"));
  d.GBRatio = f.getDouble("GBRatio");
  requirePositive(f, "GBRatio", d.GBRatio);
  d.DTTorSpr = f.getDouble("DTTorSpr");
  requireNonnegative(f, "DTTorSpr", d.DTTorSpr);
  d.DTTorDmp = f.getDouble("DTTorDmp");
  requireNonnegative(f, "DTTorDmp", d.DTTorDmp);
  return d;
}

}  // namespace

ElastoDynInput readElastoDyn(const std::filesystem::path& file, OverrideSet* overrides) {
  ElastoDynInput ed;
  ed.source = OpenFastFile::read(file);
  ed.source.checkLayout(layout());
  if (overrides) overrides->applyTo(ed.source);
  const OpenFastFile& f = ed.source;

  ed.Gravity = f.findDouble("Gravity");
  if (ed.Gravity) requireGravity(f, *ed.Gravity);
  ed.dof = readDofs(f);
  ed.init = readInitialConditions(f);
  ed.config = readConfiguration(f);
  ed.mass = readMass(f);
  ed.BldNodes = f.findInt("BldNodes");
  ed.teeter = readTeeter(f, ed.config.NumBl);
  if (ed.config.NumBl == 2) {  // ElastoDyn's ranges for a 2-bladed rotor
    if (!(ed.init.TeetDefl > -180.0 && ed.init.TeetDefl <= 180.0))
      throw InputError(f.where("TeetDefl", "must be in (-180, 180] deg (is " + numberText(ed.init.TeetDefl) + ")"));
    if (!(std::abs(ed.config.Delta3) < 90.0))
      throw InputError(f.where("Delta3", "must be in (-90, 90) deg (is " + numberText(ed.config.Delta3) + ")"));
  }
  ed.drivetrain = readDrivetrain(f);
  ed.YawFrctMod = f.findInt("YawFrctMod");
  ed.Furling = f.getBool("Furling");
  if (f.has("FurlFile")) ed.FurlFile = f.getPath("FurlFile");  // read only when Furling (unsupported)
  ed.TwrNodes = f.getInt("TwrNodes");
  requirePositive(f, "TwrNodes", ed.TwrNodes);
  if (ed.BldNodes) requirePositive(f, "BldNodes", *ed.BldNodes);
  for (const char* key : {"TwrNodes", "BldNodes"})
    if (const std::optional<int> n = f.findInt(key); n && *n > limits::kMaxElastoDynNodes)
      throw InputError(f.where(key, "at most " + std::to_string(limits::kMaxElastoDynNodes) + " nodes (is " +
                                        std::to_string(*n) + "; src/base/limits.hpp)"));

  ed.TwrFile = f.getExistingPath("TwrFile");
  ed.tower = readElastoDynTower(ed.TwrFile, overrides);
  for (int k = 1; k <= ed.config.NumBl; ++k) {
    const std::filesystem::path p = f.getExistingPath(indexedKey("BldFile", k));
    // Blades sharing a file (the usual deck) read it once: the same file with the same overrides.
    const auto same = std::find(ed.BldFile.begin(), ed.BldFile.end(), p);
    ed.blades.push_back(same != ed.BldFile.end() ? ed.blades[static_cast<std::size_t>(same - ed.BldFile.begin())]
                                                 : readElastoDynBlade(p, overrides));
    ed.BldFile.push_back(p);
  }
  return ed;
}

}  // namespace whirl::io
