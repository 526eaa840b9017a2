// The interactive Campbell report (src/writers/campbell_html.hpp): campbell_modes.json, compacted, in the
// page of campbell_html_page.cpp with d3 and three.js inlined.
#include "src/writers/campbell_html.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "src/base/error.hpp"

namespace whirl {
namespace {

using json = nlohmann::ordered_json;

// Every number to 6 significant digits: the page shows and animates, it does not compute; the file
// shrinks to about a third.
void roundNumbers(json& j) {
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (v != 0 && std::isfinite(v)) {
      const double scale = std::pow(10.0, 5 - std::floor(std::log10(std::abs(v))));
      j = std::round(v * scale) / scale;
    }
  } else if (j.is_structured()) {
    for (auto& e : j) roundNumbers(e);
  }
}

std::string readLibrary(const std::string& rel) {
  const std::string path = javascriptDir() + "/" + rel;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(
        where(path, 0, "", "not found: the HTML report inlines it (Debian: apt-get install libjs-d3 libjs-three)"));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// JSON inside a <script> element: "</" would end the element early.
std::string scriptSafe(std::string s) {
  for (std::size_t at = s.find("</"); at != std::string::npos; at = s.find("</", at + 3)) s.replace(at, 2, "<\\/");
  return s;
}

std::string htmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// The template with each @@KEY@@ replaced by values[KEY]; the values are not searched again.
std::string fillTemplate(const std::string& page, const std::map<std::string, std::string>& values) {
  std::string out;
  std::size_t pos = 0;
  while (true) {
    const std::size_t a = page.find("@@", pos);
    const std::size_t b = a == std::string::npos ? a : page.find("@@", a + 2);
    if (b == std::string::npos) break;
    const auto v = values.find(page.substr(a + 2, b - a - 2));
    if (v == values.end()) {
      out += page.substr(pos, a + 2 - pos);
      pos = a + 2;
      continue;
    }
    out += page.substr(pos, a - pos) + v->second;
    pos = b + 2;
  }
  return out + page.substr(pos);
}

}  // namespace

std::string steadyCsvIn(const std::string& dir) {
  std::ifstream in(dir + "/steady.csv", std::ios::binary);
  if (!in) return "";
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string javascriptDir() {
  const char* env = std::getenv("WHIRL_JS_DIR");
  return env && *env ? std::string(env) : std::string("/usr/share/javascript");
}

std::string campbellHtml(const std::string& modes_json, const CampbellReportOptions& opt, const std::string& source) {
  json data = json::parse(modes_json, nullptr, false);
  if (data.is_discarded() || !data.is_object())
    throw InputError(where(source, 0, "", "not a JSON object (campbell_modes.json)"));
  for (const char* key : {"title", "lines", "points"})
    if (!data.contains(key)) throw InputError(where(source, 0, key, "missing: not a campbell_modes.json of whirl"));
  if (!data["title"].is_string() || !data["lines"].is_array() || !data["points"].is_array())
    throw InputError(
        where(source, 0, "", "title, lines or points of the wrong type: not a campbell_modes.json of whirl"));
  roundNumbers(data);
  json o;
  o["harmonics"] = opt.harmonics;
  o["versus_wind_speed"] = opt.versus_wind_speed;
  o["max_freq_hz"] = opt.max_freq_hz;
  o["first_order_lines"] = opt.first_order_lines;
  o["steady_csv"] = opt.steady_csv;
  o["summary"] = json::array();
  for (const auto& [k, v] : opt.summary) o["summary"].push_back({k, v});
  return fillTemplate(detail::kCampbellHtmlPage,
                      {{"TITLE", htmlEscape(data["title"].get<std::string>())},
                       {"DATA", scriptSafe(data.dump(-1, ' ', false, json::error_handler_t::replace))},
                       {"OPTIONS", scriptSafe(o.dump(-1, ' ', false, json::error_handler_t::replace))},
                       {"D3", readLibrary("d3/d3.min.js")},
                       {"THREE", readLibrary("three/three.min.js")}});
}

}  // namespace whirl
