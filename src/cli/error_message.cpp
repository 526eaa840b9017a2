#include "src/cli/error_message.hpp"

#include <filesystem>
#include <new>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "src/base/error.hpp"
#include "src/base/text.hpp"

namespace whirl::cli {
namespace {

/// nlohmann's text after its "[json.exception.<kind>.<id>] " tag.
std::string withoutJsonTag(const std::string& what) {
  const std::size_t end = what.find("] ");
  return what.rfind("[json.exception", 0) == 0 && end != std::string::npos ? what.substr(end + 2) : what;
}

std::string describe(const std::exception& e) {
  if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const ComputeError*>(&e)) return e.what();
  if (dynamic_cast<const std::bad_alloc*>(&e))
    return "out of memory: the input asks for more than this machine can hold (the bounds whirl checks are in "
           "docs/user/limits.md; please report the input that got this far)";
  if (const auto* j = dynamic_cast<const nlohmann::json::exception*>(&e))
    return "cannot write the JSON output (" + withoutJsonTag(j->what()) +
           "): a name or value whirl should have refused where it was read; please report the input";
  if (const auto* f = dynamic_cast<const std::filesystem::filesystem_error*>(&e)) {
    const std::string path = f->path1().empty() ? "" : f->path1().string() + ": ";
    return path + f->code().message();
  }
  return std::string("internal error (") + e.what() + "); please report the input";
}

}  // namespace

std::string errorMessage(const std::exception& e) { return escapeControlCharacters(describe(e)); }

}  // namespace whirl::cli
