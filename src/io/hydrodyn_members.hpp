#pragma once
/// \file
/// HydroDyn's member geometry: the MEMBER JOINTS, MEMBER CROSS-SECTION PROPERTIES, MEMBERS and FILLED
/// MEMBERS tables, read by position below their count keys as HydroDyn's input routine reads them
/// (column-name row, unit row, then exactly that many rows), with the columns of the joint, property
/// and member tables found by name so that the v2.03 layout of the certification decks and the wider
/// v3–v5 layouts read alike. Coordinates are HydroDyn's global frame: x downwind, z up, z = 0 at mean
/// sea level (m).
#include <optional>
#include <string>
#include <vector>

#include "src/io/openfast_input.hpp"
#include "src/model/types.hpp"

namespace whirl::io {

class OpenFastLines;

struct HydroDynJoint {
  int id = 0;
  Vec3 position = Vec3::Zero();  ///< (Jointxi, Jointyi, Jointzi) (m)
  int line = 0;
};

struct HydroDynPropSet {
  int id = 0;
  double D = 0.0;          ///< outer diameter PropD (m)
  double thickness = 0.0;  ///< wall thickness PropThck (m)
  int line = 0;
};

struct HydroDynMember {
  int id = 0;
  int joint1 = 0, joint2 = 0;  ///< MJointID1, MJointID2
  int prop1 = 0, prop2 = 0;    ///< MPropSetID1, MPropSetID2 (at joint 1 and joint 2)
  bool PropPot = false;        ///< true: modelled by potential flow (only viscous drag from strip theory)
  int line = 0;
};

struct HydroDynFillGroup {
  std::vector<int> members;        ///< FillMList
  double FillFSLoc = 0.0;          ///< free-surface height of the fluid inside (m, from MSL)
  std::optional<double> FillDens;  ///< fluid density (kg/m³); nullopt: DEFAULT, the water density
  int line = 0;
};

struct HydroDynMembers {
  std::vector<HydroDynJoint> joints;
  std::vector<HydroDynPropSet> props;
  std::vector<HydroDynMember> members;
  std::vector<HydroDynFillGroup> fills;

  /// The joint, property set or member of an id; nullptr when there is none.
  const HydroDynJoint* joint(int id) const;
  const HydroDynPropSet* prop(int id) const;
  const HydroDynMember* member(int id) const;
};

/// Reads the four tables of a HydroDyn file (absent count keys: empty tables). Every row is checked
/// against the others: duplicate ids, a member whose joints or property sets do not exist or whose
/// joints coincide (zero length), a property set with D ≤ 0 or a wall thickness outside [0, D/2], a
/// fill group naming an unknown member or one already filled, a FillDens ≤ 0 — each an InputError
/// "file:line: key: reason" naming the row's line. Counts are bounded (src/model/limits.hpp).
HydroDynMembers readHydroDynMembers(const OpenFastFile& f, const OpenFastLines& lines);

}  // namespace whirl::io
