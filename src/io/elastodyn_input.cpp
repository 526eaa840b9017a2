#include "src/io/elastodyn_input.hpp"

#include <cmath>
#include <utility>

#include "src/io/elastodyn_common.hpp"
#include "src/io/openfast_overrides.hpp"
#include "src/model/error.hpp"
#include "src/model/limits.hpp"

namespace whirl::io {
namespace {

/// Keys of ElastoDyn files, all versions whirl reads (FAST 8 ElastoDyn v1.00 to OpenFAST v5), arrays written Name(k).
const OpenFastLayout& layout() {
  static const OpenFastLayout l{
      "ElastoDyn",
      {
      "Echo", "Method", "DT", "Gravity", "FlapDOF1", "FlapDOF2", "EdgeDOF", "PitchDOF", "TeetDOF", "DrTrDOF",
      "GenDOF", "YawDOF", "TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2", "PtfmSgDOF", "PtfmSwDOF", "PtfmHvDOF",
      "PtfmRDOF", "PtfmPDOF", "PtfmYDOF", "OoPDefl", "IPDefl", "BlPitch(k)", "TeetDefl", "Azimuth", "RotSpeed",
      "NacYaw", "TTDspFA", "TTDspSS", "PtfmSurge", "PtfmSway", "PtfmHeave", "PtfmRoll", "PtfmPitch", "PtfmYaw",
      "NumBl", "TipRad", "HubRad", "PreCone(k)", "HubCM", "UndSling", "Delta3", "AzimB1Up", "OverHang", "ShftGagL",
      "ShftTilt", "NacCMxn", "NacCMyn", "NacCMzn", "NcIMUxn", "NcIMUyn", "NcIMUzn", "Twr2Shft", "TowerHt",
      "TowerBsHt", "TwrRBHt", "TwrDraft", "PtfmCMxt", "PtfmCMyt", "PtfmCMzt", "PtfmRefxt", "PtfmRefyt",
      "PtfmRefzt", "PtfmRef", "TipMass(k)", "PBrIner(k)", "BlPIner(k)", "HubMass", "HubIner", "HubIner_Teeter", "GenIner",
      "NacMass", "NacYIner", "YawBrMass", "PtfmMass", "PtfmRIner", "PtfmPIner", "PtfmYIner", "PtfmXYIner",
      "PtfmYZIner", "PtfmXZIner", "BldNodes", "BldFile(k)", "TeetMod", "TeetDmpP", "TeetDmp", "TeetCDmp", "TeetSStP",
      "TeetHStP", "TeetSSSp", "TeetHSSp", "YawFrctMod", "M_CSmax", "M_CD", "sig_v", "sig_v2", "OmgCut", "M_FCSmax",
      "M_MCSmax", "M_FCD", "M_MCD", "GBoxEff", "GBRatio", "DTTorSpr", "DTTorDmp", "Furling", "FurlFile",
      "TwrNodes", "TwrFile", "SumPrint", "OutFile", "TabDelim", "OutFmt", "TStart", "DecFact", "NTwGages",
      "TwrGagNd", "NBlGages", "BldGagNd", "BldNd_BladesOut", "BldNd_BlOutNd"},
      {}};
  return l;
}

ElastoDynDofs read_dofs(const OpenFastFile& f) {
  ElastoDynDofs d;
  d.FlapDOF1 = f.get_bool("FlapDOF1");
  d.FlapDOF2 = f.get_bool("FlapDOF2");
  d.EdgeDOF = f.get_bool("EdgeDOF");
  d.PitchDOF = f.find_bool("PitchDOF");
  d.TeetDOF = f.get_bool("TeetDOF");
  d.DrTrDOF = f.get_bool("DrTrDOF");
  d.GenDOF = f.get_bool("GenDOF");
  d.YawDOF = f.get_bool("YawDOF");
  d.TwFADOF1 = f.get_bool("TwFADOF1");
  d.TwFADOF2 = f.get_bool("TwFADOF2");
  d.TwSSDOF1 = f.get_bool("TwSSDOF1");
  d.TwSSDOF2 = f.get_bool("TwSSDOF2");
  d.PtfmSgDOF = f.get_bool("PtfmSgDOF");
  d.PtfmSwDOF = f.get_bool("PtfmSwDOF");
  d.PtfmHvDOF = f.get_bool("PtfmHvDOF");
  d.PtfmRDOF = f.get_bool("PtfmRDOF");
  d.PtfmPDOF = f.get_bool("PtfmPDOF");
  d.PtfmYDOF = f.get_bool("PtfmYDOF");
  return d;
}

ElastoDynInitialConditions read_initial_conditions(const OpenFastFile& f) {
  ElastoDynInitialConditions c;
  c.OoPDefl = f.get_double("OoPDefl");
  c.IPDefl = f.get_double("IPDefl");
  c.BlPitch = get_indexed<3>(f, "BlPitch");
  c.TeetDefl = f.get_double("TeetDefl");
  c.Azimuth = f.get_double("Azimuth");
  c.RotSpeed = f.get_double("RotSpeed");
  c.NacYaw = f.get_double("NacYaw");
  c.TTDspFA = f.get_double("TTDspFA");
  c.TTDspSS = f.get_double("TTDspSS");
  c.PtfmSurge = f.get_double("PtfmSurge");
  c.PtfmSway = f.get_double("PtfmSway");
  c.PtfmHeave = f.get_double("PtfmHeave");
  c.PtfmRoll = f.get_double("PtfmRoll");
  c.PtfmPitch = f.get_double("PtfmPitch");
  c.PtfmYaw = f.get_double("PtfmYaw");
  return c;
}

ElastoDynConfiguration read_configuration(const OpenFastFile& f) {
  ElastoDynConfiguration c;
  c.NumBl = f.get_int("NumBl");
  if (c.NumBl < 2 || c.NumBl > 3)
    throw InputError(f.where("NumBl", "must be 2 or 3 (is " + std::to_string(c.NumBl) + ")"));
  c.TipRad = f.get_double("TipRad");
  c.HubRad = f.get_double("HubRad");
  require_nonnegative(f, "HubRad", c.HubRad);
  if (!(c.TipRad > c.HubRad))
    throw InputError(f.where("TipRad", "must be larger than HubRad (" + number_text(c.TipRad) +
                                           " <= " + number_text(c.HubRad) + ")"));
  c.PreCone = get_indexed<3>(f, "PreCone");
  c.HubCM = f.get_double("HubCM");
  c.UndSling = f.get_double("UndSling");
  c.Delta3 = f.get_double("Delta3");
  c.AzimB1Up = f.get_double("AzimB1Up");
  c.OverHang = f.get_double("OverHang");
  c.ShftGagL = f.get_double("ShftGagL");
  c.ShftTilt = f.get_double("ShftTilt");
  c.NacCMxn = f.get_double("NacCMxn");
  c.NacCMyn = f.get_double("NacCMyn");
  c.NacCMzn = f.get_double("NacCMzn");
  c.NcIMUxn = f.get_double("NcIMUxn");
  c.NcIMUyn = f.get_double("NcIMUyn");
  c.NcIMUzn = f.get_double("NcIMUzn");
  c.Twr2Shft = f.get_double("Twr2Shft");
  c.TowerHt = f.get_double("TowerHt");
  c.TowerBsHt = f.find_double("TowerBsHt");
  if (c.TowerBsHt && !(c.TowerHt > *c.TowerBsHt))
    throw InputError(f.where("TowerHt", "must be above TowerBsHt (" + number_text(c.TowerHt) +
                                            " <= " + number_text(*c.TowerBsHt) + ")"));
  c.PtfmCMxt = f.find_double("PtfmCMxt");
  c.PtfmCMyt = f.find_double("PtfmCMyt");
  c.PtfmCMzt = f.find_double("PtfmCMzt");
  c.PtfmRefxt = f.find_double("PtfmRefxt");
  c.PtfmRefyt = f.find_double("PtfmRefyt");
  c.PtfmRefzt = f.find_double("PtfmRefzt");
  c.TwrRBHt = f.find_double("TwrRBHt");
  c.TwrDraft = f.find_double("TwrDraft");
  c.PtfmRef = f.find_double("PtfmRef");
  return c;
}

ElastoDynMassInertia read_mass(const OpenFastFile& f) {
  ElastoDynMassInertia m;
  m.TipMass = get_indexed<3>(f, "TipMass");
  for (int k = 1; k <= 3; ++k) require_nonnegative(f, indexed_key("TipMass", k), m.TipMass[k - 1]);
  m.PBrIner = find_indexed<3>(f, "PBrIner");
  m.BlPIner = find_indexed<3>(f, "BlPIner");
  struct Scalar {
    const char* key;
    double* value;
  };
  const Scalar required[] = {{"HubMass", &m.HubMass},     {"HubIner", &m.HubIner},     {"GenIner", &m.GenIner},
                             {"NacMass", &m.NacMass},     {"NacYIner", &m.NacYIner},   {"YawBrMass", &m.YawBrMass},
                             {"PtfmMass", &m.PtfmMass},   {"PtfmRIner", &m.PtfmRIner}, {"PtfmPIner", &m.PtfmPIner},
                             {"PtfmYIner", &m.PtfmYIner}};
  for (const Scalar& s : required) {
    *s.value = f.get_double(s.key);
    require_nonnegative(f, s.key, *s.value);
  }
  m.HubIner_Teeter = f.find_double("HubIner_Teeter");
  if (m.HubIner_Teeter) require_nonnegative(f, "HubIner_Teeter", *m.HubIner_Teeter);
  m.PtfmXYIner = f.find_double("PtfmXYIner");
  m.PtfmYZIner = f.find_double("PtfmYZIner");
  m.PtfmXZIner = f.find_double("PtfmXZIner");
  return m;
}

// The ROTOR-TEETER section: optional for 3 blades (ElastoDyn ignores it), required and checked as
// ElastoDyn's ValidatePrimaryData checks it for 2 blades (every version has all eight keys).
ElastoDynTeeter read_teeter(const OpenFastFile& f, int num_blades) {
  ElastoDynTeeter t;
  const bool two = num_blades == 2;
  auto need = [&](const char* key) {
    if (two && !f.has(key))
      throw InputError(f.where(key, "key not found: a 2-bladed rotor (NumBl = 2) needs the ROTOR-TEETER section "
                                    "(TeetMod, TeetDmpP, TeetDmp, TeetCDmp, TeetSStP, TeetHStP, TeetSSSp, TeetHSSp)"));
  };
  for (const char* key : {"TeetMod", "TeetDmpP", "TeetDmp", "TeetCDmp", "TeetSStP", "TeetHStP", "TeetSSSp", "TeetHSSp"})
    need(key);
  t.TeetMod = f.find_int("TeetMod");
  t.TeetDmpP = f.find_double("TeetDmpP");
  t.TeetDmp = f.find_double("TeetDmp");
  t.TeetCDmp = f.find_double("TeetCDmp");
  t.TeetSStP = f.find_double("TeetSStP");
  t.TeetHStP = f.find_double("TeetHStP");
  t.TeetSSSp = f.find_double("TeetSSSp");
  t.TeetHSSp = f.find_double("TeetHSSp");
  if (!two) return t;
  if (*t.TeetMod < 0 || *t.TeetMod > 2)
    throw InputError(f.where("TeetMod", "must be 0 (none), 1 (standard) or 2 (user-defined) (is " +
                                            std::to_string(*t.TeetMod) + ")"));
  const std::pair<const char*, double> angles[] = {{"TeetDmpP", *t.TeetDmpP}, {"TeetSStP", *t.TeetSStP}};
  for (const auto& [key, value] : angles)
    if (!(value >= 0.0 && value <= 180.0))
      throw InputError(f.where(key, "must be in [0, 180] deg (is " + number_text(value) + ")"));
  if (!(*t.TeetHStP >= *t.TeetSStP && *t.TeetHStP <= 180.0))
    throw InputError(f.where("TeetHStP", "must be in [TeetSStP, 180] deg = [" + number_text(*t.TeetSStP) +
                                             ", 180] (is " + number_text(*t.TeetHStP) + ")"));
  for (const char* key : {"TeetDmp", "TeetCDmp", "TeetSSSp", "TeetHSSp"}) require_nonnegative(f, key, f.get_double(key));
  if (*t.TeetCDmp != 0.0)  // ElastoDyn refuses it too ("TeetCDmp must be 0 in this version")
    throw InputError(f.where("TeetCDmp", "must be 0, as ElastoDyn requires (Coulomb teeter damping is not modelled)"));
  return t;
}

ElastoDynDrivetrain read_drivetrain(const OpenFastFile& f) {
  ElastoDynDrivetrain d;
  d.GBoxEff = f.get_double("GBoxEff");
  if (!(d.GBoxEff > 0.0 && d.GBoxEff <= 100.0))
    throw InputError(f.where("GBoxEff", "must be in (0, 100] % (is " + number_text(d.GBoxEff) + ")"));
  d.GBRatio = f.get_double("GBRatio");
  require_positive(f, "GBRatio", d.GBRatio);
  d.DTTorSpr = f.get_double("DTTorSpr");
  require_nonnegative(f, "DTTorSpr", d.DTTorSpr);
  d.DTTorDmp = f.get_double("DTTorDmp");
  require_nonnegative(f, "DTTorDmp", d.DTTorDmp);
  return d;
}

}  // namespace

ElastoDynInput read_elastodyn(const std::filesystem::path& file, OverrideSet* overrides) {
  ElastoDynInput ed;
  ed.source = OpenFastFile::read(file);
  ed.source.check_layout(layout());
  if (overrides) overrides->apply_to(ed.source);
  const OpenFastFile& f = ed.source;

  ed.Gravity = f.find_double("Gravity");
  if (ed.Gravity) require_nonnegative(f, "Gravity", *ed.Gravity);
  ed.dof = read_dofs(f);
  ed.init = read_initial_conditions(f);
  ed.config = read_configuration(f);
  ed.mass = read_mass(f);
  ed.BldNodes = f.find_int("BldNodes");
  ed.teeter = read_teeter(f, ed.config.NumBl);
  if (ed.config.NumBl == 2) {  // ElastoDyn's ranges for a 2-bladed rotor
    if (!(ed.init.TeetDefl > -180.0 && ed.init.TeetDefl <= 180.0))
      throw InputError(f.where("TeetDefl", "must be in (-180, 180] deg (is " + number_text(ed.init.TeetDefl) + ")"));
    if (!(std::abs(ed.config.Delta3) < 90.0))
      throw InputError(f.where("Delta3", "must be in (-90, 90) deg (is " + number_text(ed.config.Delta3) + ")"));
  }
  ed.drivetrain = read_drivetrain(f);
  ed.YawFrctMod = f.find_int("YawFrctMod");
  ed.Furling = f.get_bool("Furling");
  if (f.has("FurlFile")) ed.FurlFile = f.get_path("FurlFile");  // read only when Furling (unsupported)
  ed.TwrNodes = f.get_int("TwrNodes");
  require_positive(f, "TwrNodes", ed.TwrNodes);
  if (ed.BldNodes) require_positive(f, "BldNodes", *ed.BldNodes);
  for (const char* key : {"TwrNodes", "BldNodes"})
    if (const std::optional<int> n = f.find_int(key); n && *n > limits::kMaxElastoDynNodes)
      throw InputError(f.where(key, "at most " + std::to_string(limits::kMaxElastoDynNodes) + " nodes (is " +
                                        std::to_string(*n) + "; src/model/limits.hpp)"));

  ed.TwrFile = f.get_existing_path("TwrFile");
  ed.tower = read_elastodyn_tower(ed.TwrFile, overrides);
  for (int k = 1; k <= ed.config.NumBl; ++k) {
    ed.BldFile.push_back(f.get_existing_path(indexed_key("BldFile", k)));
    ed.blades.push_back(read_elastodyn_blade(ed.BldFile.back(), overrides));
  }
  return ed;
}

}  // namespace whirl::io
