#include "src/io/text/time_signal_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "src/base/error.hpp"
#include "src/base/text.hpp"
#include "src/io/text/csv_table.hpp"

namespace whirl {
namespace {

std::string trim(std::string_view s) { return std::string(trimBlanks(s)); }

// "name(a,b,...)" with `count` finite numbers, or nullopt-like empty when the name differs.
bool parseCall(const std::string& text, const std::string& name, size_t count, const std::string& key,
               std::vector<double>& out) {
  if (text.rfind(name + "(", 0) != 0) return false;
  if (text.back() != ')')
    throw InputError(where("", 0, key, "'" + text + "': expected " + name + "(...) with a closing parenthesis"));
  std::string body = text.substr(name.size() + 1, text.size() - name.size() - 2) + ",";
  out.clear();
  for (size_t at = 0, comma; (comma = body.find(',', at)) != std::string::npos; at = comma + 1) {
    const std::string field = trim(body.substr(at, comma - at));
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(field, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (field.empty() || used != field.size() || !std::isfinite(v))
      throw InputError(where("", 0, key, "'" + text + "': '" + field + "' is not a finite number"));
    out.push_back(v);
  }
  if (out.size() != count)
    throw InputError(where("", 0, key,
                           "'" + text + "': " + name + " takes " + std::to_string(count) + " numbers, got " +
                               std::to_string(out.size())));
  return true;
}

}  // namespace

std::pair<std::string, std::string> splitAssignment(const std::string& text, const std::string& key) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || trim(text.substr(0, eq)).empty())
    throw InputError(where("", 0, key, "'" + text + "': expected NAME=VALUE"));
  return {trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
}

TimeSignal parseTimeSignal(const std::string& raw, const std::string& key) {
  const std::string text = trim(raw);
  if (text.empty())
    throw InputError(
        where("", 0, key, "empty signal: expected step(t0,a), ramp(t0,t1,a), sin(A,f), spinup(T,w) or a CSV file"));
  TimeSignal s;
  s.source = text;
  if (parseCall(text, "step", 2, key, s.parameters)) {
    s.kind = TimeSignal::Kind::Step;
    return s;
  }
  if (parseCall(text, "ramp", 3, key, s.parameters)) {
    s.kind = TimeSignal::Kind::Ramp;
    if (!(s.parameters[1] > s.parameters[0]))
      throw InputError(where("", 0, key, "'" + text + "': the ramp must end (t1) after it starts (t0)"));
    return s;
  }
  if (parseCall(text, "sin", 2, key, s.parameters)) {
    s.kind = TimeSignal::Kind::Sine;
    if (s.parameters[1] < 0) throw InputError(where("", 0, key, "'" + text + "': the frequency must be ≥ 0"));
    return s;
  }
  if (parseCall(text, "spinup", 2, key, s.parameters)) {
    s.kind = TimeSignal::Kind::Spinup;
    if (!(s.parameters[0] > 0)) throw InputError(where("", 0, key, "'" + text + "': the spin-up time T must be > 0"));
    return s;
  }
  if (text.find('(') != std::string::npos)
    throw InputError(
        where("", 0, key,
              "'" + text +
                  "': unknown signal; expected step(t0,a), ramp(t0,t1,a), sin(A,f), spinup(T,w) or a CSV file"));
  const CsvTable table = readCsv(text);
  if (table.names.size() < 2)
    throw InputError(where(text, table.header_line, "", "expected the columns time and value"));
  s.kind = TimeSignal::Kind::Table;
  s.time = table.columns[0];
  s.values = table.columns[1];
  if (s.time.empty()) throw InputError(where(text, table.header_line, table.names[0], "no rows"));
  for (size_t k = 1; k < s.time.size(); ++k)
    if (!(s.time[k] > s.time[k - 1]))
      throw InputError(where(text, table.row_lines[k], table.names[0],
                             fmt::format("time not increasing ({:g} after {:g})", s.time[k], s.time[k - 1])));
  return s;
}

}  // namespace whirl
