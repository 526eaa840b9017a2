#include "modal/mbc_lin.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <map>
#include <optional>
#include <regex>

#include "src/base/error.hpp"

namespace whirl {
namespace {

struct BladeMatch {
  int blade = 0;       ///< 1-based, 0 = none
  std::string masked;  ///< description with the blade number replaced by '#'
};

BladeMatch matchBlade(const std::string& d) {
  static const std::regex patterns[] = {std::regex(R"([Bb]lade\s*[Rr]oot\s*(\d+))"), std::regex(R"([Bb]lade\s*(\d+))"),
                                        std::regex(R"(BD_(\d+))"), std::regex(R"(\b[Bb](\d+))")};
  std::size_t pos = std::string::npos, len = 0;
  for (const auto& re : patterns) {
    if (std::smatch m; std::regex_search(d, m, re)) {
      pos = static_cast<std::size_t>(m.position(1)), len = static_cast<std::size_t>(m.length(1));
      break;
    }
  }
  if (pos == std::string::npos) {  // trailing digits of the channel name: "ED RootMxc1, (kN-m)"
    const std::size_t b = d.find_first_not_of(' ', d.find(' '));
    if (d.find(' ') != std::string::npos && b != std::string::npos) {
      std::size_t e = d.find_first_of(" ,", b);
      if (e == std::string::npos) e = d.size();
      std::size_t s = e;
      while (s > b && std::isdigit(static_cast<unsigned char>(d[s - 1]))) --s;
      if (s < e && s > b) pos = s, len = e - s;
    }
  }
  BladeMatch r;
  if (pos == std::string::npos) return r;
  // A number too large for an int reads as INT_MAX: mbcLayoutFromLin rejects it with the line.
  if (std::from_chars(d.data() + pos, d.data() + pos + len, r.blade).ec != std::errc())
    r.blade = std::numeric_limits<int>::max();
  r.masked = d.substr(0, pos) + "#" + d.substr(pos + len);
  // ElastoDyn repeats the blade in the internal DOF index, "DOF_BF(2,1)".
  const std::string idx = "(" + std::to_string(r.blade) + ",";
  for (std::size_t at = r.masked.find(idx); at != std::string::npos; at = r.masked.find(idx, at + 1))
    r.masked.replace(at, idx.size(), "(#,");
  return r;
}

std::string firstWord(const std::string& s) { return s.substr(0, s.find(' ')); }

constexpr const char* kRate = "First time derivative of ";

/// The description without the rate wording and the unit: "ED First time derivative of 1st tower
/// fore-aft bending mode DOF (…), m/s" and "ED 1st tower fore-aft bending mode DOF (…), m" give the
/// same key.
std::string pairingKey(std::string d) {
  if (const auto at = d.find(kRate); at != std::string::npos) d.erase(at, std::string(kRate).size());
  if (const auto comma = d.rfind(", "); comma != std::string::npos && d.find_first_of("()", comma) == std::string::npos)
    d.erase(comma);
  return d;
}

std::vector<int> velocityOf(const OpenFastLin& lin) {
  const auto& x = lin.x;
  const std::size_t n = x.size();
  std::vector<int> vel(n, -1);
  // As MBC3 pairs them: a rate state names the displacement it is the derivative of, wherever that
  // sits (ElastoDyn q, q̇ then BeamDyn q, q̇); only states of derivative order 2 (or files without
  // that column) pair.
  std::map<std::string, std::vector<std::size_t>> displacement;
  auto second = [&](std::size_t k) { return x[k].derivative_order == 2 || x[k].derivative_order < 0; };
  for (std::size_t k = 0; k < n; ++k)
    if (second(k) && x[k].description.find(kRate) == std::string::npos)
      displacement[pairingKey(x[k].description)].push_back(k);
  std::vector<bool> matched(n, false);
  for (std::size_t k = 0; k < n; ++k) {
    if (!second(k) || x[k].description.find(kRate) == std::string::npos) continue;
    auto it = displacement.find(pairingKey(x[k].description));
    if (it == displacement.end() || it->second.empty()) continue;
    vel[k] = static_cast<int>(it->second.front());
    matched[k] = matched[it->second.front()] = true;
    it->second.erase(it->second.begin());
  }
  // Descriptions that do not name their displacement: a run of consecutive states of one module with
  // derivative order 2 is split in halves, state k of the second half being the rate of state k of the first.
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j < n && firstWord(x[j].description) == firstWord(x[i].description)) ++j;
    const std::size_t len = j - i, h = len / 2;
    bool halves = len % 2 == 0 && len > 0;
    for (std::size_t k = i; halves && k < j; ++k) {
      const bool rate = x[k].description.find("First time derivative of") != std::string::npos;
      halves = !matched[k] && (x[k].derivative_order >= 0 ? x[k].derivative_order == 2 : rate == (k >= i + h));
    }
    if (halves)
      for (std::size_t k = 0; k < h; ++k) vel[i + h + k] = static_cast<int>(i + k);
    i = j;
  }
  return vel;
}

/// Blade (0-based, −1 fixed) of each entry of a table; checks that the sets pair like entries.
/// left_out: null = an entry that does not pair is an InputError; otherwise such entries (a channel
/// listed twice for one blade, a channel of one blade only) stay in the fixed frame and are listed.
std::vector<int> bladesOf(const OpenFastLin& lin, const std::vector<LinVariable>& vars, const std::vector<int>& vel,
                          int N, const std::string& key, std::vector<std::size_t>* left_out = nullptr) {
  std::vector<int> blade(vars.size(), -1);
  std::vector<std::string> masked(vars.size());
  for (std::size_t i = 0; i < vars.size(); ++i) {
    if (!vars[i].rotating) continue;
    const BladeMatch m = matchBlade(vars[i].description);
    if (m.blade < 1 || m.blade > N)
      throw InputError(where(lin.path, vars[i].line, key,
                             m.blade < 1 ? "rotating entry without a blade number: '" + vars[i].description + "'"
                                         : "blade " + std::to_string(m.blade) + " of a " + std::to_string(N) +
                                               "-bladed rotor: '" + vars[i].description + "'"));
    blade[i] = m.blade - 1;
    masked[i] = m.masked;
  }
  auto perBlade = [&] {
    std::vector<std::vector<std::pair<std::size_t, std::string>>> per(static_cast<std::size_t>(N));
    for (std::size_t i = 0; i < vars.size(); ++i)
      if (blade[i] >= 0 && (vel.empty() || vel[i] < 0))
        per[static_cast<std::size_t>(blade[i])].emplace_back(i, masked[i]);
    return per;
  };
  // The first entry at which blade b's sets differ from blade 1's, or none.
  auto mismatch = [&](const auto& per, int b) -> std::optional<std::size_t> {
    const auto& first = per[0];
    const auto& other = per[static_cast<std::size_t>(b)];
    for (std::size_t j = 0; j < std::max(first.size(), other.size()); ++j)
      if (j >= first.size() || j >= other.size() || first[j].second != other[j].second)
        return j < other.size() ? other[j].first : first[j].first;
    return std::nullopt;
  };
  auto pairs = [&] {
    const auto per = perBlade();
    for (int b = 1; b < N; ++b)
      if (mismatch(per, b)) return false;
    return true;
  };
  if (left_out && !pairs()) {
    // Leave out the channels whose count differs between blades; if the rest still does not pair
    // (another order on another blade), every rotating entry.
    std::map<std::string, std::vector<int>> count;
    for (std::size_t i = 0; i < vars.size(); ++i)
      if (blade[i] >= 0) {
        auto& c = count[masked[i]];
        c.resize(static_cast<std::size_t>(N), 0);
        ++c[static_cast<std::size_t>(blade[i])];
      }
    for (std::size_t i = 0; i < vars.size(); ++i) {
      const auto& c = count[masked[i]];
      if (blade[i] >= 0 && std::any_of(c.begin(), c.end(), [&](int k) { return k != c.front(); }))
        blade[i] = -1, left_out->push_back(i);
    }
    if (!pairs())
      for (std::size_t i = 0; i < vars.size(); ++i)
        if (blade[i] >= 0) blade[i] = -1, left_out->push_back(i);
    std::sort(left_out->begin(), left_out->end());
  }
  const auto per = perBlade();
  for (int b = 1; b < N; ++b) {
    if (const auto i = mismatch(per, b))
      throw InputError(where(lin.path, vars[*i].line, key,
                             "rotating entries do not pair across blades: blade 1 has " +
                                 std::to_string(per[0].size()) + " and blade " + std::to_string(b + 1) + " has " +
                                 std::to_string(per[static_cast<std::size_t>(b)].size()) + ", mismatch at '" +
                                 vars[*i].description + "'"));
  }
  return blade;
}

/// The highest blade number of the rotating entries; InputError naming the entry beyond kMaxBlades
/// (the blade count sizes the per-blade tables: "blade 2000000000" must not allocate them).
int highestBlade(const OpenFastLin& lin, const std::vector<LinVariable>& vars, const std::string& key) {
  constexpr int kMaxBlades = 100;
  int n = 0;
  for (const auto& v : vars) {
    if (!v.rotating) continue;
    const int b = matchBlade(v.description).blade;
    if (b > kMaxBlades)
      throw InputError(where(lin.path, v.line, key,
                             "blade number " +
                                 (b == std::numeric_limits<int>::max() ? std::string("too large") : std::to_string(b)) +
                                 " in '" + v.description + "' (at most " + std::to_string(kMaxBlades) + " blades)"));
    n = std::max(n, b);
  }
  return n;
}

}  // namespace

int bladeNumberInDescription(const std::string& description) { return matchBlade(description).blade; }

MbcLayout mbcLayoutFromLin(const OpenFastLin& lin, int num_blades, std::vector<std::size_t>* left_out_outputs) {
  MbcLayout L;
  L.num_blades = num_blades > 0 ? num_blades
                                : std::max({highestBlade(lin, lin.x, "continuous states"),
                                            highestBlade(lin, lin.u, "inputs"), highestBlade(lin, lin.y, "outputs")});
  if (L.num_blades == 0) L.num_blades = 3;
  L.velocity_of = velocityOf(lin);
  L.state_blade = bladesOf(lin, lin.x, L.velocity_of, L.num_blades, "continuous states");
  L.input_blade = bladesOf(lin, lin.u, {}, L.num_blades, "inputs");
  L.output_blade = bladesOf(lin, lin.y, {}, L.num_blades, "outputs", left_out_outputs);
  return L;
}

MbcSample mbcSampleFromLin(const OpenFastLin& lin) {
  MbcSample s;
  if (const auto nf = lin.first_non_finite.find("A"); nf != lin.first_non_finite.end())
    throw InputError(where(lin.path, nf->second, "A",
                           "value is not finite (NaN, Infinity or ****): the state matrix cannot be analysed"));
  s.azimuth = lin.azimuth;
  s.rotor_speed = lin.rotor_speed;
  const std::vector<int> vel = velocityOf(lin);
  for (std::size_t i = 0; i < lin.x.size() && i < lin.xdot.size(); ++i) {
    const std::string& d = lin.x[i].description;
    if (vel[i] >= 0 && (d.find("DOF_GeAz") != std::string::npos || d.find("DOF_DrTr") != std::string::npos))
      s.rotor_acceleration += lin.xdot[i].op;
  }
  s.A = lin.A;
  s.B = lin.B;
  s.C = lin.C;
  s.D = lin.D;
  return s;
}

}  // namespace whirl
