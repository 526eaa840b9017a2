#pragma once
/// \file
/// The interactive Campbell report: one self-contained HTML file (no network) with the two-panel Campbell
/// diagram (frequency and damping ratio against rotor or wind speed, nP lines, unstable points ringed in
/// red), a tooltip per point (line and mode name, frequencies, damping, the name's evidence, the dominant
/// coordinates), a legend that toggles lines, the animated mode shape of a clicked point (tower, nacelle,
/// hub and blades as lines, with amplitude, phase and view sliders), the input summary and the steady
/// operating points. Its data are campbell_modes.json (src/writers/campbell_output.hpp) as written, numbers
/// rounded to 6 significant digits; d3 (v3) and three.js are inlined from Debian's libjs-d3 and
/// libjs-three (files under javascriptDir()).
#include <string>
#include <utility>
#include <vector>

namespace whirl {

struct CampbellReportOptions {
  std::vector<int> harmonics = {1, 3, 6, 9};  ///< nP lines
  bool versus_wind_speed = false;             ///< x axis wind speed (when every point has one)
  double max_freq_hz = 0;                     ///< top of the frequency axis; lines entirely above are left out; 0: auto
  bool first_order_lines = false;             ///< also draw lines made only of first-order roots
  std::vector<std::pair<std::string, std::string>> summary;  ///< the input table: (what, value)
  /// Text of a steady.csv (`whirl steady`) shown as the steady operating table; empty: the Campbell
  /// points' rotor speed, wind speed and pitch instead.
  std::string steady_csv;
};

/// The text of `dir`/steady.csv when the folder has one (`whirl steady` wrote it), else empty.
std::string steadyCsvIn(const std::string& dir);

/// The folder of Debian's JavaScript libraries: $WHIRL_JS_DIR when set, else /usr/share/javascript.
std::string javascriptDir();

/// The report page for the text of a campbell_modes.json.
/// Throws InputError when the JSON does not parse or lacks `title`, `lines` or `points`, or when
/// d3/d3.min.js or three/three.min.js is missing under javascriptDir() (install libjs-d3 libjs-three).
std::string campbellHtml(const std::string& modes_json, const CampbellReportOptions& opt,
                         const std::string& source = "campbell_modes.json");

namespace detail {
extern const char* const kCampbellHtmlPage;
}

}  // namespace whirl
