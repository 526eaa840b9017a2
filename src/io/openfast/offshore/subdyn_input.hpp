#pragma once
/// \file
/// SubDyn input file: the substructure of a fixed-bottom offshore turbine as SubDyn describes it —
/// joints, members between joints with circular tubular cross-sections (E, G, ρ, D, t), base reaction
/// joints, interface joints tied to the transition piece, joint lumped masses, the element model
/// (FEMMod), the member subdivision (NDiv), the Craig–Bampton modes kept (Nmodes, CBMod) and their
/// damping (JDampings), and the Guyan damping of OpenFAST v3+ (GuyanDampMod).
///
/// Layouts read: SubDyn v1.01 (the OpenFAST certification decks: `CBMod`, 4-column joints, 6-column
/// members with COSMID) and the OpenFAST v3–v5 layouts (`Nmodes < 0` = every mode, 9-column joints
/// with JointType, 7-column members with MType, Guyan damping, the rectangular/cable/rigid/spring
/// property tables, the interface TPID column). Scalars are read by key (so `--set Nmodes=8` works),
/// each table positionally below its count key (header and unit rows, then exactly that many rows, then
/// a `---` section line), as SubDyn reads it.
///
/// Refused with `file:line: key: reason` (not ignored): FEMMod 2 and 4 (tapered elements, which SubDyn
/// does not implement either), soil–structure interaction (an SSIfile on a reaction joint with a free
/// DOF), a floating substructure (NReact = 0, or an interface TPID = 0), several transition pieces,
/// joints other than cantilever (JointType ≠ 1), members other than circular beams (cables, rigid
/// links, rectangular and arbitrary sections, springs), interface DOFs not all locked (SubDyn refuses
/// them too), concentrated masses with a centre-of-mass offset. Time integration, the static improvement
/// method and the output lists do not enter a linearization without hydrodynamic loads: ignored.
/// Every count is bounded (src/base/limits.hpp) before its rows are read.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "src/base/types.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// A joint: `JointID` and its position in the substructure frame (SubDyn's SS frame = OpenFAST's
/// inertial frame: X downwind, Z up, origin on the tower axis at MSL) [m].
struct SubDynJoint {
  int id = 0;
  Vec3 position = Vec3::Zero();
  int line = 0;  ///< 1-based line of the row
};

/// A base reaction joint: which of its DOFs (translations x, y, z, rotations x, y, z) are held.
struct SubDynReaction {
  int joint = 0;
  std::array<bool, 6> fixed{true, true, true, true, true, true};
  int line = 0;
};

/// An interface joint, rigidly tied to the transition piece (ElastoDyn's platform reference point).
struct SubDynInterface {
  int joint = 0;
  int line = 0;
};

/// A member from joint `joint1` to `joint2`, cross-section `prop1` at joint 1 and `prop2` at joint 2
/// (diameter and thickness interpolated linearly between them).
struct SubDynMember {
  int id = 0;
  int joint1 = 0, joint2 = 0;
  int prop1 = 0, prop2 = 0;
  int line = 0;
};

/// A circular tubular cross-section: Young's and shear moduli [N/m²], density [kg/m³], outer diameter
/// and wall thickness [m] (thickness ≤ 0: a solid section, as SubDyn reads it).
struct SubDynSection {
  int id = 0;
  double E = 0, G = 0, rho = 0, D = 0, t = 0;
  int line = 0;
};

/// A lumped mass at a joint: mass [kg] and inertia about the joint in the SS axes [kg m²].
struct SubDynMass {
  int joint = 0;
  double mass = 0;
  Mat3 inertia = Mat3::Zero();
  int line = 0;
};

struct SubDynInput {
  OpenFastFile source;  ///< the parsed file (path, line of every key)
  int FEMMod = 1;       ///< element model {1 Euler–Bernoulli, 3 Timoshenko}
  int NDiv = 1;         ///< elements per member
  /// Craig–Bampton modes kept: 0 = Guyan, −1 = all of them (the full FE model; `CBMod = False` in
  /// v1.01 layouts, `Nmodes < 0` from OpenFAST v2).
  int Nmodes = 0;
  /// Damping ratio of each kept mode (fraction of critical; the file gives %), the last value
  /// repeated up to Nmodes as SubDyn does; one value for every mode when Nmodes = −1; empty for Guyan.
  std::vector<double> JDampings;
  int GuyanDampMod = 0;                  ///< {0 none, 1 Rayleigh, 2 matrix}; absent in v1.01 (= 0)
  std::array<double, 2> RayleighDamp{};  ///< α [1/s], β [s] of C_BB = α M_BB + β K_BB
  Eigen::Matrix<double, 6, 6> GuyanDampMat = Eigen::Matrix<double, 6, 6>::Zero();  ///< [N s/m, …]
  std::vector<SubDynJoint> joints;
  std::vector<SubDynReaction> reactions;
  std::vector<SubDynInterface> interfaces;
  std::vector<SubDynMember> members;
  std::vector<SubDynSection> sections;
  std::vector<SubDynMass> masses;
  std::vector<std::string> notes;  ///< inputs read and ignored, one line each

  /// Index in `joints` of the joint with this id; −1 when none.
  int jointIndex(int id) const;
  /// Index in `sections` of the property set with this id; −1 when none.
  int sectionIndex(int id) const;
  /// "file:line: key: reason" for a table row.
  std::string where(int line, const std::string& key, const std::string& reason) const;
};

/// Reads a SubDyn file; `overrides` (may be null) apply to its scalar keys. Checks the tables against
/// each other (ids unique, members between distinct joints at distinct positions, property sets that
/// exist and are circular, reaction and interface joints that exist and differ) and throws InputError
/// `file:line: key: reason` for the first problem, or one message with every refusal.
SubDynInput readSubDyn(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
