// libFuzzer harness: the bytes are any OpenFAST input file (.fst, ElastoDyn main/tower/blade,
// ServoDyn) for the in-memory parser every OpenFAST reader starts with (io::OpenFastFile::parse:
// key/value lines, tables, Fortran numbers), then every typed getter on every key and every table
// lookup. Hundreds of times faster than the whole-model harnesses (fuzz_fst, fuzz_elastodyn, ...),
// so it reaches the parser's corners those cannot in the same time.
#include "fuzz/fuzz_support.hpp"
#include "src/io/openfast_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
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
      quietly([&] { (void)f.get_double(e.key); });
      quietly([&] { (void)f.get_int(e.key); });
      quietly([&] { (void)f.get_bool(e.key); });
      quietly([&] { (void)f.get_doubles(e.key); });
      quietly([&] { (void)f.get_string(e.key); });
      quietly([&] { (void)f.get_double_or_default(e.key); });
    }
    for (const auto& t : f.tables())
      for (const auto& c : t.columns) (void)f.find_table(c);
  });
  return 0;
}
