#include "src/io/openfast/offshore/hydrodyn_members.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/openfast/openfast_lines.hpp"

namespace whirl::io {
namespace {

// One table below its count key: the column names and the rows' words, each with its line.
struct Table {
  std::vector<std::string> columns;  // lower case
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;
};

class TableReader {
 public:
  TableReader(const OpenFastFile& f, const OpenFastLines& lines) : f_(f), lines_(lines) {}

  std::string where(int line, const std::string& key, const std::string& reason) const {
    return whirl::where(f_.path().string(), line, key, reason);
  }

  // The count of a table (absent key: 0), bounded before anything of that size is read.
  int count(const char* key, int hi) const {
    const std::optional<int> n = f_.findInt(key);
    if (!n) return 0;
    if (*n < 0 || *n > hi)
      throw InputError(f_.where(key, "must be between 0 and " + std::to_string(hi) + " (src/base/limits.hpp)"));
    return *n;
  }

  // The n rows below the key's line, after its column-name and unit rows: HydroDyn reads exactly n, so
  // a missing row would shift everything after it.
  Table rows(const char* key, int n) const {
    Table t;
    const OpenFastEntry* e = f_.find(key);
    if (!e || n == 0) return t;
    for (const std::string& w : splitWords(lines_.line(e->line + 1))) t.columns.push_back(toLower(w));
    for (int k = 0; k < n; ++k) {
      const int ln = e->line + 3 + k;
      const std::vector<std::string> w = splitWords(lines_.line(ln));
      if (ln > lines_.count() || w.empty() || w[0].rfind("---", 0) == 0)
        throw InputError(f_.where(key, std::to_string(n) +
                                           " rows expected below it (after the column-name and unit "
                                           "rows); line " +
                                           std::to_string(ln) + " is not one"));
      t.rows.push_back(w);
      t.lines.push_back(ln);
    }
    return t;
  }

  // The index of a column the table must have.
  int column(const Table& t, const char* key, const char* name) const {
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      if (t.columns[c] == toLower(name)) return static_cast<int>(c);
    const OpenFastEntry* e = f_.find(key);
    throw InputError(where(e ? e->line + 1 : 0, key, std::string("no column '") + name + "' in the column-name row"));
  }

  const std::string& word(const Table& t, int row, int col, const char* name) const {
    if (col >= static_cast<int>(t.rows[row].size())) throw InputError(where(t.lines[row], name, "missing in this row"));
    return t.rows[row][col];
  }

  double number(const Table& t, int row, int col, const char* name) const {
    const std::string& w = word(t, row, col, name);
    const std::optional<double> v = parseFortranDouble(w);
    if (!v || !std::isfinite(*v)) throw InputError(where(t.lines[row], name, "'" + w + "' is not a finite number"));
    return *v;
  }

  int integer(const Table& t, int row, int col, const char* name) const {
    const double v = number(t, row, col, name);
    if (v != std::floor(v) || std::abs(v) > 1e9)
      throw InputError(where(t.lines[row], name, "'" + word(t, row, col, name) + "' is not an integer"));
    return static_cast<int>(v);
  }

  bool flag(const Table& t, int row, int col, const char* name) const {
    const std::string v = toLower(word(t, row, col, name));
    if (v == "true" || v == "t" || v == ".true.") return true;
    if (v == "false" || v == "f" || v == ".false.") return false;
    throw InputError(where(t.lines[row], name, "'" + word(t, row, col, name) + "' is not True or False"));
  }

 private:
  const OpenFastFile& f_;
  const OpenFastLines& lines_;
};

template <class Row>
void checkUniqueIds(const TableReader& r, const std::vector<Row>& rows, const char* name) {
  std::set<int> seen;
  for (const Row& x : rows)
    if (!seen.insert(x.id).second) throw InputError(r.where(x.line, name, std::to_string(x.id) + " given twice"));
}

void readJoints(HydroDynMembers& m, const TableReader& r) {
  const int n = r.count("NJoints", limits::kMaxHydroDynJoints);
  const Table t = r.rows("NJoints", n);
  if (n == 0) return;
  const int id = r.column(t, "NJoints", "JointID"), x = r.column(t, "NJoints", "Jointxi"),
            y = r.column(t, "NJoints", "Jointyi"), z = r.column(t, "NJoints", "Jointzi");
  int ax = -1;
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == "jointaxid") ax = static_cast<int>(c);
  for (int k = 0; k < n; ++k)
    m.joints.push_back({r.integer(t, k, id, "JointID"),
                        Vec3(r.number(t, k, x, "Jointxi"), r.number(t, k, y, "Jointyi"), r.number(t, k, z, "Jointzi")),
                        t.lines[k], ax >= 0 ? r.integer(t, k, ax, "JointAxID") : 0});
  checkUniqueIds(r, m.joints, "JointID");
}

void readProps(HydroDynMembers& m, const OpenFastFile& f, const TableReader& r) {
  // v4.1 split the table into circular (NPropSetsCyl) and rectangular (NPropSetsRec) sections.
  const char* key = f.has("NPropSetsCyl") ? "NPropSetsCyl" : "NPropSets";
  const int n = r.count(key, limits::kMaxHydroDynPropSets);
  const Table t = r.rows(key, n);
  if (n == 0) return;
  const int id = r.column(t, key, "PropSetID"), d = r.column(t, key, "PropD"), th = r.column(t, key, "PropThck");
  for (int k = 0; k < n; ++k) {
    HydroDynPropSet p{r.integer(t, k, id, "PropSetID"), r.number(t, k, d, "PropD"), r.number(t, k, th, "PropThck"),
                      t.lines[k]};
    if (!(p.D > 0)) throw InputError(r.where(p.line, "PropD", "must be positive"));
    if (!(p.thickness >= 0 && p.thickness <= 0.5 * p.D))
      throw InputError(r.where(p.line, "PropThck", "must be between 0 and half the diameter PropD"));
    m.props.push_back(p);
  }
  checkUniqueIds(r, m.props, "PropSetID");
}

void readMembers(HydroDynMembers& m, const TableReader& r) {
  const int n = r.count("NMembers", limits::kMaxHydroDynMembers);
  const Table t = r.rows("NMembers", n);
  if (n == 0) return;
  const int id = r.column(t, "NMembers", "MemberID"), j1 = r.column(t, "NMembers", "MJointID1"),
            j2 = r.column(t, "NMembers", "MJointID2"), p1 = r.column(t, "NMembers", "MPropSetID1"),
            p2 = r.column(t, "NMembers", "MPropSetID2"), pot = r.column(t, "NMembers", "PropPot"),
            mod = r.column(t, "NMembers", "MCoefMod");
  int geom = -1;  // MSecGeom (v4.1+): 1 circular, 2 rectangular
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == "msecgeom") geom = static_cast<int>(c);
  for (int k = 0; k < n; ++k) {
    HydroDynMember mb{r.integer(t, k, id, "MemberID"),
                      r.integer(t, k, j1, "MJointID1"),
                      r.integer(t, k, j2, "MJointID2"),
                      r.integer(t, k, p1, "MPropSetID1"),
                      r.integer(t, k, p2, "MPropSetID2"),
                      r.flag(t, k, pot, "PropPot"),
                      t.lines[k],
                      r.integer(t, k, mod, "MCoefMod")};
    if (mb.MCoefMod < 1 || mb.MCoefMod > 3)
      throw InputError(r.where(mb.line, "MCoefMod", "must be 1 (simple), 2 (depth-based) or 3 (member-based)"));
    if (geom >= 0 && r.integer(t, k, geom, "MSecGeom") != 1)
      throw InputError(
          r.where(mb.line, "MSecGeom", "rectangular members are not modelled by whirl (only 1, circular)"));
    const HydroDynJoint* a = m.joint(mb.joint1);
    const HydroDynJoint* b = m.joint(mb.joint2);
    if (!a)
      throw InputError(
          r.where(mb.line, "MJointID1", "joint " + std::to_string(mb.joint1) + " is not in the joint table"));
    if (!b)
      throw InputError(
          r.where(mb.line, "MJointID2", "joint " + std::to_string(mb.joint2) + " is not in the joint table"));
    if ((a->position - b->position).norm() == 0.0)
      throw InputError(r.where(mb.line, "MemberID",
                               "member " + std::to_string(mb.id) + " has zero length (its two joints coincide)"));
    if (!m.prop(mb.prop1))
      throw InputError(r.where(mb.line, "MPropSetID1",
                               "property set " + std::to_string(mb.prop1) + " is not in the property table"));
    if (!m.prop(mb.prop2))
      throw InputError(r.where(mb.line, "MPropSetID2",
                               "property set " + std::to_string(mb.prop2) + " is not in the property table"));
    m.members.push_back(mb);
  }
  checkUniqueIds(r, m.members, "MemberID");
}

// FILLED MEMBERS rows: FillNumM, that many member ids, FillFSLoc, FillDens (a number or DEFAULT).
void readFills(HydroDynMembers& m, const TableReader& r) {
  const int n = r.count("NFillGroups", limits::kMaxHydroDynMembers);
  const Table t = r.rows("NFillGroups", n);
  std::set<int> filled;
  for (int k = 0; k < n; ++k) {
    HydroDynFillGroup g;
    g.line = t.lines[k];
    const int count = r.integer(t, k, 0, "FillNumM");
    if (count < 1 || count > static_cast<int>(m.members.size()))
      throw InputError(r.where(g.line, "FillNumM", "must be between 1 and the number of members"));
    if (static_cast<int>(t.rows[k].size()) != count + 3)
      throw InputError(r.where(g.line, "FillMList",
                               "expected FillNumM = " + std::to_string(count) +
                                   " member ids, then FillFSLoc and FillDens (" + std::to_string(count + 3) +
                                   " words), found " + std::to_string(t.rows[k].size())));
    for (int j = 0; j < count; ++j) {
      const int id = r.integer(t, k, 1 + j, "FillMList");
      if (!m.member(id))
        throw InputError(r.where(g.line, "FillMList", "member " + std::to_string(id) + " is not in the member table"));
      if (!filled.insert(id).second)
        throw InputError(r.where(g.line, "FillMList", "member " + std::to_string(id) + " is already in a fill group"));
      g.members.push_back(id);
    }
    g.FillFSLoc = r.number(t, k, count + 1, "FillFSLoc");
    const std::string dens = toLower(unquoted(t.rows[k][count + 2]));
    if (dens != "default") {
      g.FillDens = r.number(t, k, count + 2, "FillDens");
      if (!(*g.FillDens > 0)) throw InputError(r.where(g.line, "FillDens", "must be positive (or DEFAULT)"));
    }
    m.fills.push_back(g);
  }
}

void readCoefficients(HydroDynMembers& m, const OpenFastFile& f, const TableReader& r) {
  const int na = r.count("NAxCoef", limits::kMaxHydroDynPropSets);
  const Table a = r.rows("NAxCoef", na);
  if (na > 0) {
    const int id = r.column(a, "NAxCoef", "AxCoefID"), ca = r.column(a, "NAxCoef", "AxCa");
    for (int k = 0; k < na; ++k)
      m.axial.push_back({r.integer(a, k, id, "AxCoefID"), r.number(a, k, ca, "AxCa"), a.lines[k]});
    checkUniqueIds(r, m.axial, "AxCoefID");
  }
  // v4.1 split the table into cylindrical (NCoefMembersCyl) and rectangular members.
  const char* key = f.has("NCoefMembersCyl") ? "NCoefMembersCyl" : "NCoefMembers";
  const int nm = r.count(key, limits::kMaxHydroDynMembers);
  const Table c = r.rows(key, nm);
  if (nm > 0) {
    const int id = r.column(c, key, "MemberID"), c1 = r.column(c, key, "MemberCa1"), c2 = r.column(c, key, "MemberCa2"),
              a1 = r.column(c, key, "MemberAxCa1"), a2 = r.column(c, key, "MemberAxCa2"),
              g1 = r.column(c, key, "MemberCaMG1"), g2 = r.column(c, key, "MemberCaMG2");
    for (int k = 0; k < nm; ++k)
      m.member_coefs.push_back({r.integer(c, k, id, "MemberID"), r.number(c, k, c1, "MemberCa1"),
                                r.number(c, k, c2, "MemberCa2"), r.number(c, k, a1, "MemberAxCa1"),
                                r.number(c, k, a2, "MemberAxCa2"), c.lines[k], r.number(c, k, g1, "MemberCaMG1"),
                                r.number(c, k, g2, "MemberCaMG2")});
    checkUniqueIds(r, m.member_coefs, "MemberID");
  }
  const int ng = r.count("NMGDepths", limits::kMaxHydroDynPropSets);
  const Table g = r.rows("NMGDepths", ng);
  if (ng > 0) {
    const int z = r.column(g, "NMGDepths", "MGDpth"), t = r.column(g, "NMGDepths", "MGThck"),
              d = r.column(g, "NMGDepths", "MGDens");
    for (int k = 0; k < ng; ++k) {
      HydroDynMarineGrowth row{r.number(g, k, z, "MGDpth"), r.number(g, k, t, "MGThck"), r.number(g, k, d, "MGDens"),
                               g.lines[k]};
      if (!(row.thickness >= 0)) throw InputError(r.where(row.line, "MGThck", "must not be negative"));
      if (!(row.density > 0)) throw InputError(r.where(row.line, "MGDens", "must be positive"));
      m.growth.push_back(row);
    }
    std::sort(m.growth.begin(), m.growth.end(), [](const auto& x, const auto& y) { return x.z < y.z; });
    for (std::size_t k = 1; k < m.growth.size(); ++k)
      if (m.growth[k].z == m.growth[k - 1].z)
        throw InputError(r.where(m.growth[k].line, "MGDpth", "the same depth given twice"));
  }
  // The simple table has no count: one row under its column names and units.
  if (const OpenFastTable* t = f.findTable("SimplCa"); t && !t->rows.empty()) {
    auto value = [&](const char* name) -> std::optional<double> {
      const int col = t->columnIndex(name);
      if (col < 0 || col >= static_cast<int>(t->rows[0].size())) return std::nullopt;
      const double v = t->rows[0][col];
      if (!std::isfinite(v)) throw InputError(r.where(t->row_lines[0], name, "not a finite number"));
      return v;
    };
    m.SimplCa = value("SimplCa");
    m.SimplAxCa = value("SimplAxCa");
    m.SimplCaMG = value("SimplCaMG");
  }
}

template <class Row>
const Row* byId(const std::vector<Row>& rows, int id) {
  for (const Row& x : rows)
    if (x.id == id) return &x;
  return nullptr;
}

}  // namespace

const HydroDynJoint* HydroDynMembers::joint(int id) const { return byId(joints, id); }
const HydroDynPropSet* HydroDynMembers::prop(int id) const { return byId(props, id); }
const HydroDynMember* HydroDynMembers::member(int id) const { return byId(members, id); }
const HydroDynAxialCoef* HydroDynMembers::axialCoef(int id) const { return byId(axial, id); }

std::pair<double, double> HydroDynMembers::growthAt(double z) const {
  if (growth.empty() || z < growth.front().z || z > growth.back().z) return {0.0, 0.0};
  if (growth.size() == 1) return {growth[0].thickness, growth[0].density};
  std::size_t k = 1;
  while (k + 1 < growth.size() && growth[k].z < z) ++k;
  const HydroDynMarineGrowth &a = growth[k - 1], &b = growth[k];
  const double f = (z - a.z) / (b.z - a.z);
  return {a.thickness + f * (b.thickness - a.thickness), a.density + f * (b.density - a.density)};
}
const HydroDynMemberCoef* HydroDynMembers::memberCoef(int id) const { return byId(member_coefs, id); }

HydroDynMemberCoef HydroDynMembers::memberCoefs(const HydroDynMember& mb, const OpenFastFile& f) const {
  const std::string file = f.path().string();
  if (mb.MCoefMod == 2)
    throw InputError(whirl::where(file, mb.line, "MCoefMod",
                                  "2 not supported by whirl (depth-based coefficients are not read; 1 or 3)"));
  if (mb.MCoefMod == 3) {
    const HydroDynMemberCoef* c = memberCoef(mb.id);
    if (!c)
      throw InputError(
          whirl::where(file, mb.line, "MCoefMod",
                       "3, but member " + std::to_string(mb.id) + " has no row of member-based coefficients"));
    return *c;
  }
  if (!SimplCa || !SimplAxCa)
    throw InputError(whirl::where(file, mb.line, "MCoefMod", "1, but the simple coefficients are not found"));
  const double mg = SimplCaMG.value_or(*SimplCa);
  return {mb.id, *SimplCa, *SimplCa, *SimplAxCa, *SimplAxCa, mb.line, mg, mg};
}

HydroDynMembers readHydroDynMembers(const OpenFastFile& f, const OpenFastLines& lines) {
  HydroDynMembers m;
  const TableReader r(f, lines);
  readJoints(m, r);
  readProps(m, f, r);
  readMembers(m, r);
  readFills(m, r);
  readCoefficients(m, f, r);
  return m;
}

}  // namespace whirl::io
