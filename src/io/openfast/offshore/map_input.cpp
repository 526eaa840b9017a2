#include "src/io/openfast/offshore/map_input.hpp"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <unordered_map>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/offshore/mooring_table.hpp"
#include "src/io/openfast/openfast_input.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

enum class Section { None, Dictionary, Nodes, Lines, Options };

}  // namespace

MapInput readMap(const std::filesystem::path& file) {
  std::istringstream in;
  if (!openInputFile(file.string(), in)) throw InputError(whirl::where(file.string(), 0, "", "cannot open file"));
  MapInput m;
  m.path = file;
  MooringTableReader r{file.string()};
  Section sec = Section::None;
  int header = 0;  // header and unit rows still to skip in the section
  for (std::string s; std::getline(in, s);) {
    ++r.line;
    const std::vector<std::string> t = mooringTokens(s);
    if (t.empty()) continue;
    if (s.rfind("---", 0) == 0 || t[0].rfind("---", 0) == 0) {
      const std::string u = toLower(s);
      sec = u.find("dictionary") != std::string::npos  ? Section::Dictionary
            : u.find("node") != std::string::npos      ? Section::Nodes
            : u.find("line prop") != std::string::npos ? Section::Lines
            : u.find("option") != std::string::npos    ? Section::Options
                                                       : Section::None;
      header = 2;
      continue;
    }
    if (header > 0) {
      --header;
      continue;
    }
    switch (sec) {
      case Section::Dictionary: {
        if (t.size() < 5) throw r.fail("LineType", "expected LineType Diam MassDenInAir EA CB …");
        MapLineType lt{
            t[0],  r.number(t[1], "Diam"), r.number(t[2], "MassDenInAir"), r.number(t[3], "EA"), r.number(t[4], "CB"),
            r.line};
        if (!(lt.Diam >= 0)) throw r.fail("Diam", "must not be negative");
        if (!(lt.MassDenInAir > 0)) throw r.fail("MassDenInAir", "must be positive");
        if (!(lt.EA > 0)) throw r.fail("EA", "must be positive");
        if (!(lt.CB >= 0)) throw r.fail("CB", "must not be negative");
        m.types.push_back(lt);
        break;
      }
      case Section::Nodes: {
        if (t.size() < 7) throw r.fail("Node", "expected Node Type X Y Z M B …");
        MapNode n;
        n.id = r.integer(t[0], "Node");
        n.line = r.line;
        const std::string type = toLower(t[1]);
        if (type == "fix" || type == "fixed") n.fixed = true;
        else if (type == "connect")
          throw r.fail("Type",
                       "connect nodes (multi-segment lines) are not supported by whirl: only anchor-to-fairlead lines");
        else if (type != "vessel") throw r.fail("Type", "'" + t[1] + "' is not fix, vessel or connect");
        n.position(0) = r.number(t[2], "X");
        n.position(1) = r.number(t[3], "Y");
        if (toLower(t[4]) == "depth") n.at_depth = true;
        else n.position(2) = r.number(t[4], "Z");
        if (r.number(t[5], "M") != 0.0 || r.number(t[6], "B") != 0.0)
          throw r.fail("M", "clump weights and buoys (M, B ≠ 0) are not supported by whirl");
        m.nodes.push_back(n);
        break;
      }
      case Section::Lines: {
        if (t.size() < 5) throw r.fail("Line", "expected Line LineType UnstrLen NodeAnch NodeFair …");
        MapLine l{r.integer(t[0], "Line"),     t[1],  r.number(t[2], "UnstrLen"), r.integer(t[3], "NodeAnch"),
                  r.integer(t[4], "NodeFair"), r.line};
        if (!(l.UnstrLen > 0)) throw r.fail("UnstrLen", "must be positive");
        m.lines.push_back(l);
        break;
      }
      case Section::Options: {
        if (toLower(t[0]) == "repeat")
          for (std::size_t k = 1; k < t.size(); ++k) m.repeat_deg.push_back(r.number(t[k], "repeat"));
        break;  // the other options tune MAP++'s solver
      }
      case Section::None:
        throw r.fail("", "data outside a LINE DICTIONARY, NODE PROPERTIES, LINE PROPERTIES or SOLVER OPTIONS section");
    }
  }
  if (m.lines.empty()) throw InputError(whirl::where(m.path.string(), 0, "Line", "no mooring line"));
  requireUniqueMooringIds(m);
  return m;
}

void requireUniqueMooringIds(const MapInput& m) {
  const std::string file = m.path.string();
  // One pass per kind with a map from id to its first line (the files may be long: no pairwise loop).
  auto check = [&](const char* key, const std::string& id, int line, std::unordered_map<std::string, int>& seen) {
    const auto [it, inserted] = seen.emplace(id, line);
    if (!inserted)
      throw InputError(whirl::where(file, line, key,
                                    "'" + id.substr(0, 40) + "' given twice (first on line " +
                                        std::to_string(it->second) + "): ids must be unique"));
  };
  std::unordered_map<std::string, int> types, nodes, lines;
  for (const MapLineType& t : m.types) check("LineType", toLower(t.name), t.line, types);
  for (const MapNode& n : m.nodes) check("Node", std::to_string(n.id), n.line, nodes);
  for (const MapLine& l : m.lines) check("Line", std::to_string(l.id), l.line, lines);
}

std::vector<MooringLine> mapMooringLines(const MapInput& map, int body, double depth, double rho, double g) {
  const std::string file = map.path.string();
  auto node = [&](int id, const MapLine& l, const char* key) -> const MapNode& {
    for (const MapNode& n : map.nodes)
      if (n.id == id) return n;
    throw InputError(whirl::where(file, l.line, key, "no node " + std::to_string(id)));
  };
  std::vector<MooringLine> base;
  for (const MapLine& l : map.lines) {
    const MapLineType* type = nullptr;
    for (const MapLineType& t : map.types)
      if (toLower(t.name) == toLower(l.type)) type = &t;
    if (!type)
      throw InputError(whirl::where(file, l.line, "LineType", "no line type '" + l.type + "' in the dictionary"));
    const MapNode& a = node(l.anchor, l, "NodeAnch");
    const MapNode& f = node(l.fairlead, l, "NodeFair");
    if (!a.fixed)
      throw InputError(whirl::where(file, l.line, "NodeAnch", "node " + std::to_string(a.id) + " is not a fix node"));
    if (f.fixed)
      throw InputError(
          whirl::where(file, l.line, "NodeFair", "node " + std::to_string(f.id) + " is not a vessel node"));
    MooringLine ml;
    ml.body = body;
    ml.fairlead = f.position;
    ml.anchor = a.position;
    if (a.at_depth) ml.anchor(2) = -depth;
    ml.seabed = a.at_depth || std::abs(ml.anchor(2) + depth) <= 1e-9 * depth;
    ml.length = l.UnstrLen;
    ml.weight = (type->MassDenInAir - rho * std::numbers::pi * type->Diam * type->Diam / 4.0) * g;
    ml.EA = type->EA;
    ml.CB = type->CB;
    if (!(ml.weight > 0))
      throw InputError(whirl::where(file, type->line, "MassDenInAir",
                                    "the line floats (weight in water " + numberText(ml.weight) +
                                        " N/m ≤ 0): a catenary needs a positive weight in water"));
    if (ml.anchor(2) < -depth * (1 + 1e-9))
      throw InputError(whirl::where(file, a.line, "Z", "anchor below the seabed (depth " + numberText(depth) + " m)"));
    if (!(ml.anchor(2) < ml.fairlead(2)))
      throw InputError(whirl::where(file, l.line, "NodeAnch", "the anchor must be below its fairlead"));
    base.push_back(ml);
  }
  // `repeat`: the whole set again, turned about the vertical by each angle.
  std::vector<MooringLine> out = base;
  for (double deg : map.repeat_deg) {
    const Mat3 R = Eigen::AngleAxisd(deg * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
    for (MooringLine ml : base) {
      ml.fairlead = R * ml.fairlead;
      ml.anchor = R * ml.anchor;
      out.push_back(ml);
    }
  }
  // Names carry the place of the line's row: "map.dat:14: Line 1", "… Line 1 (repeat 240 deg)".
  for (std::size_t k = 0; k < out.size(); ++k) {
    const MapLine& l = map.lines[k % map.lines.size()];
    out[k].name = file + ":" + std::to_string(l.line) + ": Line " + std::to_string(l.id);
    if (k >= map.lines.size())
      out[k].name += " (repeat " + numberText(map.repeat_deg[k / map.lines.size() - 1]) + " deg)";
  }
  return out;
}

}  // namespace whirl::io
