#include "src/io/openfast/servodyn/discon_input.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/openfast_input.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

// Every key of ROSCO v2.10's ReadControlParameterFileSub (ReadSetParameters.f90), and keys of earlier
// ROSCO versions that ROSCO itself now skips (it ignores lines it does not look for).
const std::set<std::string>& knownKeys() {
  static const std::set<std::string> keys = [] {
    const char* names[] = {
        "Echo", "LoggingLevel", "DT_Out", "Ext_Interface", "F_LPFType", "IPC_ControlMode", "VS_ControlMode",
        "VS_ConstPower", "VS_FBP", "PC_ControlMode", "Y_ControlMode", "SS_Mode", "PRC_Mode", "WE_Mode", "PS_Mode",
        "SU_Mode", "SD_Mode", "Fl_Mode", "TD_Mode", "TRA_Mode", "Flp_Mode", "OL_Mode", "PA_Mode", "PF_Mode", "AWC_Mode",
        "Ext_Mode", "ZMQ_Mode", "CC_Mode", "StC_Mode", "F_LPFCornerFreq", "F_LPFDamping", "F_NumNotchFilts",
        "F_NotchFreqs", "F_NotchBetaNum", "F_NotchBetaDen", "F_GenSpdNotch_N", "F_TwrTopNotch_N", "F_SSCornerFreq",
        "F_WECornerFreq", "F_YawErr", "F_FlCornerFreq", "F_FlHighPassFreq", "F_FlpCornerFreq", "F_VSRefSpdCornerFreq",
        "F_GenSpdNotch_Ind", "F_TwrTopNotch_Ind", "PC_GS_n", "PC_GS_angles", "PC_GS_KP", "PC_GS_KI", "PC_GS_KD",
        "PC_GS_TF", "PC_MaxPit", "PC_MinPit", "PC_MaxRat", "PC_MinRat", "PC_RefSpd", "PC_FinePit", "PC_Switch",
        "IPC_Vramp", "IPC_SatMode", "IPC_IntSat", "IPC_KP", "IPC_KI", "IPC_aziOffset", "IPC_CornerFreqAct", "VS_GenEff",
        "VS_ArSatTq", "VS_MaxRat", "VS_MaxTq", "VS_MinTq", "VS_MinOMSpd", "VS_Rgn2K", "VS_RtPwr", "VS_RtTq",
        "VS_RefSpd", "VS_n", "VS_KP", "VS_KI", "VS_TSRopt", "VS_FBP_n", "VS_FBP_U", "VS_FBP_Omega", "VS_FBP_Tau",
        "SS_VSGain", "SS_PCGain", "PRC_Comm", "PRC_R_Torque", "PRC_R_Speed", "PRC_R_Pitch", "PRC_Table_n",
        "PRC_R_Table", "PRC_Pitch_Table", "PRC_n", "PRC_LPF_Freq", "PRC_WindSpeeds", "PRC_GenSpeeds", "WE_BladeRadius",
        "WE_Gamma", "WE_GearboxRatio", "WE_Jtot", "WE_RhoAir", "PerfFileName", "PerfTableSize", "WE_FOPoles_N",
        "WE_FOPoles_v", "WE_FOPoles", "WE_CP_n", "WE_CP", "Y_uSwitch", "Y_ErrThresh", "Y_Rate", "Y_MErrSet",
        "Y_IPC_IntSat", "Y_IPC_KP", "Y_IPC_KI", "TRA_ExclSpeed", "TRA_ExclBand", "TRA_RateLimit", "FA_KI",
        "FA_HPFCornerFreq", "FA_IntSat", "PS_BldPitchMin_N", "PS_WindSpeeds", "PS_BldPitchMin", "SU_StartTime",
        "SU_FW_MinDuration", "SU_RotorSpeedThresh", "SU_RotorSpeedCornerFreq", "SU_LoadStages_N", "SU_LoadStages",
        "SU_LoadRampDuration", "SU_LoadHoldDuration", "SD_TimeActivate", "SD_EnablePitch", "SD_EnableYawError",
        "SD_EnableGenSpeed", "SD_EnableTime", "SD_MaxPit", "SD_PitchCornerFreq", "SD_MaxYawError",
        "SD_YawErrorCornerFreq", "SD_MaxGenSpd", "SD_GenSpdCornerFreq", "SD_Time", "SD_Method", "SD_Stage_N",
        "SD_StageTime", "SD_StagePitch", "SD_MaxTorqueRate", "SD_MaxPitchRate", "Fl_n", "Fl_Kp", "Fl_U", "Flp_Angle",
        "Flp_Kp", "Flp_Ki", "Flp_MaxPit", "OL_Filename", "OL_BP_Mode", "OL_BP_FiltFreq", "Ind_Breakpoint",
        "Ind_BldPitch", "Ind_GenTq", "Ind_YawRate", "Ind_Azimuth", "Ind_R_Speed", "Ind_R_Torque", "Ind_R_Pitch",
        "RP_Gains", "Ind_CableControl", "Ind_StructControl", "PA_CornerFreq", "PA_Damping", "PF_Offsets",
        "PF_TimeStuck", "AWC_NumModes", "AWC_n", "AWC_harmonic", "AWC_freq", "AWC_amp", "AWC_clockangle",
        "AWC_phaseoffset", "AWC_CntrGains", "DLL_FileName", "DLL_InFile", "DLL_ProcName", "ZMQ_ID", "ZMQ_CommAddress",
        "ZMQ_UpdatePeriod", "CC_Group_N", "CC_GroupIndex", "CC_ActTau", "StC_Group_N", "StC_GroupIndex",
        // Earlier versions (ROSCO 2.0–2.9 Examples): notch and yaw filters, power control, shutdown.
        "F_NotchCornerFreq", "F_NotchBetaNumDen", "F_NotchType", "IPC_omegaLP", "IPC_zetaLP", "IPC_omegaNotch",
        "IPC_zetaNotch", "Y_IPC_omegaLP", "Y_IPC_zetaLP", "Y_IPC_n", "Y_omegaLPFast", "Y_omegaLPSlow", "SD_CornerFreq",
        "PwC_Mode", "PwC_ConstPwr", "PwC_OpenLoop_Inp", "PwC_BldPitchMin_N", "Ind_Breakpoints"};
    std::set<std::string> s;
    for (const char* n : names) s.insert(toLower(n));
    return s;
  }();
  return keys;
}

struct Entry {
  std::string key;                  ///< as written
  std::vector<std::string> values;  ///< value words (quotes kept on strings)
  int line = 0;
};

bool isKeyChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The value words of a line: blanks and commas separate them (ROSCO's GetWords also splits at ';'),
// a quoted string is one word.
std::vector<std::string> valueWords(std::string_view s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == ' ' || c == '\t' || c == ',' || c == ';') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    if (c == '"' || c == '\'') {
      while (j < s.size() && s[j] != c) ++j;
      if (j < s.size()) ++j;
    } else {
      while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != ',' && s[j] != ';') ++j;
    }
    out.emplace_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

// The position of the '!' that ends the values (outside quotes), or npos.
std::size_t commentStart(std::string_view s) {
  char quote = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '!') {
      return i;
    }
  }
  return std::string_view::npos;
}

class DisconFile {
 public:
  DisconFile(const std::string& text, std::string file, OverrideSet* overrides) : file_(std::move(file)) {
    std::istringstream in(text);
    std::string raw;
    int lineno = 0;
    while (std::getline(in, raw)) {
      ++lineno;
      if (!raw.empty() && raw.back() == '\r') raw.pop_back();
      std::string_view t = raw;
      while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
      if (t.empty() || t.front() == '!') continue;  // blank, comment or section title
      for (char c : t)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
          throw InputError(where(file_, lineno, "", "control character in the line"));
      const std::size_t bang = commentStart(t);
      Entry e;
      e.line = lineno;
      std::string_view label;
      if (bang != std::string_view::npos) {
        e.values = valueWords(t.substr(0, bang));
        label = t.substr(bang + 1);
        while (!label.empty() && (label.front() == ' ' || label.front() == '\t')) label.remove_prefix(1);
      } else {
        // No '!': ROSCO's word after the values, i.e. the first word that is not a number or a string.
        std::vector<std::string> w = valueWords(t);
        std::size_t k = 0;
        while (k < w.size() && (parseFortranDouble(w[k]) || w[k].front() == '"' || w[k].front() == '\'')) ++k;
        if (k == w.size()) throw InputError(where(file_, lineno, "", "values without a key (write 'value ! Key')"));
        e.values.assign(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(k));
        label = t.substr(t.find(w[k]));
      }
      std::size_t n = 0;
      while (n < label.size() && isKeyChar(label[n])) ++n;
      e.key = std::string(label.substr(0, n));
      if (e.key.empty())
        throw InputError(where(file_, lineno, "", "no key after the values (write 'value ! Key - description')"));
      const std::string lower = toLower(e.key);
      if (!knownKeys().count(lower))
        throw InputError(
            where(file_, lineno, e.key, "not a key of ROSCO's DISCON.IN (ROSCO 2.10 or earlier): check the spelling"));
      if (e.values.empty()) throw InputError(where(file_, lineno, e.key, "no value before the key"));
      if (overrides)  // --set KEY=VALUE: the value as if written here (its line stays the key's)
        if (const std::optional<std::string> v = overrides->take(e.key, file_)) e.values = valueWords(*v);
      const auto [it, fresh] = index_.emplace(lower, entries_.size());
      if (!fresh)
        throw InputError(where(file_, lineno, e.key,
                               "given twice (first on line " + std::to_string(entries_[it->second].line) +
                                   "; ROSCO would take the last silently): keep one"));
      entries_.push_back(std::move(e));
    }
  }

  const Entry* find(const std::string& key) const {
    const auto it = index_.find(toLower(key));
    return it == index_.end() ? nullptr : &entries_[it->second];
  }

  /// Records where `key` was written in `c.where` (under ROSCO's spelling).
  void note(RoscoController& c, const std::string& key) const {
    if (const Entry* e = find(key)) c.where[key] = Where{file_, e->line, e->key, ""};
  }

  [[noreturn]] void missing(const std::string& key, const std::string& why) const {
    throw InputError(where(file_, 0, key, "missing (" + why + ")"));
  }

  double number(const Entry& e, const std::string& word) const {
    const std::optional<double> v = parseFortranDouble(word);
    if (!v) throw InputError(where(file_, e.line, e.key, "'" + word + "' is not a number"));
    if (!std::isfinite(*v)) throw InputError(where(file_, e.line, e.key, "'" + word + "' is not finite"));
    return *v;
  }

  /// A scalar; absent: `def` (ROSCO's default), or an error saying why the key is needed.
  double real(RoscoController& c, const std::string& key, std::optional<double> def, const char* why = "") const {
    const Entry* e = find(key);
    if (!e) {
      if (!def) missing(key, why);
      return *def;
    }
    if (e->values.size() != 1)
      throw InputError(where(file_, e->line, e->key, std::to_string(e->values.size()) + " values, expected one"));
    note(c, key);
    return number(*e, e->values[0]);
  }

  int integer(RoscoController& c, const std::string& key, std::optional<int> def, const char* why = "") const {
    const Entry* e = find(key);
    if (!e) {
      if (!def) missing(key, why);
      return *def;
    }
    const double v = real(c, key, std::nullopt);
    if (v != std::floor(v) || std::abs(v) > 1e9)
      throw InputError(where(file_, e->line, e->key, "'" + e->values[0] + "' is not an integer"));
    return static_cast<int>(v);
  }

  /// An array of `n` values (n from its count key `count_key`); absent: n zeros when `optional`.
  std::vector<double> array(RoscoController& c, const std::string& key, int n, const std::string& count_key,
                            bool optional, const char* why = "") const {
    const Entry* e = find(key);
    if (!e) {
      if (!optional) missing(key, why);
      return std::vector<double>(static_cast<std::size_t>(std::max(n, 1)), 0.0);
    }
    // A count of 0: ROSCO reads one placeholder value (FinalAryLen = 1, ParseDbAry_Opt) and uses none.
    if (n == 0) {
      note(c, key);
      return {};
    }
    if (static_cast<int>(e->values.size()) != n)
      throw InputError(where(file_, e->line, e->key,
                             std::to_string(e->values.size()) + " values, but " + count_key + " = " +
                                 std::to_string(n) + (n == 1 ? " expects 1" : " expects " + std::to_string(n))));
    note(c, key);
    std::vector<double> out;
    for (const std::string& w : e->values) out.push_back(number(*e, w));
    return out;
  }

  const std::string& file() const { return file_; }
  int lineOf(const std::string& key) const {
    const Entry* e = find(key);
    return e ? e->line : 0;
  }

 private:
  std::string file_;
  std::vector<Entry> entries_;
  std::unordered_map<std::string, std::size_t> index_;
};

// CONTROLLER FLAGS: the modes of the filters, the torque and pitch control, the setpoint smoother,
// the minimum pitch, the floating feedback, the pitch actuator and the wind-speed estimator.
void readDisconFlags(const DisconFile& f, RoscoController& c) {
  auto flag = [&](const char* key, int def = 0) { return f.integer(c, key, def); };
  c.F_LPFType = flag("F_LPFType");
  c.VS_ControlMode = f.integer(c, "VS_ControlMode", std::nullopt, "whirl needs the torque control mode");
  c.VS_ConstPower = flag("VS_ConstPower");
  c.PC_ControlMode = f.integer(c, "PC_ControlMode", std::nullopt, "whirl needs the pitch control mode");
  c.SS_Mode = flag("SS_Mode");
  c.PS_Mode = flag("PS_Mode");
  c.Fl_Mode = flag("Fl_Mode");
  c.PA_Mode = flag("PA_Mode");
  c.WE_Mode = flag("WE_Mode");
}

// FILTERS, the notches: F_NumNotchFilts notch filters (frequency [rad/s], numerator and denominator
// damping), and the generator-speed and tower-top signals' lists of them by index.
void readDisconNotches(const DisconFile& f, RoscoController& c) {
  const int notches = f.integer(c, "F_NumNotchFilts", 0);
  if (notches < 0)
    throw InputError(where(f.file(), f.lineOf("F_NumNotchFilts"), "F_NumNotchFilts", "must not be negative"));
  const bool no_notch = notches == 0;
  const std::vector<double> freqs = f.array(c, "F_NotchFreqs", notches, "F_NumNotchFilts", no_notch,
                                            "F_NumNotchFilts > 0");
  const std::vector<double> num = f.array(c, "F_NotchBetaNum", notches, "F_NumNotchFilts", no_notch,
                                          "F_NumNotchFilts > 0");
  const std::vector<double> den = f.array(c, "F_NotchBetaDen", notches, "F_NumNotchFilts", no_notch,
                                          "F_NumNotchFilts > 0");
  auto notchList = [&](const char* count_key, const char* index_key, std::vector<RoscoNotch>& out) {
    const int n = f.integer(c, count_key, 0);
    if (n < 0 || n > notches)
      throw InputError(where(f.file(), f.lineOf(count_key), count_key,
                             "must be between 0 and F_NumNotchFilts = " + std::to_string(notches)));
    if (n == 0) return;
    for (double k : f.array(c, index_key, n, count_key, false, "the indices of the notch filters")) {
      if (k != std::floor(k) || k < 1 || k > notches)
        throw InputError(where(f.file(), f.lineOf(index_key), index_key,
                               "index " + numberText(k) + " is not a notch filter 1 to " + std::to_string(notches)));
      const std::size_t i = static_cast<std::size_t>(k) - 1;
      out.push_back({freqs[i], num[i], den[i]});
    }
  };
  notchList("F_GenSpdNotch_N", "F_GenSpdNotch_Ind", c.gen_speed_notches);
  notchList("F_TwrTopNotch_N", "F_TwrTopNotch_Ind", c.twr_top_notches);
}

// FILTERS: the generator-speed low pass, the notches, the setpoint smoother's, wind-speed estimator's
// and torque reference's low passes, and the floating feedback's filters (corner frequencies [rad/s]).
void readDisconFilters(const DisconFile& f, RoscoController& c) {
  c.F_LPFCornerFreq = f.real(c, "F_LPFCornerFreq", std::nullopt, "the generator-speed filter's corner frequency");
  c.F_LPFDamping = f.real(c, "F_LPFDamping", c.F_LPFType == 1 ? std::optional<double>(0.0) : std::nullopt,
                          "F_LPFType = 2 needs the filter's damping");
  readDisconNotches(f, c);
  c.F_SSCornerFreq = f.real(c, "F_SSCornerFreq", c.SS_Mode == 0 ? std::optional<double>(0.0) : std::nullopt,
                            "SS_Mode = 1 needs the setpoint smoother's filter");
  c.F_WECornerFreq = f.real(c, "F_WECornerFreq", 0.0);
  c.F_VSRefSpdCornerFreq = f.real(c, "F_VSRefSpdCornerFreq", 0.0);
  {
    const std::vector<double> fl = f.array(c, "F_FlCornerFreq", 2, "its definition (frequency, damping)",
                                           c.Fl_Mode == 0, "Fl_Mode > 0 needs the floating feedback's filter");
    c.F_FlCornerFreq = fl[0];
    c.F_FlCornerDamp = fl.size() > 1 ? fl[1] : 0.0;
  }
  c.F_FlHighPassFreq = f.real(c, "F_FlHighPassFreq", c.Fl_Mode == 0 ? std::optional<double>(0.0) : std::nullopt,
                              "Fl_Mode > 0 needs the floating feedback's high-pass filter");
}

// BLADE PITCH CONTROL: the gain schedule (PC_ControlMode = 1), pitch limits [rad], rates [rad/s] and
// the rated generator speed [rad/s] (0 when the pitch control is off).
void readDisconPitchControl(const DisconFile& f, RoscoController& c) {
  if (c.PC_ControlMode != 0) {
    const char* why = "PC_ControlMode = 1 needs the pitch controller's schedule";
    const int n = f.integer(c, "PC_GS_n", std::nullopt, why);
    if (n < 1) throw InputError(where(f.file(), f.lineOf("PC_GS_n"), "PC_GS_n", "must be greater than 0"));
    c.PC_GS_angles = f.array(c, "PC_GS_angles", n, "PC_GS_n", false, why);
    c.PC_GS_KP = f.array(c, "PC_GS_KP", n, "PC_GS_n", false, why);
    c.PC_GS_KI = f.array(c, "PC_GS_KI", n, "PC_GS_n", false, why);
    const std::vector<double> kd = f.array(c, "PC_GS_KD", n, "PC_GS_n", true);
    if (std::any_of(kd.begin(), kd.end(), [](double v) { return v != 0.0; }))
      c.notes.push_back(where(f.file(), f.lineOf("PC_GS_KD"), "PC_GS_KD",
                              "derivative pitch gains not modelled: the linear model's pitch controller is PI"));
  }
  const bool pc_off = c.PC_ControlMode == 0;
  const char* pwhy = "PC_ControlMode = 1 needs it";
  auto pc = [&](const char* key) { return f.real(c, key, pc_off ? std::optional<double>(0.0) : std::nullopt, pwhy); };
  c.PC_MaxPit = pc("PC_MaxPit");
  c.PC_MinPit = pc("PC_MinPit");
  c.PC_MaxRat = pc("PC_MaxRat");
  c.PC_MinRat = pc("PC_MinRat");
  c.PC_RefSpd = pc("PC_RefSpd");
  c.PC_FinePit = pc("PC_FinePit");
  c.PC_Switch = pc("PC_Switch");
}

// VS TORQUE CONTROL: efficiency, torque limits [N m], speeds [rad/s], the region-2 constant, rated
// power and torque, the PI gains and the optimal tip-speed ratio.
void readDisconTorqueControl(const DisconFile& f, RoscoController& c) {
  const char* vwhy = "the torque controller needs it";
  c.VS_GenEff = f.real(c, "VS_GenEff", std::nullopt, vwhy) / 100.0;
  c.VS_ArSatTq = f.real(c, "VS_ArSatTq", c.VS_ControlMode != 1 ? std::optional<double>(0.0) : std::nullopt,
                        "VS_ControlMode = 1 needs the region-2½ torque saturation");
  c.VS_MaxRat = f.real(c, "VS_MaxRat", c.VS_ControlMode != 1 ? std::optional<double>(0.0) : std::nullopt,
                       "VS_ControlMode = 1 needs the torque rate limit");
  c.VS_MaxTq = f.real(c, "VS_MaxTq", std::nullopt, vwhy);
  c.VS_MinTq = f.real(c, "VS_MinTq", std::nullopt, vwhy);
  c.VS_MinOMSpd = f.real(c, "VS_MinOMSpd", 0.0);
  c.VS_Rgn2K = f.real(c, "VS_Rgn2K", c.VS_ControlMode == 2 ? std::optional<double>(0.0) : std::nullopt,
                      "VS_ControlMode 1, 3 and 4 need the region-2 constant");
  c.VS_RtPwr = f.real(c, "VS_RtPwr", std::nullopt, vwhy);
  c.VS_RtTq = f.real(c, "VS_RtTq", std::nullopt, vwhy);
  c.VS_RefSpd = f.real(c, "VS_RefSpd", std::nullopt, vwhy);
  const int vs_n = f.integer(c, "VS_n", std::nullopt, vwhy);
  if (vs_n < 1) throw InputError(where(f.file(), f.lineOf("VS_n"), "VS_n", "must be greater than 0"));
  c.VS_KP = f.array(c, "VS_KP", vs_n, "VS_n", false, vwhy);
  c.VS_KI = f.array(c, "VS_KI", vs_n, "VS_n", false, vwhy);
  c.VS_TSRopt = f.real(c, "VS_TSRopt", c.VS_ControlMode < 2 ? std::optional<double>(0.0) : std::nullopt,
                       "TSR tracking (VS_ControlMode >= 2) needs the optimal tip-speed ratio");
}

// SETPOINT SMOOTHER: its gains on the torque and pitch loops' references (SS_Mode = 1).
void readDisconSetpointSmoother(const DisconFile& f, RoscoController& c) {
  c.SS_VSGain = f.real(c, "SS_VSGain", c.SS_Mode == 0 ? std::optional<double>(0.0) : std::nullopt,
                       "SS_Mode = 1 needs it");
  c.SS_PCGain = f.real(c, "SS_PCGain", c.SS_Mode == 0 ? std::optional<double>(0.0) : std::nullopt,
                       "SS_Mode = 1 needs it");
}

// WIND SPEED ESTIMATOR: the rotor radius [m] and the gearbox ratio whirl uses.
void readDisconWindEstimator(const DisconFile& f, RoscoController& c) {
  c.WE_BladeRadius = f.real(c, "WE_BladeRadius", std::nullopt, "the tip-speed ratio needs the rotor radius");
  c.WE_GearboxRatio = f.real(c, "WE_GearboxRatio", std::nullopt, "whirl needs the gearbox ratio");
}

// MINIMUM PITCH SATURATION (peak shaving): the minimum pitch [rad] per wind speed [m/s] (PS_Mode = 1).
void readDisconMinimumPitch(const DisconFile& f, RoscoController& c) {
  if (c.PS_Mode != 0) {
    const char* why = "PS_Mode = 1 needs the minimum-pitch table";
    const int n = f.integer(c, "PS_BldPitchMin_N", std::nullopt, why);
    if (n < 1)
      throw InputError(where(f.file(), f.lineOf("PS_BldPitchMin_N"), "PS_BldPitchMin_N", "must be greater than 0"));
    c.PS_WindSpeeds = f.array(c, "PS_WindSpeeds", n, "PS_BldPitchMin_N", false, why);
    c.PS_BldPitchMin = f.array(c, "PS_BldPitchMin", n, "PS_BldPitchMin_N", false, why);
  }
}

// Floating: the platform feedback's gains, scheduled on wind speed [m/s] when Fl_n > 1.
void readDisconFloating(const DisconFile& f, RoscoController& c) {
  const int fl_n = f.integer(c, "Fl_n", 1);
  if (fl_n < 1) throw InputError(where(f.file(), f.lineOf("Fl_n"), "Fl_n", "must be greater than 0"));
  c.Fl_Kp = f.array(c, "Fl_Kp", fl_n, "Fl_n", c.Fl_Mode == 0, "Fl_Mode > 0 needs the feedback gain");
  c.Fl_U = f.array(c, "Fl_U", fl_n, "Fl_n", fl_n == 1, "Fl_n > 1 needs the wind speeds of the Fl_Kp schedule");
}

// Pitch Actuator Model: its corner frequency [rad/s] and damping (PA_Mode > 0).
void readDisconPitchActuator(const DisconFile& f, RoscoController& c) {
  c.PA_CornerFreq = f.real(c, "PA_CornerFreq", c.PA_Mode == 0 ? std::optional<double>(0.0) : std::nullopt,
                           "PA_Mode > 0 needs the actuator's corner frequency");
  c.PA_Damping = f.real(c, "PA_Damping", c.PA_Mode == 0 ? std::optional<double>(0.0) : std::nullopt,
                        "PA_Mode > 0 needs the actuator's damping");
}

// The parameters whirl reads from DISCON.IN, one function per section of ROSCO's file, in the file's order.
// ROSCO's defaults are those of ReadSetParameters.f90: a key read with CheckOptional true (or without
// it) takes 0 when missing; `need` states why a key whose mode needs it may not be missing.
void readDisconParameters(const DisconFile& f, RoscoController& c) {
  readDisconFlags(f, c);
  readDisconFilters(f, c);
  readDisconPitchControl(f, c);
  readDisconTorqueControl(f, c);
  readDisconSetpointSmoother(f, c);
  readDisconWindEstimator(f, c);
  readDisconMinimumPitch(f, c);
  readDisconFloating(f, c);
  readDisconPitchActuator(f, c);
}

bool nonDecreasing(const std::vector<double>& v) { return std::is_sorted(v.begin(), v.end()); }

// ReadSetParameters.f90, CheckInputs: the checks of the parameters whirl uses, with ROSCO's wording.
void checkDiscon(const DisconFile& f, RoscoController& c) {
  auto fail = [&](const char* key, const std::string& reason) {
    throw InputError(where(f.file(), f.lineOf(key), key, reason));
  };
  auto oneOf = [&](const char* key, int v, int lo, int hi) {
    if (v < lo || v > hi)
      fail(key, "must be " + std::to_string(lo) + " to " + std::to_string(hi) + " (is " + std::to_string(v) + ")");
  };
  oneOf("F_LPFType", c.F_LPFType, 1, 2);
  oneOf("VS_ControlMode", c.VS_ControlMode, 0, 4);
  oneOf("VS_ConstPower", c.VS_ConstPower, 0, 1);
  oneOf("PC_ControlMode", c.PC_ControlMode, 0, 1);
  oneOf("SS_Mode", c.SS_Mode, 0, 1);
  oneOf("PS_Mode", c.PS_Mode, 0, 1);
  oneOf("Fl_Mode", c.Fl_Mode, 0, 2);
  oneOf("PA_Mode", c.PA_Mode, 0, 2);
  oneOf("WE_Mode", c.WE_Mode, 0, 2);
  if (!(c.F_LPFCornerFreq > 0)) fail("F_LPFCornerFreq", "must be greater than zero");
  if (c.F_LPFType == 2 && !(c.F_LPFDamping > 0)) fail("F_LPFDamping", "must be greater than zero");
  for (const auto* list : {&c.gen_speed_notches, &c.twr_top_notches})
    for (const RoscoNotch& n : *list) {
      if (!(n.freq > 0)) fail("F_NotchFreqs", "must be greater than zero");
      if (!(n.beta_den > 0)) fail("F_NotchBetaDen", "must be greater than zero");
    }
  if (c.SS_Mode == 1 && !(c.F_SSCornerFreq > 0)) fail("F_SSCornerFreq", "must be greater than zero");
  if (c.Fl_Mode > 0) {
    if (!(c.F_FlCornerFreq > 0)) fail("F_FlCornerFreq", "the frequency (first value) must be greater than zero");
    if (!(c.F_FlCornerDamp > 0)) fail("F_FlCornerFreq", "the damping (second value) must be greater than zero");
    if (!(c.F_FlHighPassFreq > 0)) fail("F_FlHighPassFreq", "must be greater than zero");
  }
  if (c.VS_ControlMode >= 2 && !(c.F_VSRefSpdCornerFreq > 0)) fail("F_VSRefSpdCornerFreq", "must be greater than zero");
  if (c.PC_ControlMode == 1) {
    if (!nonDecreasing(c.PC_GS_angles)) fail("PC_GS_angles", "must be non-decreasing");
    if (!(c.PC_MinPit < c.PC_MaxPit)) fail("PC_MinPit", "must be less than PC_MaxPit");
    if (!(c.PC_RefSpd > 0)) fail("PC_RefSpd", "must be greater than zero");
    if (!(c.PC_MaxRat > 0)) fail("PC_MaxRat", "must be greater than zero");
    if (!(c.PC_MinRat < 0)) fail("PC_MinRat", "must be less than zero");
  }
  if (c.VS_ControlMode == 1 && !(c.VS_MaxRat > 0)) fail("VS_MaxRat", "must be greater than zero");
  if (c.VS_Rgn2K < 0) fail("VS_Rgn2K", "must not be negative");
  if (c.VS_RtTq > c.VS_MaxTq) fail("VS_RtTq", "must not be greater than VS_MaxTq");
  if (c.VS_RtPwr < 0) fail("VS_RtPwr", "must not be negative");
  if (c.VS_RtTq < 0) fail("VS_RtTq", "must not be negative");
  if (!(c.VS_GenEff > 0 && c.VS_GenEff <= 1)) fail("VS_GenEff", "must be in (0, 100] %");
  if (!(c.VS_RefSpd > 0)) fail("VS_RefSpd", "must be greater than zero");
  if (c.VS_MinOMSpd < 0 || c.VS_MinOMSpd > c.VS_RefSpd) fail("VS_MinOMSpd", "must be between 0 and VS_RefSpd");
  if (c.VS_KP.front() > 0) fail("VS_KP", "must be less than zero");
  if (c.VS_KI.front() > 0) fail("VS_KI", "must be less than zero");
  if (c.VS_ControlMode >= 2 && !(c.VS_TSRopt > 0)) fail("VS_TSRopt", "must be greater than zero");
  if (c.SS_Mode == 1) {
    if (!(c.SS_VSGain > 0)) fail("SS_VSGain", "must be greater than zero");
    if (!(c.SS_PCGain > 0)) fail("SS_PCGain", "must be greater than zero");
  }
  if (!(c.WE_BladeRadius > 0)) fail("WE_BladeRadius", "must be greater than zero");
  if (!(c.WE_GearboxRatio > 0)) fail("WE_GearboxRatio", "must be greater than zero");
  if (c.PS_Mode == 1 && !nonDecreasing(c.PS_WindSpeeds)) fail("PS_WindSpeeds", "must be non-decreasing");
  if (c.Fl_Kp.size() > 1 && !nonDecreasing(c.Fl_U)) fail("Fl_U", "must be non-decreasing");
  if (c.PA_Mode > 0 && !(c.PA_CornerFreq > 0)) fail("PA_CornerFreq", "must be greater than zero");
  if (c.PA_Mode == 2 && !(c.PA_Damping > 0)) fail("PA_Damping", "must be greater than zero");
}

// The active modes whirl does not model, each with what the linear model and the trim assume instead.
void noteDisconModes(const DisconFile& f, RoscoController& c) {
  struct Mode {
    const char* key;
    const char* what;
  };
  static const Mode modes[] = {
      {"IPC_ControlMode",
       "individual pitch control not modelled: collective pitch only (IPC adds no mean pitch in a steady state)"},
      {"Y_ControlMode", "yaw control not modelled: the nacelle yaw is held where the deck puts it"},
      {"VS_FBP", "fixed-pitch region-3 torque control not modelled: whirl's region 3 pitches to feather"},
      {"PRC_Mode", "power reference tracking not modelled: rated power and speed as written"},
      {"SU_Mode", "start-up not modelled: the turbine is in power production"},
      {"SD_Mode", "shut-down not modelled: the turbine is in power production"},
      {"TD_Mode", "tower fore-aft damper not modelled: no tower-acceleration feedback"},
      {"TRA_Mode", "tower-resonance avoidance not modelled: the torque loop's speed reference is not shifted"},
      {"Flp_Mode", "flap control not modelled: no flaps"},
      {"OL_Mode", "open-loop control not modelled: the closed loop as written"},
      {"PF_Mode", "pitch faults not modelled: every blade follows the command"},
      {"AWC_Mode", "active wake control not modelled: no periodic pitch forcing"},
      {"Ext_Mode", "external controller library not called: ROSCO's own laws only"},
      {"ZMQ_Mode", "ZeroMQ interface not modelled: no external set points"},
      {"CC_Mode", "cable control not modelled"},
      {"StC_Mode", "structural control not modelled"},
  };
  for (const Mode& m : modes) {
    const int v = f.integer(c, m.key, 0);
    if (v != 0) c.notes.push_back(where(f.file(), f.lineOf(m.key), m.key, std::to_string(v) + ": " + m.what));
  }
  // Modelled with an assumption, said once.
  if (c.WE_Mode > 0)
    c.notes.push_back(where(f.file(), f.lineOf("WE_Mode"), "WE_Mode",
                            std::to_string(c.WE_Mode) +
                                ": the wind-speed estimator's dynamics are not modelled: its estimate is taken equal "
                                "to the hub-height wind (its steady state)"));
  if (c.VS_ControlMode == 0)
    c.notes.push_back(where(f.file(), f.lineOf("VS_ControlMode"), "VS_ControlMode",
                            "0: no torque control: the generator torque is zero, so whirl cannot trim along the wind"));
}

}  // namespace

RoscoController parseDiscon(const std::string& text, const std::filesystem::path& file, OverrideSet* overrides) {
  const DisconFile f(text, file.string(), overrides);
  RoscoController c;
  c.file = file.string();
  readDisconParameters(f, c);
  checkDiscon(f, c);
  noteDisconModes(f, c);
  return c;
}

std::optional<RoscoController> readServoDynController(const ServoDynInput& servo, OverrideSet* overrides) {
  const OpenFastFile& f = servo.source;
  if (servo.VSContrl.value_or(0) != 5 || !f.has("DLL_InFile")) return std::nullopt;
  const std::filesystem::path file = f.getPath("DLL_InFile");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  RoscoController c = readDiscon(file, overrides);
  if (servo.PCMode.value_or(0) != 5 && c.PC_ControlMode != 0) {
    c.PC_ControlMode = 0;
    c.notes.push_back(f.where("PCMode", std::to_string(servo.PCMode.value_or(0)) +
                                            ": the pitch is not the controller's: held at PC_FinePit"));
  }
  return c;
}

std::optional<RoscoController> readDeckController(const std::filesystem::path& deck,
                                                  const std::vector<std::string>& sets) {
  if (toLower(deck.extension().string()) != ".fst") return std::nullopt;
  std::vector<KeyOverride> overrides;
  for (const std::string& s : sets) overrides.push_back(parseOverride(s));
  OverrideSet set(std::move(overrides));
  const FstInput fst = readFst(deck, &set);
  if (fst.CompServo == 0) return std::nullopt;
  const std::optional<ServoDynInput> servo = readServoDynIfEnabled(fst, &set);
  if (!servo) return std::nullopt;
  return readServoDynController(*servo, &set);
}

RoscoController readDiscon(const std::filesystem::path& file, OverrideSet* overrides) {
  std::string text;  // the one preamble of every input file (regular files only, size bounded)
  if (!readInputFile(file.string(), text)) throw InputError(where(file.string(), 0, "", "cannot open file"));
  return parseDiscon(text, file, overrides);
}

}  // namespace whirl::io
