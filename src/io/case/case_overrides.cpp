// `--set key=value` overrides: parsed from the command line, applied to the YAML document before
// it is read. List entries are found by name (or index); map keys that are missing are added and
// then checked by the reader like any key in the file, so a typo is still reported.
#include <charconv>

#include "src/base/error.hpp"
#include "src/base/text.hpp"
#include "src/io/case/case_reader.hpp"

namespace whirl {
namespace {

std::vector<std::string> splitKey(const std::string& key) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t dot = key.find('.', start);
    out.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) return out;
    start = dot + 1;
  }
}

std::string joinSegments(const std::vector<std::string>& s, size_t from, size_t to) {
  std::string r;
  for (size_t i = from; i < to; ++i) r += (i > from ? "." : "") + s[i];
  return r;
}

// The new value: a YAML flow list or map when it starts with '[' or '{', else the text as is.
YAML::Node parseValue(const CaseOverride& o, const std::string& file) {
  if (o.value.empty() || (o.value[0] != '[' && o.value[0] != '{')) return YAML::Node(o.value);
  try {
    return YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw InputError(
        where(file, 0, o.key, "--set " + o.key + "=" + o.value + ": the value is not valid YAML: " + e.msg));
  }
}

// The entry of a list named seg[i..j) (names may contain dots: longest match first), else the
// entry at index seg[i]; `used` = number of segments consumed, 0 when there is none.
size_t findEntry(const YAML::Node& list, const std::vector<std::string>& seg, size_t i, size_t& used) {
  for (size_t j = seg.size(); j > i; --j)
    for (size_t k = 0; k < list.size(); ++k) {
      const YAML::Node& e = list[k];
      if (e.IsMap() && e["name"] && e["name"].IsScalar() && e["name"].Scalar() == joinSegments(seg, i, j)) {
        used = j - i;
        return k;
      }
    }
  size_t idx = 0;
  const auto [end, ec] = std::from_chars(seg[i].data(), seg[i].data() + seg[i].size(), idx);
  used = ec == std::errc() && end == seg[i].data() + seg[i].size() && idx < list.size() ? 1 : 0;
  return idx;
}

}  // namespace

CaseOverride parseOverride(const std::string& text) {
  const auto eq = text.find('=');
  auto bad = [&](const std::string& why) {
    return InputError(where("", 0, "--set " + text, why + " (expected key=value, e.g. bodies.nacelle.mass=2.4e5)"));
  };
  if (eq == std::string::npos) throw bad("no '='");
  CaseOverride o{std::string(trimBlanks(std::string_view(text).substr(0, eq))),
                 std::string(trimBlanks(std::string_view(text).substr(eq + 1)))};
  if (o.key.empty()) throw bad("the key is empty");
  if (o.value.empty()) throw bad("the value is empty");
  for (const auto& s : splitKey(o.key))
    if (s.empty()) throw bad("the key has an empty part");
  return o;
}

void applyOverrides(YAML::Node& root, const std::vector<CaseOverride>& overrides, CaseSource& source) {
  for (const CaseOverride& o : overrides) {
    const std::string text = o.key + "=" + o.value;
    const std::vector<std::string> seg = splitKey(o.key);
    for (const auto& s : seg)
      if (s.empty()) throw InputError(where(source.file, 0, o.key, "--set " + text + ": the key has an empty part"));
    YAML::Node node;
    node.reset(root);  // YAML::Node assignment would copy data into the tree: rebind with reset()
    std::string path;
    int line = 1;
    auto fail = [&](const std::string& why) {
      throw InputError(where(source.file, line, path.empty() ? o.key : path, why + " (in --set " + text + ")"));
    };
    // Line in the file of the value at `path` (a value set before has its mark from the --set text).
    auto lineHere = [&] {
      for (const auto& s : source.sets)
        if (s.path == path) return s.line;
      return node.IsDefined() && !node.Mark().is_null() ? node.Mark().line + 1 : line;
    };
    for (size_t i = 0; i < seg.size();) {
      const YAML::Node& cnode = node;  // const lookups never add placeholder keys
      line = lineHere();
      size_t used = 0;
      if (cnode.IsSequence()) {
        const size_t k = findEntry(cnode, seg, i, used);
        if (used == 0) {
          std::string names;
          for (size_t e = 0; e < cnode.size(); ++e) names += (e ? ", " : "") + listChildPath("", cnode[e], e);
          fail("no entry named '" + seg[i] + "' in " + (path.empty() ? "the case" : path) + " (entries: " + names +
               ")");
        }
        YAML::Node next = node[k];
        path = listChildPath(path, next, k);
        node.reset(next);
      } else if (cnode.IsMap() || cnode.IsNull()) {
        std::string key = seg[i];
        used = 1;
        for (size_t j = seg.size(); cnode.IsMap() && j > i + 1; --j)
          if (cnode[joinSegments(seg, i, j)].IsDefined()) {
            key = joinSegments(seg, i, j);
            used = j - i;
            break;
          }
        if (!cnode.IsMap()) node = YAML::Node(YAML::NodeType::Map);  // an empty value becomes a map
        if (i + used < seg.size() && !cnode[key].IsDefined()) node[key] = YAML::Node(YAML::NodeType::Map);
        YAML::Node next = node[key];
        path = mapChildPath(path, key);
        node.reset(next);
      } else {
        fail("'" + path + "' is a single value, it has no '" + seg[i] + "'");
      }
      i += used;
    }
    line = lineHere();
    const YAML::Node value = parseValue(o, source.file);
    if (value.IsScalar()) {
      node = o.value;  // in place: the value keeps its place in the file
      node.SetTag("?");
    } else {
      node = value;
    }
    source.sets.push_back({path, text, line});
  }
}

}  // namespace whirl
