#include "src/io/elastodyn_blade.hpp"

#include "src/io/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// Keys of ElastoDyn blade files, all versions whirl reads (FAST 8 ElastoDyn v1.00 to OpenFAST v5), arrays written Name(k).
const OpenFastLayout& layout() {
  static const OpenFastLayout l{
      "ElastoDyn blade",
      {
      "NBlInpSt", "CalcBMode", "BldFlDmp(k)", "BldEdDmp(k)", "FlStTunr(k)", "AdjBlMs", "AdjFlSt", "AdjEdSt", "BldFl1Sh(k)",
      "BldFl2Sh(k)", "BldEdgSh(k)"},
      {}};
  return l;
}

}  // namespace

const std::vector<double>* ElastoDynBlade::pitch_axis() const {
  if (const std::vector<double>* c = distributed.find("PitchAxis")) return c;
  return distributed.find("AeroCent");
}

ElastoDynBlade read_elastodyn_blade(const std::filesystem::path& file, OverrideSet* overrides) {
  ElastoDynBlade b;
  b.source = OpenFastFile::read(file);
  b.source.check_layout(layout());
  if (overrides) overrides->apply_to(b.source);
  const OpenFastFile& f = b.source;

  b.NBlInpSt = f.get_int("NBlInpSt");
  b.BldFlDmp = get_indexed<2>(f, "BldFlDmp");
  b.BldEdDmp = f.get_double("BldEdDmp(1)");
  b.FlStTunr = get_indexed<2>(f, "FlStTunr");
  b.AdjBlMs = f.get_double("AdjBlMs");
  b.AdjFlSt = f.get_double("AdjFlSt");
  b.AdjEdSt = f.get_double("AdjEdSt");
  for (int m = 1; m <= 2; ++m) {
    require_nonnegative(f, indexed_key("BldFlDmp", m), b.BldFlDmp[m - 1]);
    require_positive(f, indexed_key("FlStTunr", m), b.FlStTunr[m - 1]);
  }
  require_nonnegative(f, "BldEdDmp(1)", b.BldEdDmp);
  require_positive(f, "AdjBlMs", b.AdjBlMs);
  require_positive(f, "AdjFlSt", b.AdjFlSt);
  require_positive(f, "AdjEdSt", b.AdjEdSt);

  b.distributed = read_distributed_table(f, "NBlInpSt", "BlFract",
                                         {"BlFract", "StrcTwst", "BMassDen", "FlpStff", "EdgStff"});
  require_fraction_column(b.distributed, "BlFract");
  require_nonnegative_column(b.distributed, "BMassDen");
  require_positive_column(b.distributed, "FlpStff");
  require_positive_column(b.distributed, "EdgStff");

  b.BldFl1Sh = read_mode_shape(f, "BldFl1Sh");
  b.BldFl2Sh = read_mode_shape(f, "BldFl2Sh");
  b.BldEdgSh = read_mode_shape(f, "BldEdgSh");
  return b;
}

}  // namespace whirl::io
