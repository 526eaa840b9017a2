#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"

#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// Keys of ElastoDyn blade files, all versions whirl reads (FAST 8 ElastoDyn v1.00 to OpenFAST v5), arrays written
/// Name(k).
const OpenFastLayout& layout() {
  static const OpenFastLayout l{"ElastoDyn blade",
                                {"NBlInpSt", "CalcBMode", "BldFlDmp(k)", "BldEdDmp(k)", "FlStTunr(k)", "AdjBlMs",
                                 "AdjFlSt", "AdjEdSt", "BldFl1Sh(k)", "BldFl2Sh(k)", "BldEdgSh(k)"},
                                {}};
  return l;
}

}  // namespace

const std::vector<double>* ElastoDynBlade::pitchAxis() const {
  if (const std::vector<double>* c = distributed.find("PitchAxis")) return c;
  return distributed.find("AeroCent");
}

ElastoDynBlade readElastoDynBlade(const std::filesystem::path& file, OverrideSet* overrides) {
  ElastoDynBlade b;
  b.source = OpenFastFile::read(file);
  b.source.checkLayout(layout());
  if (overrides) overrides->applyTo(b.source);
  const OpenFastFile& f = b.source;

  b.NBlInpSt = f.getInt("NBlInpSt");
  b.BldFlDmp = getIndexed<2>(f, "BldFlDmp");
  b.BldEdDmp = f.getDouble("BldEdDmp(1)");
  b.FlStTunr = getIndexed<2>(f, "FlStTunr");
  b.AdjBlMs = f.getDouble("AdjBlMs");
  b.AdjFlSt = f.getDouble("AdjFlSt");
  b.AdjEdSt = f.getDouble("AdjEdSt");
  for (int m = 1; m <= 2; ++m) {
    requireNonnegative(f, indexedKey("BldFlDmp", m), b.BldFlDmp[m - 1]);
    requirePositive(f, indexedKey("FlStTunr", m), b.FlStTunr[m - 1]);
  }
  requireNonnegative(f, "BldEdDmp(1)", b.BldEdDmp);
  requirePositive(f, "AdjBlMs", b.AdjBlMs);
  requirePositive(f, "AdjFlSt", b.AdjFlSt);
  requirePositive(f, "AdjEdSt", b.AdjEdSt);

  b.distributed = readDistributedTable(f, "NBlInpSt", "BlFract",
                                       {"BlFract", "StrcTwst", "BMassDen", "FlpStff", "EdgStff"});
  requireFractionColumn(b.distributed, "BlFract");
  requireNonnegativeColumn(b.distributed, "BMassDen");
  requirePositiveColumn(b.distributed, "FlpStff");
  requirePositiveColumn(b.distributed, "EdgStff");

  b.BldFl1Sh = readModeShape(f, "BldFl1Sh");
  b.BldFl2Sh = readModeShape(f, "BldFl2Sh");
  b.BldEdgSh = readModeShape(f, "BldEdgSh");
  return b;
}

}  // namespace whirl::io
