#include "src/io/elastodyn_tower.hpp"

#include "src/io/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// Keys of ElastoDyn tower files, all versions whirl reads (FAST 8 ElastoDyn v1.00 to OpenFAST v5), arrays written Name(k).
const OpenFastLayout& layout() {
  static const OpenFastLayout l{
      "ElastoDyn tower",
      {
      "NTwInpSt", "CalcTMode", "TwrFADmp(k)", "TwrSSDmp(k)", "FAStTunr(k)", "SSStTunr(k)", "AdjTwMa", "AdjFASt", "AdjSSSt",
      "TwFAM1Sh(k)", "TwFAM2Sh(k)", "TwSSM1Sh(k)", "TwSSM2Sh(k)"},
      {}};
  return l;
}

}  // namespace

ElastoDynTower read_elastodyn_tower(const std::filesystem::path& file, OverrideSet* overrides) {
  ElastoDynTower t;
  t.source = OpenFastFile::read(file);
  t.source.check_layout(layout());
  if (overrides) overrides->apply_to(t.source);
  const OpenFastFile& f = t.source;

  t.NTwInpSt = f.get_int("NTwInpSt");
  t.TwrFADmp = get_indexed<2>(f, "TwrFADmp");
  t.TwrSSDmp = get_indexed<2>(f, "TwrSSDmp");
  t.FAStTunr = get_indexed<2>(f, "FAStTunr");
  t.SSStTunr = get_indexed<2>(f, "SSStTunr");
  t.AdjTwMa = f.get_double("AdjTwMa");
  t.AdjFASt = f.get_double("AdjFASt");
  t.AdjSSSt = f.get_double("AdjSSSt");
  for (int m = 1; m <= 2; ++m) {
    require_nonnegative(f, indexed_key("TwrFADmp", m), t.TwrFADmp[m - 1]);
    require_nonnegative(f, indexed_key("TwrSSDmp", m), t.TwrSSDmp[m - 1]);
    require_positive(f, indexed_key("FAStTunr", m), t.FAStTunr[m - 1]);
    require_positive(f, indexed_key("SSStTunr", m), t.SSStTunr[m - 1]);
  }
  require_positive(f, "AdjTwMa", t.AdjTwMa);
  require_positive(f, "AdjFASt", t.AdjFASt);
  require_positive(f, "AdjSSSt", t.AdjSSSt);

  t.distributed = read_distributed_table(f, "NTwInpSt", "HtFract", {"HtFract", "TMassDen", "TwFAStif", "TwSSStif"});
  require_fraction_column(t.distributed, "HtFract");
  require_nonnegative_column(t.distributed, "TMassDen");
  require_positive_column(t.distributed, "TwFAStif");
  require_positive_column(t.distributed, "TwSSStif");

  t.TwFAM1Sh = read_mode_shape(f, "TwFAM1Sh");
  t.TwFAM2Sh = read_mode_shape(f, "TwFAM2Sh");
  t.TwSSM1Sh = read_mode_shape(f, "TwSSM1Sh");
  t.TwSSM2Sh = read_mode_shape(f, "TwSSM2Sh");
  return t;
}

}  // namespace whirl::io
