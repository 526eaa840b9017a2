#include "src/io/openfast/openfast_lines.hpp"

#include <fstream>
#include <sstream>

#include "src/base/error.hpp"
#include "src/io/openfast/openfast_input.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

char firstNonblank(std::string_view line) {
  for (char c : line)
    if (!isBlank(c)) return c;
  return '\0';
}

}  // namespace

bool isCommentLine(std::string_view line) {
  const char c = firstNonblank(line);
  return c == '!' || c == '#' || c == '%';
}

bool isBlankLine(std::string_view line) { return firstNonblank(line) == '\0'; }

std::vector<std::string> splitWords(std::string_view line) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (isBlank(c) || c == ',') {
      ++i;
      continue;
    }
    if (c == '!') break;  // trailing comment
    const std::size_t b = i;
    if (c == '"' || c == '\'') {
      const std::size_t close = line.find(c, i + 1);
      i = close == std::string_view::npos ? line.size() : close + 1;
    } else {
      while (i < line.size() && !isBlank(line[i]) && line[i] != ',' && line[i] != '!') ++i;
    }
    out.emplace_back(line.substr(b, i - b));
  }
  return out;
}

std::string unquoted(std::string_view word) {
  if (!word.empty() && (word.front() == '"' || word.front() == '\'')) {
    word.remove_prefix(1);
    if (!word.empty() && (word.back() == '"' || word.back() == '\'')) word.remove_suffix(1);
  }
  return std::string(word);
}

std::optional<std::vector<double>> parseNumberRow(std::string_view line) {
  const std::vector<std::string> words = splitWords(line);
  if (words.empty()) return std::nullopt;
  std::vector<double> out;
  out.reserve(words.size());
  for (const std::string& w : words) {
    const std::optional<double> v = parseFortranDouble(w);
    if (!v) return std::nullopt;
    out.push_back(*v);
  }
  return out;
}

OpenFastLines OpenFastLines::read(const std::filesystem::path& file) {
  std::string text;
  if (!readInputFile(file.string(), text)) throw InputError(whirl::where(file.string(), 0, "", "cannot open file"));
  return fromText(text, file);
}

OpenFastLines OpenFastLines::fromText(std::string_view text, const std::filesystem::path& file) {
  OpenFastLines l;
  l.path_ = file;
  std::size_t b = 0;
  while (b < text.size()) {
    std::size_t e = text.find('\n', b);
    if (e == std::string_view::npos) e = text.size();
    std::string_view s = text.substr(b, e - b);
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    l.lines_.emplace_back(s);
    b = e + 1;
  }
  return l;
}

const std::string& OpenFastLines::line(int n) const {
  static const std::string empty;
  if (n < 1 || n > count()) return empty;
  return lines_[static_cast<std::size_t>(n - 1)];
}

std::string OpenFastLines::text() const {
  std::string out;
  for (const std::string& l : lines_) out += l + '\n';
  return out;
}

std::string OpenFastLines::textWithoutComments() const {
  std::string out;
  for (const std::string& l : lines_) out += (isCommentLine(l) ? std::string() : l) + '\n';
  return out;
}

std::optional<int> OpenFastLines::nextContentLine(int n) const {
  for (int i = n + 1; i <= count(); ++i) {
    const std::string& l = line(i);
    if (!isBlankLine(l) && !isCommentLine(l)) return i;
  }
  return std::nullopt;
}

}  // namespace whirl::io
