#pragma once
/// \file
/// MAP++ input file (the mooring file of CompMooring = 1): line dictionary, nodes, lines and solver
/// options, as the OpenFAST certification decks write them (MAP++ v1). whirl reads single-segment
/// lines from a fixed anchor to a vessel fairlead, and the `repeat` option (copies of the whole line
/// set turned about the vertical by the given angles); connect nodes (multi-segment lines), clump
/// weights and buoys are refused. Every error reads "file:line: key: reason".
#include <filesystem>
#include <string>
#include <vector>

#include "src/model/mooring.hpp"

namespace whirl::io {

struct MapLineType {
  std::string name;
  double Diam = 0, MassDenInAir = 0, EA = 0, CB = 0;  ///< m, kg/m, N, -
  int line = 0;
};

struct MapNode {
  int id = 0;
  bool fixed = false;  ///< `fix` (anchor); otherwise `vessel` (fairlead)
  Vec3 position = Vec3::Zero();
  bool at_depth = false;  ///< Z written `depth`: on the seabed
  int line = 0;
};

struct MapLine {
  int id = 0;
  std::string type;
  double UnstrLen = 0;
  int anchor = 0, fairlead = 0;  ///< node ids
  int line = 0;
};

struct MapInput {
  std::filesystem::path path;
  std::vector<MapLineType> types;
  std::vector<MapNode> nodes;
  std::vector<MapLine> lines;
  std::vector<double> repeat_deg;  ///< `repeat` angles [deg]
};

/// Reads a MAP++ input file. InputError "file:line: key: reason" on anything malformed or refused.
MapInput readMap(const std::filesystem::path& file);

/// Refuses two line types with one name (case-insensitive), two nodes (points) with one id and two lines
/// with one id, naming the second row and the line of the first: MAP++ and MoorDyn look nodes up by id
/// (MAP++ by row order, which whirl, looking up ids, would not follow), so either would silently read
/// another mooring than OpenFAST does. Used by readMap and readMoorDyn.
void requireUniqueMooringIds(const MapInput& m);

/// The mooring lines of `map` on body `body` (fairleads in its frame, whose origin is the platform
/// reference point), for water depth `depth` [m], density `rho` [kg/m³] and gravity `g` [m/s²]: the
/// weight in water w = (MassDenInAir − ρ π Diam²/4) g. InputError when a line floats (w ≤ 0), its
/// anchor is not below its fairlead, or below the seabed. An anchor straight below its fairlead (a
/// tension-leg tendon) is a line like the others (src/dynamics/catenary.hpp: the taut-line form).
std::vector<MooringLine> mapMooringLines(const MapInput& map, int body, double depth, double rho, double g);

}  // namespace whirl::io
