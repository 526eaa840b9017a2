#include "src/writers/discon_gains.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

#include "src/base/error.hpp"

namespace whirl {
namespace {

/// A line split at its '!' into the value field and the rest (comment and line end).
struct Line {
  std::string values, rest;
  bool has_comment = false;
};

Line splitLine(const std::string& s) {
  const size_t bang = s.find('!');
  if (bang == std::string::npos) return {s, "", false};
  return {s.substr(0, bang), s.substr(bang), true};
}

/// The first word after the '!': ROSCO's key of the line.
std::string keyOf(const Line& l) {
  std::istringstream in(l.rest.substr(1));
  std::string k;
  in >> k;
  return k;
}

std::string formatted(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

/// ROSCO's write_array: each value left-aligned in `width` columns and a blank, the whole padded.
std::string row(const std::vector<double>& v, const char* format, int width) {
  std::string s;
  for (double x : v) {
    std::string f = formatted(format, x);
    if (static_cast<int>(f.size()) < width) f.append(static_cast<size_t>(width) - f.size(), ' ');
    s += f + " ";
  }
  return s + "              ";  // write_DISCON: 14 blanks before the comment
}

bool allZero(const std::string& values) {
  std::istringstream in(values);
  for (std::string w; in >> w;)
    if (std::strtod(w.c_str(), nullptr) != 0) return false;
  return true;
}

}  // namespace

std::string disconWithGains(const std::string& text, const std::string& file, const GainSchedule& g) {
  std::vector<std::string> lines;
  for (size_t b = 0; b <= text.size();) {
    const size_t e = text.find('\n', b);
    if (e == std::string::npos) {
      if (b < text.size()) lines.push_back(text.substr(b));
      break;
    }
    lines.push_back(text.substr(b, e - b + 1));
    b = e + 1;
  }
  std::map<std::string, size_t> at;
  std::vector<std::string> keys = {"PC_GS_n",  "PC_GS_angles", "PC_GS_KP", "PC_GS_KI",
                                   "PC_GS_KD", "PC_GS_TF",     "VS_KP",    "VS_KI"};
  if (g.fl_mode > 0) keys.insert(keys.end(), {"Fl_Mode", "Fl_Kp", "Fl_U"});
  for (size_t i = 0; i < lines.size(); ++i) {
    const Line l = splitLine(lines[i]);
    if (!l.has_comment || l.values.find_first_not_of(" \t") == std::string::npos) continue;
    const std::string k = keyOf(l);
    for (const std::string& want : keys)
      if (k == want) {
        if (at.count(k)) throw InputError(where(file, static_cast<int>(i + 1), k, "given twice"));
        at[k] = i;
      }
  }
  for (const std::string& k : keys)
    if (!at.count(k)) throw InputError(where(file, 0, k, "missing: whirl tune replaces it"));
  auto replace = [&](const std::string& k, const std::string& values) {
    Line l = splitLine(lines[at[k]]);
    lines[at[k]] = values + l.rest;
  };
  const Line old_n = splitLine(lines[at["PC_GS_n"]]);
  const long n_old = std::strtol(old_n.values.c_str(), nullptr, 10);
  const size_t n = g.pitch.size();
  if (n_old != static_cast<long>(n)) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%-11zu         ", n);
    replace("PC_GS_n", buf);
    for (const char* k : {"PC_GS_KD", "PC_GS_TF"}) {
      if (!allZero(splitLine(lines[at[k]]).values))
        throw InputError(
            where(file, static_cast<int>(at[k] + 1), k,
                  "non-zero gains cannot follow a schedule of another length (" + std::to_string(n) + " angles)"));
      replace(k, row(std::vector<double>(n, 0.0), "%.3e", 12));
    }
  }
  replace("PC_GS_angles", row(g.pitch, "%.3f", 12));
  replace("PC_GS_KP", row(g.kp, "%.3e", 12));
  replace("PC_GS_KI", row(g.ki, "%.3e", 12));
  replace("VS_KP", formatted("%-14.5e", g.vs_kp) + "      ");
  replace("VS_KI", formatted("%-14.5e", g.vs_ki) + "      ");
  if (g.fl_mode > 0) {
    // One gain at one wind speed (Fl_n, when the file has it, must then be 1: ROSCO's default).
    char buf[32];
    std::snprintf(buf, sizeof buf, "%-20d", g.fl_mode);
    replace("Fl_Mode", buf);
    replace("Fl_Kp", formatted("%-20.4f", g.fl_kp));
    replace("Fl_U", formatted("%-20.4f", g.fl_wind));
    for (size_t i = 0; i < lines.size(); ++i) {
      const Line l = splitLine(lines[i]);
      if (l.has_comment && keyOf(l) == "Fl_n" && std::strtol(l.values.c_str(), nullptr, 10) != 1)
        lines[i] = std::string("1                   ") + l.rest;
    }
  }
  std::string out;
  for (const std::string& l : lines) out += l;
  return out;
}

}  // namespace whirl
