#include "src/io/servodyn_input.hpp"

#include "src/io/elastodyn_common.hpp"
#include "src/io/openfast_overrides.hpp"

namespace whirl::io {

ServoDynInput read_servodyn(const std::filesystem::path& file, OverrideSet* overrides) {
  ServoDynInput s;
  s.source = OpenFastFile::read(file);
  s.source.check_layout(OpenFastLayout{"ServoDyn", {}, {}});  // duplicates only: many keys across versions
  if (overrides) overrides->apply_to(s.source);
  const OpenFastFile& f = s.source;
  s.YCMode = f.get_int("YCMode");
  s.YawNeut = f.get_double("YawNeut");
  s.YawSpr = f.get_double("YawSpr");
  s.YawDamp = f.get_double("YawDamp");
  require_nonnegative(f, "YawSpr", s.YawSpr);
  require_nonnegative(f, "YawDamp", s.YawDamp);
  return s;
}

}  // namespace whirl::io
