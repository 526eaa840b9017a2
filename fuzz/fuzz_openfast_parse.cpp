// libFuzzer harness: the bytes are any OpenFAST input file (.fst, ElastoDyn main/tower/blade,
// ServoDyn) for the in-memory parser every OpenFAST reader starts with (io::OpenFastFile::parse:
// key/value lines, tables, Fortran numbers), then every typed getter on every key and every table
// lookup. Hundreds of times faster than the whole-model harnesses (fuzz_fst, fuzz_elastodyn, ...),
// so it reaches the parser's corners those cannot in the same time.
#include "fuzz/fuzz_support.hpp"
#include "src/io/openfast/openfast_input.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    const whirl::io::OpenFastFile f = whirl::io::OpenFastFile::parse(text, "fuzz.dat");
    auto quietly = [](auto&& get) {
      try {
        get();
      } catch (const whirl::InputError&) {
      }
    };
    for (const auto& e : f.entries()) {
      quietly([&] { (void)f.getDouble(e.key); });
      quietly([&] { (void)f.getInt(e.key); });
      quietly([&] { (void)f.getBool(e.key); });
      quietly([&] { (void)f.getDoubles(e.key); });
      quietly([&] { (void)f.getString(e.key); });
      quietly([&] { (void)f.getDoubleOrDefault(e.key); });
    }
    for (const auto& t : f.tables())
      for (const auto& c : t.columns) (void)f.findTable(c);
  });
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_openfast_parse", fuzzOne);
