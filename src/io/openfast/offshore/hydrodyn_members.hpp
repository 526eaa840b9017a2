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

#include "src/base/types.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OpenFastLines;

struct HydroDynJoint {
  int id = 0;
  Vec3 position = Vec3::Zero();  ///< (Jointxi, Jointyi, Jointzi) (m)
  int line = 0;
  int axial_coef = 0;  ///< JointAxID: a row of the AXIAL COEFFICIENTS table (0: none given)
};

/// A row of AXIAL COEFFICIENTS: the joints' axial added-mass coefficient (end effects).
struct HydroDynAxialCoef {
  int id = 0;
  double AxCa = 0.0;
  int line = 0;
};

/// A member's added-mass coefficients at its two ends: transverse (MemberCa1, 2) and axial on a
/// taper (MemberAxCa1, 2).
struct HydroDynMemberCoef {
  int id = 0;
  double Ca1 = 0.0, Ca2 = 0.0;
  double AxCa1 = 0.0, AxCa2 = 0.0;
  int line = 0;
  double CaMG1 = 0.0, CaMG2 = 0.0;  ///< transverse, where marine growth covers the member
};

/// A row of MARINE GROWTH: thickness and density at a depth (z, m from MSL, negative down); linear
/// between rows, none outside them.
struct HydroDynMarineGrowth {
  double z = 0.0, thickness = 0.0, density = 0.0;
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
  int MCoefMod = 1;  ///< coefficients from {1 the simple, 2 the depth-based, 3 the member-based} table
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
  std::vector<HydroDynAxialCoef> axial;      ///< AXIAL COEFFICIENTS
  std::optional<double> SimplCa;             ///< the simple table's transverse added-mass coefficient
  std::optional<double> SimplAxCa;           ///< … and its axial one (on tapers)
  std::optional<double> SimplCaMG;           ///< … and the transverse one under marine growth
  std::vector<HydroDynMarineGrowth> growth;  ///< MARINE GROWTH, by increasing z
  /// Marine-growth thickness [m] and density [kg/m³] at height z (0, 0 outside the table's depths).
  std::pair<double, double> growthAt(double z) const;
  std::vector<HydroDynMemberCoef> member_coefs;  ///< MEMBER-BASED HYDRODYNAMIC COEFFICIENTS

  /// The joint, property set or member of an id; nullptr when there is none.
  const HydroDynJoint* joint(int id) const;
  const HydroDynPropSet* prop(int id) const;
  const HydroDynMember* member(int id) const;
  const HydroDynAxialCoef* axialCoef(int id) const;
  const HydroDynMemberCoef* memberCoef(int id) const;
  /// The member's added-mass coefficients at its joint 1 and joint 2 (MCoefMod 1 or 3): transverse
  /// Ca1, Ca2 and axial AxCa1, AxCa2. InputError naming the member's line for MCoefMod = 2
  /// (depth-based, not read) or a missing row.
  HydroDynMemberCoef memberCoefs(const HydroDynMember& m, const OpenFastFile& f) const;
};

/// Reads the four tables of a HydroDyn file (absent count keys: empty tables). Every row is checked
/// against the others: duplicate ids, a member whose joints or property sets do not exist or whose
/// joints coincide (zero length), a property set with D ≤ 0 or a wall thickness outside [0, D/2], a
/// fill group naming an unknown member or one already filled, a FillDens ≤ 0 — each an InputError
/// "file:line: key: reason" naming the row's line. Counts are bounded (src/base/limits.hpp).
HydroDynMembers readHydroDynMembers(const OpenFastFile& f, const OpenFastLines& lines);

}  // namespace whirl::io
