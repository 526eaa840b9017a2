#include "src/io/openfast/offshore/moordyn_input.hpp"

#include <cmath>
#include <fstream>

#include "src/base/limits.hpp"
#include "src/io/openfast/offshore/mooring_table.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

enum class Section { None, Types, Points, LinesV1, LinesV2, Options, Outputs, Refused };

Section sectionOf(const std::string& heading) {
  const std::string u = toLower(heading);
  if (u.find("line type") != std::string::npos) return Section::Types;
  if (u.find("connection") != std::string::npos || u.find("point") != std::string::npos) return Section::Points;
  if (u.find("line prop") != std::string::npos) return Section::LinesV1;
  if (u.find("lines") != std::string::npos) return Section::LinesV2;
  if (u.find("option") != std::string::npos) return Section::Options;
  if (u.find("output") != std::string::npos) return Section::Outputs;
  if (u.find("bod") != std::string::npos || u.find("rod") != std::string::npos) return Section::Refused;
  return Section::None;
}

// v1 sections open with a count row ("3  NLines - …") before their two heading rows.
bool countRow(const std::vector<std::string>& t) {
  if (t.size() < 2) return false;
  const std::string k = toLower(t[1]);
  return k == "ntypes" || k == "nconnects" || k == "nlines";
}

MapNode point(const MooringTableReader& r, const std::vector<std::string>& t) {
  if (t.size() < 7) throw r.fail("Point", "expected ID Type X Y Z M V …");
  MapNode n;
  n.id = r.integer(t[0], "Point");
  n.line = r.line;
  const std::string type = toLower(t[1]);
  if (type == "fixed" || type == "fix" || type == "anchor") n.fixed = true;
  else if (type == "connect" || type == "free")
    throw r.fail("Type",
                 "connect points (multi-segment lines) are not supported by whirl: only anchor-to-fairlead lines");
  else if (type != "vessel" && type != "coupled" && type != "fairlead")
    throw r.fail("Type", "'" + t[1].substr(0, 40) + "' is not fixed, vessel or connect (bodies are not supported)");
  n.position = Vec3(r.number(t[2], "X"), r.number(t[3], "Y"), r.number(t[4], "Z"));
  if (r.number(t[5], "M") != 0.0 || r.number(t[6], "V") != 0.0)
    throw r.fail("M", "point masses and volumes (M, V ≠ 0) are not supported by whirl");
  return n;
}

}  // namespace

MapInput readMoorDyn(const std::filesystem::path& file) {
  std::istringstream in;
  if (!openInputFile(file.string(), in)) throw InputError(whirl::where(file.string(), 0, "", "cannot open file"));
  MapInput m;
  m.path = file;
  MooringTableReader r{file.string()};
  Section sec = Section::None;
  int header = 0;  // heading and unit rows still to skip in the section
  for (std::string s; std::getline(in, s);) {
    ++r.line;
    const std::vector<std::string> t = mooringTokens(s);
    if (t.empty()) continue;
    if (t[0].rfind("---", 0) == 0) {
      sec = sectionOf(s);
      header = sec == Section::Options || sec == Section::Outputs ? 0 : 2;
      continue;
    }
    if (r.line <= 2 && sec == Section::None) continue;  // title rows
    if (header > 0 && countRow(t)) {
      // MoorDyn v1 reads exactly this many rows (MoorDyn_IO.f90); whirl reads the rows there are and
      // bounds the count, which MoorDyn would allocate.
      const double n = r.number(t[0], t[1]);
      if (n != std::floor(n) || n < 0 || n > limits::kMaxMooringCount)
        throw r.fail(t[1], "must be in [0, " + std::to_string(limits::kMaxMooringCount) + "] (is " +
                               t[0].substr(0, 40) + "; src/base/limits.hpp)");
      continue;
    }
    if (header > 0) {
      --header;
      continue;
    }
    switch (sec) {
      case Section::Types: {
        if (t.size() < 4) throw r.fail("LineType", "expected Name Diam MassDen EA …");
        MapLineType lt{t[0], r.number(t[1], "Diam"), r.number(t[2], "MassDen"), r.number(t[3], "EA"), 0.0, r.line};
        if (!(lt.Diam >= 0)) throw r.fail("Diam", "must not be negative");
        if (!(lt.MassDenInAir > 0)) throw r.fail("MassDen", "must be positive");
        if (!(lt.EA > 0)) throw r.fail("EA", "must be positive");
        m.types.push_back(lt);
        break;
      }
      case Section::Points: m.nodes.push_back(point(r, t)); break;
      case Section::LinesV1:
      case Section::LinesV2: {
        // v1: Line LineType UnstrLen NumSegs NodeAnch NodeFair; v2: ID LineType AttachA AttachB UnstrLen NumSegs.
        if (t.size() < 6) throw r.fail("Line", "expected 6 columns: ID, LineType, two points, UnstrLen, NumSegs");
        const bool v1 = sec == Section::LinesV1;
        MapLine l{r.integer(t[0], "Line"),
                  t[1],
                  r.number(t[v1 ? 2 : 4], "UnstrLen"),
                  r.integer(t[v1 ? 4 : 2], v1 ? "NodeAnch" : "AttachA"),
                  r.integer(t[v1 ? 5 : 3], v1 ? "NodeFair" : "AttachB"),
                  r.line};
        if (!(l.UnstrLen > 0)) throw r.fail("UnstrLen", "must be positive");
        m.lines.push_back(l);
        break;
      }
      case Section::Options:
      case Section::Outputs: break;  // the dynamic solver's settings and output channels
      case Section::Refused:         // a body or rod row (an empty section of them is fine)
        throw r.fail("", "MoorDyn bodies and rods are not supported by whirl: only anchor-to-fairlead lines");
      case Section::None:
        throw r.fail("",
                     "data outside a LINE TYPES, CONNECTION PROPERTIES / POINTS, LINE PROPERTIES / LINES, "
                     "SOLVER OPTIONS or OUTPUTS section");
    }
  }
  // v2 lines may name the fairlead first: anchor = the fixed point of the two.
  for (MapLine& l : m.lines) {
    for (const MapNode& n : m.nodes)
      if (n.id == l.fairlead && n.fixed) std::swap(l.anchor, l.fairlead);
  }
  if (m.lines.empty()) throw InputError(whirl::where(m.path.string(), 0, "Line", "no mooring line"));
  requireUniqueMooringIds(m);
  return m;
}

}  // namespace whirl::io
