#include "src/io/openfast/elastodyn/elastodyn_tower.hpp"

#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// Keys of ElastoDyn tower files, all versions whirl reads (FAST 8 ElastoDyn v1.00 to OpenFAST v5), arrays written
/// Name(k).
const OpenFastLayout& layout() {
  static const OpenFastLayout l{"ElastoDyn tower",
                                {"NTwInpSt", "CalcTMode", "TwrFADmp(k)", "TwrSSDmp(k)", "FAStTunr(k)", "SSStTunr(k)",
                                 "AdjTwMa", "AdjFASt", "AdjSSSt", "TwFAM1Sh(k)", "TwFAM2Sh(k)", "TwSSM1Sh(k)",
                                 "TwSSM2Sh(k)"},
                                {}};
  return l;
}

}  // namespace

ElastoDynTower readElastoDynTower(const std::filesystem::path& file, OverrideSet* overrides) {
  ElastoDynTower t;
  t.source = OpenFastFile::read(file);
  t.source.checkLayout(layout());
  if (overrides) overrides->applyTo(t.source);
  const OpenFastFile& f = t.source;

  t.NTwInpSt = f.getInt("NTwInpSt");
  t.TwrFADmp = getIndexed<2>(f, "TwrFADmp");
  t.TwrSSDmp = getIndexed<2>(f, "TwrSSDmp");
  t.FAStTunr = getIndexed<2>(f, "FAStTunr");
  t.SSStTunr = getIndexed<2>(f, "SSStTunr");
  t.AdjTwMa = f.getDouble("AdjTwMa");
  t.AdjFASt = f.getDouble("AdjFASt");
  t.AdjSSSt = f.getDouble("AdjSSSt");
  for (int m = 1; m <= 2; ++m) {
    requireNonnegative(f, indexedKey("TwrFADmp", m), t.TwrFADmp[m - 1]);
    requireNonnegative(f, indexedKey("TwrSSDmp", m), t.TwrSSDmp[m - 1]);
    requirePositive(f, indexedKey("FAStTunr", m), t.FAStTunr[m - 1]);
    requirePositive(f, indexedKey("SSStTunr", m), t.SSStTunr[m - 1]);
  }
  requirePositive(f, "AdjTwMa", t.AdjTwMa);
  requirePositive(f, "AdjFASt", t.AdjFASt);
  requirePositive(f, "AdjSSSt", t.AdjSSSt);

  t.distributed = readDistributedTable(f, "NTwInpSt", "HtFract", {"HtFract", "TMassDen", "TwFAStif", "TwSSStif"});
  requireFractionColumn(t.distributed, "HtFract");
  requireNonnegativeColumn(t.distributed, "TMassDen");
  requirePositiveColumn(t.distributed, "TwFAStif");
  requirePositiveColumn(t.distributed, "TwSSStif");

  t.TwFAM1Sh = readModeShape(f, "TwFAM1Sh");
  t.TwFAM2Sh = readModeShape(f, "TwFAM2Sh");
  t.TwSSM1Sh = readModeShape(f, "TwSSM1Sh");
  t.TwSSM2Sh = readModeShape(f, "TwSSM2Sh");
  return t;
}

}  // namespace whirl::io
