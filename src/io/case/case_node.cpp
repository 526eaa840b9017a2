#include "src/io/case/case_node.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>

#include <fmt/format.h>

#include "src/base/error.hpp"
#include "src/base/text.hpp"

namespace whirl {
namespace {

std::string joinKeys(const std::vector<std::string>& keys) {
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

// Shown in messages: the value as written, shortened.
std::string shown(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsMap()) return "a map";
  if (n.IsSequence()) return "a list";
  return "'" + shortenedForMessage(n.Scalar()) + "'";
}

bool isYamlNonFinite(const std::string& s) {
  static const std::set<std::string> special = {".nan",  ".NaN",  ".NAN",  ".inf",  ".Inf",  ".INF",
                                                "+.inf", "+.Inf", "+.INF", "-.inf", "-.Inf", "-.INF"};
  return special.count(s) > 0;
}

}  // namespace

std::string CaseSource::resolve(const std::string& relative) const {
  const std::filesystem::path p(relative);
  if (p.is_absolute() || folder.empty()) return p.string();
  return (std::filesystem::path(folder) / p).string();
}

std::string CaseSource::outsideReason(const std::string& resolved) const {
  if (allow_outside_files) return "";
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path base = fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : fs::path(folder)), ec);
  const fs::path target = fs::weakly_canonical(fs::absolute(resolved), ec);
  const fs::path rel = target.lexically_relative(base);
  if (!ec && !rel.empty() && *rel.begin() != ".." && !rel.is_absolute()) return "";
  return "the file is outside the case folder (" + (base.empty() ? std::string(".") : base.string()) +
         "); only files under it are read unless --allow-outside-files is given";
}

std::string num(double v) { return fmt::format("{:g}", v); }

std::string mapChildPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string listChildPath(const std::string& parent, const YAML::Node& item, size_t index) {
  if (item.IsMap() && item["name"] && item["name"].IsScalar()) return mapChildPath(parent, item["name"].Scalar());
  return parent + "[" + std::to_string(index) + "]";
}

CaseNode::CaseNode(YAML::Node node, const CaseSource& source) : CaseNode(std::move(node), "", 1, &source) {}

CaseNode::CaseNode(YAML::Node node, std::string path, int fallback_line, const CaseSource* source)
    : node_(std::move(node)), path_(std::move(path)), source_(source) {
  // A value that came from --set: its own mark (if any) is from the --set text, not the file.
  if (const CaseSource::Set* s = setBy()) {
    line_ = s->line;
  } else {
    const YAML::Mark mk = node_.IsDefined() ? node_.Mark() : YAML::Mark::null_mark();
    line_ = mk.is_null() ? fallback_line : mk.line + 1;
  }
}

const CaseSource::Set* CaseNode::setBy() const {
  const CaseSource::Set* best = nullptr;
  for (const auto& s : source_->sets) {
    const bool prefix = path_.compare(0, s.path.size(), s.path) == 0 &&
                        (path_.size() == s.path.size() || path_[s.path.size()] == '.' || path_[s.path.size()] == '[');
    if (prefix && (!best || s.path.size() >= best->path.size())) best = &s;
  }
  return best;
}

CaseNode CaseNode::child(const YAML::Node& node, std::string path) const {
  return CaseNode(node, std::move(path), line_, source_);
}

Where CaseNode::where() const {
  const CaseSource::Set* s = setBy();
  return Where{source_->file, line_, path_, s ? " (value from --set " + s->text + ")" : ""};
}

void CaseNode::fail(const std::string& reason) const { where().fail(reason); }

void CaseNode::allowKeys(std::initializer_list<std::string_view> allowed) const {
  allowKeys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void CaseNode::allowKeys(const std::vector<std::string>& allowed) const {
  for (const MapEntry& e : entries()) {
    bool ok = false;
    for (const auto& a : allowed) ok = ok || e.key == a;
    if (!ok) e.key_where.fail("unknown key '" + e.key + "' (allowed: " + joinKeys(allowed) + ")");
  }
}

bool CaseNode::has(std::string_view key) const { return find(key).has_value(); }

std::optional<CaseNode> CaseNode::find(std::string_view key) const {
  if (!isMap()) {
    if (isNull()) return std::nullopt;
    fail("expected a map of keys, got " + shown(node_));
  }
  for (auto it = node_.begin(); it != node_.end(); ++it)
    if (it->first.IsScalar() && it->first.Scalar() == key)
      return child(it->second, mapChildPath(path_, std::string(key)));
  return std::nullopt;
}

CaseNode CaseNode::at(std::string_view key) const {
  std::optional<CaseNode> n = find(key);
  if (!n) fail("missing key '" + std::string(key) + "'");
  return *n;
}

std::vector<MapEntry> CaseNode::entries() const {
  std::vector<MapEntry> out;
  if (isNull()) return out;
  if (!isMap()) fail("expected a map of keys, got " + shown(node_));
  std::set<std::string> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (!it->first.IsScalar()) child(it->first, path_).fail("a key must be a plain name, got " + shown(it->first));
    const std::string k = it->first.Scalar();
    const std::string p = mapChildPath(path_, k);
    const Where kw = child(it->first, p).where();
    if (!seen.insert(k).second) kw.fail("key '" + k + "' given twice");
    out.push_back(MapEntry{k, kw, child(it->second, p)});
  }
  return out;
}

std::vector<CaseNode> CaseNode::items() const {
  std::vector<CaseNode> out;
  if (isNull()) return out;
  if (!isList()) fail("expected a list, got " + shown(node_));
  for (size_t i = 0; i < node_.size(); ++i) out.push_back(child(node_[i], listChildPath(path_, node_[i], i)));
  return out;
}

double CaseNode::number() const {
  if (!isScalar()) fail("expected a number, got " + shown(node_));
  std::string s = node_.Scalar();
  if (node_.Tag() == "!") fail("expected a number, got the quoted text " + shown(node_));
  if (isYamlNonFinite(s)) fail("expected a finite number, got " + s);
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) fail("expected a number, got " + shown(node_));
  if (!std::isfinite(v)) fail("expected a finite number, got " + shown(node_));
  return v;
}

int CaseNode::integer() const {
  const double v = number();
  if (v != std::floor(v) || std::abs(v) > 1e9) fail("expected a whole number, got " + shown(node_));
  return static_cast<int>(v);
}

bool CaseNode::boolean() const {
  const std::string s = isScalar() && node_.Tag() != "!" ? node_.Scalar() : "";
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  fail("expected true or false, got " + shown(node_));
}

std::string CaseNode::text() const {
  const std::string s = freeText();
  // Names end up inside generated scripts and tables (campbell.gp, .lin): one printable line only.
  if (const std::string reason = controlCharacterReason(s); !reason.empty()) fail(reason);
  return s;
}

std::string CaseNode::freeText() const {
  if (!isScalar()) fail("expected a text value, got " + shown(node_));
  return node_.Scalar();
}

std::vector<double> CaseNode::numbers() const {
  if (!isList()) fail("expected a list of numbers, got " + shown(node_));
  std::vector<double> v;
  for (const CaseNode& item : items()) v.push_back(item.number());
  return v;
}

Vec3 CaseNode::vec3() const {
  const std::vector<double> v = numbers();
  if (v.size() != 3) fail("expected 3 numbers [x, y, z], got " + std::to_string(v.size()));
  return Vec3(v[0], v[1], v[2]);
}

MatX CaseNode::matrix(int rows, int cols) const {
  const std::string dims = std::to_string(rows) + "×" + std::to_string(cols);
  if (!isList() || static_cast<int>(node_.size()) != rows)
    fail("expected a " + dims + " matrix written as " + std::to_string(rows) + " rows");
  MatX m(rows, cols);
  const std::vector<CaseNode> r = items();
  for (int i = 0; i < rows; ++i) {
    const std::vector<double> v = r[i].numbers();
    if (static_cast<int>(v.size()) != cols)
      r[i].fail("row " + std::to_string(i + 1) + " of a " + dims + " matrix has " + std::to_string(v.size()) +
                " numbers");
    for (int j = 0; j < cols; ++j) m(i, j) = v[j];
  }
  return m;
}

double CaseNode::number(std::string_view key, double fallback) const {
  const auto n = find(key);
  return n ? n->number() : fallback;
}

bool CaseNode::boolean(std::string_view key, bool fallback) const {
  const auto n = find(key);
  return n ? n->boolean() : fallback;
}

std::string CaseNode::text(std::string_view key, const std::string& fallback) const {
  const auto n = find(key);
  return n ? n->text() : fallback;
}

Vec3 CaseNode::vec3(std::string_view key, const Vec3& fallback) const {
  const auto n = find(key);
  return n ? n->vec3() : fallback;
}

}  // namespace whirl
