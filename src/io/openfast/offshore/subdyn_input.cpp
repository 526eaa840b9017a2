// The SubDyn reader: scalars by key (overrides apply), tables positionally below their count keys, as
// SubDyn's SD_Input reads them; then the tables checked against each other.
#include "src/io/openfast/offshore/subdyn_input.hpp"

#include <cmath>
#include <optional>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_lines.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/refusals.hpp"

namespace whirl::io {
namespace {

// Rows of one table: the words of each row (split at blanks and commas, '!' comments dropped).
struct Rows {
  std::vector<std::vector<std::string>> words;
  std::vector<int> lines;
  int header_line = 0;
};

class Reader {
 public:
  Reader(const SubDynInput& in, const OpenFastLines& lines) : in_(in), f_(in.source), lines_(lines) {}

  // The entry of a key the file must have (the first one; duplicates are refused by checkDuplicates).
  const OpenFastEntry& entry(const char* key) const {
    const OpenFastEntry* e = f_.find(key);
    if (!e) throw InputError(f_.where(key, "key not found in this SubDyn file"));
    return *e;
  }

  // A count key, checked against its bound before anything of that size is read. `e` may be a
  // repeated key (the second NPropSets): its own value, not the first one's.
  int count(const OpenFastEntry& e, int lo, int hi) const {
    int n = 0;
    if (f_.find(e.key) == &e) {
      n = f_.getInt(e.key);
    } else {
      const std::optional<double> v = e.tokens.size() == 1 ? parseFortranDouble(e.tokens[0]) : std::nullopt;
      if (!v || *v != std::floor(*v) || std::abs(*v) > 1e9)
        throw InputError(where(e, "'" + e.raw + "' is not an integer"));
      n = static_cast<int>(*v);
    }
    if (n < lo || n > hi)
      throw InputError(
          where(e, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + " (src/base/limits.hpp)"));
    return n;
  }

  // The n rows below the count key's line (a column-name row and a unit row first), then a `---`
  // section line or the end of the file: OpenFAST reads exactly n rows, so a missing or extra row
  // would shift everything after it.
  Rows rows(const OpenFastEntry& e, int n) const {
    Rows r;
    r.header_line = e.line + 1;
    for (int k = 0; k < n; ++k) {
      const int ln = e.line + 3 + k;
      if (ln > lines_.count())
        throw InputError(
            where(e, std::to_string(n) +
                         " rows expected below it (after the column-name and unit rows), the file ends after " +
                         std::to_string(k)));
      const std::vector<std::string> w = splitWords(lines_.line(ln));
      if (w.empty() || isSection(lines_.line(ln)))
        throw InputError(where(e, std::to_string(n) +
                                      " rows expected below it (after the column-name and unit rows), line " +
                                      std::to_string(ln) + " is " + (w.empty() ? "empty" : "a section line")));
      r.words.push_back(w);
      r.lines.push_back(ln);
    }
    const int next = e.line + 3 + n;
    if (next <= lines_.count() && !isSection(lines_.line(next)) && !isBlankLine(lines_.line(next)))
      throw InputError(where(e, "is " + std::to_string(n) + " but line " + std::to_string(next) +
                                    " is another row (expected a '---' section line after the table)"));
    return r;
  }

  double number(const std::string& w, int line, const std::string& key) const {
    const std::optional<double> v = parseFortranDouble(w);
    if (!v) throw InputError(in_.where(line, key, "'" + w + "' is not a number"));
    if (!std::isfinite(*v)) throw InputError(in_.where(line, key, "'" + w + "' is not a finite number"));
    return *v;
  }

  int integer(const std::string& w, int line, const std::string& key) const {
    const double v = number(w, line, key);
    if (v != std::floor(v) || std::abs(v) > 1e9)
      throw InputError(in_.where(line, key, "'" + w + "' is not an integer"));
    return static_cast<int>(v);
  }

  // The leading numeric words of a row (stops at the first word that is not a number).
  static int numericWords(const std::vector<std::string>& w) {
    int n = 0;
    while (n < static_cast<int>(w.size()) && parseFortranDouble(w[n])) ++n;
    return n;
  }

  std::string where(const OpenFastEntry& e, const std::string& reason) const {
    return f_.find(e.key) == &e ? f_.where(e.key, reason) : whirl::where(f_.path().string(), e.line, e.key, reason);
  }

  const OpenFastFile& file() const { return f_; }
  const OpenFastLines& lines() const { return lines_; }

 private:
  static bool isSection(const std::string& line) {
    const std::size_t b = line.find_first_not_of(" \t");
    return b != std::string::npos && (line.compare(b, 3, "---") == 0 || line.compare(b, 3, "===") == 0);
  }

  const SubDynInput& in_;
  const OpenFastFile& f_;
  const OpenFastLines& lines_;
};

// Keys read here, each allowed once (NPropSets twice: the circular and, from OpenFAST v3.2, the
// rectangular table): a repeated line would shift SubDyn's positional reading.
void checkDuplicates(const OpenFastFile& f) {
  const char* keys[] = {"FEMMod",          "NDiv",         "CBMod",         "Nmodes",         "JDampings",
                        "GuyanDampMod",    "RayleighDamp", "GuyanDampSize", "NJoints",        "NReact",
                        "NInterf",         "NMembers",     "NXPropSets",    "NCablePropSets", "NRigidPropSets",
                        "NSpringPropSets", "NCOSMs",       "NCmass"};
  for (const OpenFastEntry& e : f.entries()) {
    const std::string k = canonicalKey(e.key);
    const OpenFastEntry* first = f.find(e.key);
    if (first == nullptr || first == &e) continue;  // informal lines (comments, table headers) are not found by key
    if (k == "npropsets") {
      int seen = 0;
      for (const OpenFastEntry& x : f.entries())
        if (canonicalKey(x.key) == k && &x != &e && x.line < e.line) ++seen;
      if (seen < 2) continue;
    } else {
      bool ours = false;
      for (const char* key : keys) ours = ours || canonicalKey(key) == k;
      if (!ours) continue;
    }
    throw InputError(whirl::where(f.path().string(), e.line, e.key,
                                  "given twice (first on line " + std::to_string(first->line) +
                                      "): SubDyn reads its file by position"));
  }
}

std::vector<const OpenFastEntry*> entriesOf(const OpenFastFile& f, const char* key) {
  std::vector<const OpenFastEntry*> out;
  for (const OpenFastEntry& e : f.entries())
    if (canonicalKey(e.key) == canonicalKey(key)) out.push_back(&e);
  return out;
}

void readModes(SubDynInput& sd, Refusals& r) {
  const OpenFastFile& f = sd.source;
  sd.FEMMod = f.getInt("FEMMod");
  r.addIf(sd.FEMMod == 2 || sd.FEMMod == 4, "FEMMod", "tapered elements are not implemented (in SubDyn either)",
          "1 (Euler-Bernoulli) or 3 (Timoshenko)");
  if (sd.FEMMod != 1 && sd.FEMMod != 2 && sd.FEMMod != 3 && sd.FEMMod != 4)
    throw InputError(f.where("FEMMod", "must be 1 (Euler-Bernoulli) or 3 (Timoshenko)"));
  sd.NDiv = f.getInt("NDiv");
  if (sd.NDiv < 1 || sd.NDiv > limits::kMaxSubDynNDiv)
    throw InputError(
        f.where("NDiv", "must be between 1 and " + std::to_string(limits::kMaxSubDynNDiv) + " (src/base/limits.hpp)"));
  const int nmodes = f.getInt("Nmodes");
  if (nmodes > limits::kMaxReducedModes)
    throw InputError(
        f.where("Nmodes", "must be at most " + std::to_string(limits::kMaxReducedModes) + " (src/base/limits.hpp)"));
  // v1.01: CBMod = False keeps every mode (Nmodes ignored); from OpenFAST v2, Nmodes < 0 does.
  const std::optional<bool> cb = f.findBool("CBMod");
  if (cb && !*cb) {
    sd.Nmodes = -1;
  } else if (cb && nmodes < 0) {
    throw InputError(f.where("Nmodes", "must not be negative with CBMod = True (CBMod = False keeps every mode)"));
  } else {
    sd.Nmodes = nmodes < 0 ? -1 : nmodes;
  }
  if (sd.Nmodes == 0) return;  // Guyan: SubDyn reads the JDampings line as a comment
  const std::vector<double> d = f.getDoubles("JDampings");
  if (d.empty()) throw InputError(f.where("JDampings", "expected at least one damping ratio (%)"));
  for (double x : d)
    if (!(x >= 0)) throw InputError(f.where("JDampings", "damping ratios must not be negative"));
  const int n = sd.Nmodes < 0 ? 1 : sd.Nmodes;
  for (int k = 0; k < n; ++k) sd.JDampings.push_back(0.01 * d[std::min<std::size_t>(k, d.size() - 1)]);
}

void readGuyanDamping(SubDynInput& sd, const Reader& rd) {
  const OpenFastFile& f = sd.source;
  const std::optional<int> mod = f.findInt("GuyanDampMod");
  if (!mod) return;  // v1.01: no Guyan damping
  sd.GuyanDampMod = *mod;
  if (sd.GuyanDampMod < 0 || sd.GuyanDampMod > 2)
    throw InputError(f.where("GuyanDampMod", "must be 0 (none), 1 (Rayleigh) or 2 (matrix)"));
  if (sd.GuyanDampMod == 1) {
    const std::vector<double> ab = f.getDoubles("RayleighDamp");
    if (ab.size() < 2) throw InputError(f.where("RayleighDamp", "expected the two coefficients alpha, beta"));
    sd.RayleighDamp = {ab[0], ab[1]};
  }
  if (sd.GuyanDampMod == 2) {
    const OpenFastEntry& e = rd.entry("GuyanDampSize");
    if (f.getInt("GuyanDampSize") != 6)
      throw InputError(f.where("GuyanDampSize", "must be 6 (one transition piece of a fixed-bottom substructure)"));
    for (int r = 0; r < 6; ++r) {
      const int ln = e.line + 1 + r;
      const std::vector<std::string> w = splitWords(rd.lines().line(ln));
      if (w.size() < 6)
        throw InputError(
            sd.where(ln, "GuyanDampMat", "row " + std::to_string(r + 1) + " of the 6×6 matrix is not 6 numbers"));
      for (int c = 0; c < 6; ++c) sd.GuyanDampMat(r, c) = rd.number(w[c], ln, "GuyanDampMat");
    }
  }
}

void readJoints(SubDynInput& sd, const Reader& rd, std::vector<std::string>& refused) {
  const OpenFastEntry& e = rd.entry("NJoints");
  const Rows rows = rd.rows(e, rd.count(e, 2, limits::kMaxSubDynJoints));
  // OpenFAST v2.5+: JointID, X, Y, Z, JointType, JointDirX/Y/Z, JointStiff; before: the first four.
  const int columns = Reader::numericWords(rows.words[0]) >= 9 ? 9 : 4;
  for (std::size_t k = 0; k < rows.words.size(); ++k) {
    const auto& w = rows.words[k];
    const int ln = rows.lines[k];
    if (Reader::numericWords(w) < columns)
      throw InputError(
          sd.where(ln, "JointID",
                   "expected " + std::to_string(columns) + " numbers (JointID, JointXss, JointYss, JointZss" +
                       (columns == 9 ? ", JointType, JointDirX, JointDirY, JointDirZ, JointStiff)" : ")")));
    SubDynJoint j;
    j.id = rd.integer(w[0], ln, "JointID");
    j.position = Vec3(rd.number(w[1], ln, "JointXss"), rd.number(w[2], ln, "JointYss"),
                      rd.number(w[3], ln, "JointZss"));
    j.line = ln;
    if (sd.jointIndex(j.id) >= 0) throw InputError(sd.where(ln, "JointID", "joint " + w[0] + " defined twice"));
    if (columns == 9 && rd.integer(w[4], ln, "JointType") != 1)
      refused.push_back(sd.where(ln, "JointType",
                                 w[4] + " not supported by whirl (universal, pin and ball joints are not modelled; "
                                        "whirl supports only cantilever joints, JointType = 1)"));
    sd.joints.push_back(j);
  }
}

void readReactions(SubDynInput& sd, const Reader& rd, std::vector<std::string>& refused) {
  const OpenFastEntry& e = rd.entry("NReact");
  const int n = rd.count(e, 0, static_cast<int>(sd.joints.size()));
  if (n == 0) {
    refused.push_back(
        rd.where(e, "0 not supported by whirl (a floating substructure, without reaction joints, is not modelled)"));
    return;
  }
  const Rows rows = rd.rows(e, n);
  for (std::size_t k = 0; k < rows.words.size(); ++k) {
    const auto& w = rows.words[k];
    const int ln = rows.lines[k];
    const int num = Reader::numericWords(w);
    SubDynReaction r;
    r.joint = rd.integer(w[0], ln, "RJointID");
    r.line = ln;
    if (num != 1 && num != 7)
      throw InputError(
          sd.where(ln, "RJointID", "expected RJointID and 6 flags (RctTDXss … RctRDZss), then an optional SSIfile"));
    if (num == 7)
      for (int d = 0; d < 6; ++d) {
        const int v = rd.integer(w[1 + d], ln, "RctTDXss");
        if (v != 0 && v != 1)
          throw InputError(sd.where(ln, "RctTDXss", "flags are 1 (locked) or 0 (free), found " + w[1 + d]));
        r.fixed[d] = v == 1;
      }
    if (sd.jointIndex(r.joint) < 0) throw InputError(sd.where(ln, "RJointID", "no joint " + w[0]));
    for (const SubDynReaction& o : sd.reactions)
      if (o.joint == r.joint) throw InputError(sd.where(ln, "RJointID", "joint " + w[0] + " listed twice"));
    if (static_cast<int>(w.size()) > num) {
      const std::string ssi = unquoted(w[num]);
      bool free = false;
      for (bool fx : r.fixed) free = free || !fx;
      if (!ssi.empty() && free)
        refused.push_back(sd.where(ln, "SSIfile",
                                   "'" + ssi +
                                       "' not supported by whirl (soil-structure interaction is not modelled; lock "
                                       "every DOF of the reaction joint)"));
      else if (!ssi.empty())
        sd.notes.push_back(
            sd.where(ln, "SSIfile", "ignored: every DOF of the joint is locked (SubDyn ignores it too)"));
    }
    sd.reactions.push_back(r);
  }
}

void readInterfaces(SubDynInput& sd, const Reader& rd, std::vector<std::string>& refused) {
  const OpenFastEntry& e = rd.entry("NInterf");
  const int n = rd.count(e, 1, static_cast<int>(sd.joints.size()));
  const Rows rows = rd.rows(e, n);
  for (std::size_t k = 0; k < rows.words.size(); ++k) {
    const auto& w = rows.words[k];
    const int ln = rows.lines[k];
    const int num = Reader::numericWords(w);
    // IJointID + 6 flags (to OpenFAST v4), IJointID + TPID (+ 6 flags) (v5).
    if (num != 7 && num != 2 && num != 8)
      throw InputError(sd.where(ln, "IJointID",
                                "expected IJointID and 6 flags (ItfTDXss … ItfRDZss), or IJointID, TPID and 6 flags"));
    SubDynInterface i;
    i.joint = rd.integer(w[0], ln, "IJointID");
    i.line = ln;
    if (num != 7) {
      const int tp = rd.integer(w[1], ln, "TPID");
      if (tp == 0)
        refused.push_back(sd.where(
            ln, "TPID",
            "0 not supported by whirl (the rigid-body reference point of a floating substructure is not modelled)"));
      else if (tp != 1)
        refused.push_back(sd.where(ln, "TPID", w[1] + " not supported by whirl (one transition piece only, TPID = 1)"));
    }
    for (int d = num == 7 ? 1 : 2; d < num; ++d)
      if (rd.integer(w[d], ln, "ItfTDXss") != 1)
        refused.push_back(sd.where(
            ln, "ItfTDXss",
            w[d] +
                " not supported by whirl (every interface DOF is locked to the transition piece, as SubDyn requires)"));
    if (sd.jointIndex(i.joint) < 0) throw InputError(sd.where(ln, "IJointID", "no joint " + w[0]));
    for (const SubDynInterface& o : sd.interfaces)
      if (o.joint == i.joint) throw InputError(sd.where(ln, "IJointID", "joint " + w[0] + " listed twice"));
    for (const SubDynReaction& r : sd.reactions)
      if (r.joint == i.joint) throw InputError(sd.where(ln, "IJointID", "joint " + w[0] + " is a reaction joint too"));
    sd.interfaces.push_back(i);
  }
}

void readMembers(SubDynInput& sd, const Reader& rd, std::vector<std::string>& refused) {
  const OpenFastEntry& e = rd.entry("NMembers");
  const int n = rd.count(e, 1, limits::kMaxSubDynMembers);
  if (static_cast<long>(n) * sd.NDiv > limits::kMaxFemElements)
    throw InputError(rd.where(e, "NMembers × NDiv = " + std::to_string(static_cast<long>(n) * sd.NDiv) +
                                     " elements, more than " + std::to_string(limits::kMaxFemElements) +
                                     " (src/base/limits.hpp)"));
  const Rows rows = rd.rows(e, n);
  // OpenFAST v2.5+ has an MType column (1 or 1c circular beam, 1r rectangular, 2 cable, 3 rigid link,
  // 4 arbitrary section, 5 spring); v1.01 members are all circular beams.
  const bool typed = toLower(rd.lines().line(rows.header_line)).find("mtype") != std::string::npos;
  for (std::size_t k = 0; k < rows.words.size(); ++k) {
    const auto& w = rows.words[k];
    const int ln = rows.lines[k];
    if (static_cast<int>(w.size()) < (typed ? 6 : 5) || Reader::numericWords(w) < 5)
      throw InputError(
          sd.where(ln, "MemberID",
                   typed ? "expected MemberID, MJointID1, MJointID2, MPropSetID1, MPropSetID2, MType, MSpin/COSMID"
                         : "expected MemberID, MJointID1, MJointID2, MPropSetID1, MPropSetID2 (COSMID)"));
    SubDynMember m;
    m.id = rd.integer(w[0], ln, "MemberID");
    m.joint1 = rd.integer(w[1], ln, "MJointID1");
    m.joint2 = rd.integer(w[2], ln, "MJointID2");
    m.prop1 = rd.integer(w[3], ln, "MPropSetID1");
    m.prop2 = rd.integer(w[4], ln, "MPropSetID2");
    m.line = ln;
    for (const SubDynMember& o : sd.members)
      if (o.id == m.id) throw InputError(sd.where(ln, "MemberID", "member " + w[0] + " defined twice"));
    if (typed) {
      const std::string t = toLower(w[5]);
      const char* what = t == "1r"  ? "rectangular beams"
                         : t == "2" ? "pretension cables"
                         : t == "3" ? "rigid links"
                         : t == "4" ? "beams with arbitrary sections"
                         : t == "5" ? "spring elements"
                                    : nullptr;
      if (what)
        refused.push_back(sd.where(ln, "MType",
                                   w[5] + " not supported by whirl (" + what +
                                       " are not modelled; whirl supports only circular beams, MType = 1)"));
      else if (t != "1" && t != "1c")
        throw InputError(sd.where(ln, "MType", "'" + w[5] + "' is not a member type (1c, 1r, 2, 3, 4, 5)"));
    }
    const int a = sd.jointIndex(m.joint1), b = sd.jointIndex(m.joint2);
    if (a < 0) throw InputError(sd.where(ln, "MJointID1", "no joint " + w[1]));
    if (b < 0) throw InputError(sd.where(ln, "MJointID2", "no joint " + w[2]));
    if (a == b) throw InputError(sd.where(ln, "MJointID2", "member " + w[0] + " starts and ends at joint " + w[1]));
    const Vec3 d = sd.joints[b].position - sd.joints[a].position;
    if (d.norm() <= 1e-9 * std::max(1.0, sd.joints[a].position.norm()))
      throw InputError(
          sd.where(ln, "MJointID2",
                   "member " + w[0] + " has zero length: joints " + w[1] + " and " + w[2] + " are at the same place"));
    sd.members.push_back(m);
  }
}

void readSections(SubDynInput& sd, const Reader& rd) {
  const std::vector<const OpenFastEntry*> sets = entriesOf(sd.source, "NPropSets");
  if (sets.empty()) throw InputError(sd.source.where("NPropSets", "key not found in this SubDyn file"));
  const Rows rows = rd.rows(*sets[0], rd.count(*sets[0], 1, limits::kMaxSubDynPropSets));
  for (std::size_t k = 0; k < rows.words.size(); ++k) {
    const auto& w = rows.words[k];
    const int ln = rows.lines[k];
    if (Reader::numericWords(w) < 6)
      throw InputError(sd.where(ln, "PropSetID", "expected PropSetID, YoungE, ShearG, MatDens, XsecD, XsecT"));
    SubDynSection s{rd.integer(w[0], ln, "PropSetID"),
                    rd.number(w[1], ln, "YoungE"),
                    rd.number(w[2], ln, "ShearG"),
                    rd.number(w[3], ln, "MatDens"),
                    rd.number(w[4], ln, "XsecD"),
                    rd.number(w[5], ln, "XsecT"),
                    ln};
    if (sd.sectionIndex(s.id) >= 0)
      throw InputError(sd.where(ln, "PropSetID", "property set " + w[0] + " defined twice"));
    if (!(s.E > 0)) throw InputError(sd.where(ln, "YoungE", "must be positive"));
    if (!(s.G > 0)) throw InputError(sd.where(ln, "ShearG", "must be positive"));
    if (!(s.rho > 0)) throw InputError(sd.where(ln, "MatDens", "must be positive"));
    if (!(s.D > 0)) throw InputError(sd.where(ln, "XsecD", "must be positive"));
    if (s.t > 0.5 * s.D)
      throw InputError(sd.where(ln, "XsecT", "the wall is thicker than the radius (XsecT ≤ 0 gives a solid section)"));
    sd.sections.push_back(s);
  }
}

// Ids of a property table other than the circular one (members using them are refused by name).
std::vector<int> otherSectionIds(const Reader& rd, const OpenFastEntry* e) {
  std::vector<int> ids;
  if (!e) return ids;
  const Rows rows = rd.rows(*e, rd.count(*e, 0, limits::kMaxSubDynPropSets));
  for (std::size_t k = 0; k < rows.words.size(); ++k)
    ids.push_back(rd.integer(rows.words[k][0], rows.lines[k], e->key));
  return ids;
}

void checkMemberSections(SubDynInput& sd, const Reader& rd, std::vector<std::string>& refused) {
  const std::vector<const OpenFastEntry*> sets = entriesOf(sd.source, "NPropSets");
  std::vector<int> other = otherSectionIds(rd, sd.source.find("NXPropSets"));
  if (sets.size() > 1) {
    const std::vector<int> rect = otherSectionIds(rd, sets[1]);
    other.insert(other.end(), rect.begin(), rect.end());
  }
  for (const SubDynMember& m : sd.members) {
    for (const auto& [id, key] : {std::pair{m.prop1, "MPropSetID1"}, std::pair{m.prop2, "MPropSetID2"}}) {
      if (sd.sectionIndex(id) >= 0) continue;
      bool found = false;
      for (int o : other) found = found || o == id;
      if (found)
        refused.push_back(
            sd.where(m.line, key,
                     std::to_string(id) + " not supported by whirl (non-circular cross-sections are not modelled)"));
      else throw InputError(sd.where(m.line, key, "no property set " + std::to_string(id)));
    }
    const int a = sd.sectionIndex(m.prop1), b = sd.sectionIndex(m.prop2);
    if (a < 0 || b < 0) continue;
    const SubDynSection &s1 = sd.sections[a], &s2 = sd.sections[b];
    if (s1.E != s2.E || s1.G != s2.G || s1.rho != s2.rho)
      throw InputError(sd.where(m.line, "MPropSetID2",
                                "E, G and density must be the same at both ends of member " + std::to_string(m.id) +
                                    " (only D and t may change along a member, as in SubDyn)"));
  }
}

void readMasses(SubDynInput& sd, const Reader& rd, std::vector<std::string>& refused) {
  const OpenFastEntry& e = rd.entry("NCmass");
  const Rows rows = rd.rows(e, rd.count(e, 0, static_cast<int>(sd.joints.size())));
  for (std::size_t k = 0; k < rows.words.size(); ++k) {
    const auto& w = rows.words[k];
    const int ln = rows.lines[k];
    const int num = Reader::numericWords(w);
    // CMJointID, JMass, JMXX, JMYY, JMZZ (+ JMXY, JMXZ, JMYZ, MCGX, MCGY, MCGZ from OpenFAST v3).
    if (num < 5) throw InputError(sd.where(ln, "CMJointID", "expected CMJointID, JMass, JMXX, JMYY, JMZZ"));
    SubDynMass m;
    m.joint = rd.integer(w[0], ln, "CMJointID");
    m.mass = rd.number(w[1], ln, "JMass");
    m.line = ln;
    m.inertia.diagonal() << rd.number(w[2], ln, "JMXX"), rd.number(w[3], ln, "JMYY"), rd.number(w[4], ln, "JMZZ");
    if (num >= 11) {
      m.inertia(0, 1) = m.inertia(1, 0) = rd.number(w[5], ln, "JMXY");
      m.inertia(0, 2) = m.inertia(2, 0) = rd.number(w[6], ln, "JMXZ");
      m.inertia(1, 2) = m.inertia(2, 1) = rd.number(w[7], ln, "JMYZ");
      for (int c = 8; c < 11; ++c)
        if (rd.number(w[c], ln, "MCGX") != 0.0)
          refused.push_back(
              sd.where(ln,
                       c == 8   ? "MCGX"
                       : c == 9 ? "MCGY"
                                : "MCGZ",
                       w[c] + " not supported by whirl (a lumped mass away from its joint is not modelled)"));
    }
    if (sd.jointIndex(m.joint) < 0) throw InputError(sd.where(ln, "CMJointID", "no joint " + w[0]));
    if (!(m.mass >= 0)) throw InputError(sd.where(ln, "JMass", "must not be negative"));
    if ((m.inertia.diagonal().array() < 0).any())
      throw InputError(sd.where(ln, "JMXX", "moments of inertia must not be negative"));
    sd.masses.push_back(m);
  }
}

}  // namespace

int SubDynInput::jointIndex(int id) const {
  for (std::size_t k = 0; k < joints.size(); ++k)
    if (joints[k].id == id) return static_cast<int>(k);
  return -1;
}

int SubDynInput::sectionIndex(int id) const {
  for (std::size_t k = 0; k < sections.size(); ++k)
    if (sections[k].id == id) return static_cast<int>(k);
  return -1;
}

std::string SubDynInput::where(int line, const std::string& key, const std::string& reason) const {
  return whirl::where(source.path().string(), line, key, reason);
}

SubDynInput readSubDyn(const std::filesystem::path& file, OverrideSet* overrides) {
  const OpenFastLines lines = OpenFastLines::read(file);  // the file opened once: keys and tables
  SubDynInput sd;
  sd.source = OpenFastFile::parse(lines.text(), file);
  if (overrides) overrides->applyTo(sd.source);
  checkDuplicates(sd.source);
  Refusals r(sd.source);
  readModes(sd, r);
  std::vector<std::string> refused = r.take();
  const Reader rd(sd, lines);
  readGuyanDamping(sd, rd);
  readJoints(sd, rd, refused);
  readReactions(sd, rd, refused);
  readInterfaces(sd, rd, refused);
  readMembers(sd, rd, refused);
  readSections(sd, rd);
  checkMemberSections(sd, rd, refused);
  readMasses(sd, rd, refused);
  throwIfAny(refused);
  return sd;
}

}  // namespace whirl::io
