#pragma once
/// \file
/// BeamDyn input files: the primary file (numerical options, the blade reference axis as members of
/// key points with their initial twist, the pitch actuator, `BldFile`) and the blade file (stations
/// along the reference axis, each with its 6 × 6 cross-section stiffness and mass matrices, and the
/// stiffness-proportional damping `mu`). Values in SI, angles in radians.
///
/// Frames and orderings as BeamDyn writes them (OpenFAST docs/source/user/beamdyn/input_files.rst;
/// modules/beamdyn/src/BeamDyn_IO.f90, BD_ReadPrimaryFile and BD_ReadBladeFile):
/// - key points (`kp_xr kp_yr kp_zr`) in the blade-root frame: z_r along the pitch axis towards the tip,
///   x_r flapwise (ElastoDyn's j1, downwind at zero pitch and azimuth), y_r edgewise (j2);
/// - the 6 × 6 matrices are in the section frame, which is the reference-axis frame turned about the
///   tangent by −initial_twist (BeamDyn stores −twist on reading, BeamDyn_Subs.f90
///   BD_ComputeIniNodalCrv turns by that angle); rows and columns ordered as the sectional
///   strains/forces [F1, F2, F3, M1, M2, M3]: 1, 2 shear (γ), 3 extension along the axis, then the
///   two bending curvatures about axes 1 and 2 and torsion about 3 — index 3 (0-based 2) is axial,
///   index 6 (0-based 5) is torsion;
/// - the mass matrix is [m 1, −m c̃; m c̃, J] with c the mass-centre offset in the section and J the
///   inertia per length about the reference axis.
///
/// Read layouts: BeamDyn v1.00/v1.01 (certification decks) and the OpenFAST v3–v5 primary files;
/// the blade file with or without the modal-damping block (`n_modes`, OpenFAST v4+). Scalars are
/// read by key (overrides apply), tables positionally as BeamDyn reads them.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "src/base/types.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

using Mat6d = Eigen::Matrix<double, 6, 6>;

/// A key point of the reference axis: position in the blade-root frame [m] and initial twist [rad]
/// (as written in the file: positive = leading edge into the wind, BeamDyn turns the section by −it).
struct BeamDynKeyPoint {
  Vec3 r = Vec3::Zero();
  double twist = 0;
  int line = 0;
};

/// A cross-section station: η ∈ [0, 1] along the reference axis, its 6 × 6 stiffness [N, N m, N m²]
/// and mass [kg/m, kg, kg m] matrices in the section frame (see the file comment).
struct BeamDynStation {
  double eta = 0;
  Mat6d K = Mat6d::Zero();
  Mat6d M = Mat6d::Zero();
  int line = 0;  ///< line of η
};

/// The blade file.
struct BeamDynBlade {
  OpenFastFile source;
  int damp_type = 0;           ///< 0 none, 1 stiffness-proportional (mu), 2 modal (refused)
  std::array<double, 6> mu{};  ///< stiffness-proportional damping per strain component [s]
  std::vector<BeamDynStation> stations;
  int mu_line = 0;
};

/// The primary file with its blade file.
struct BeamDynInput {
  OpenFastFile source;
  int quadrature = 2;                  ///< 1 Gauss, 2 trapezoidal (BeamDyn's own discretisation: read, not used)
  int refine = 1;                      ///< trapezoidal refinement (read, not used)
  int order_elem = 0;                  ///< BeamDyn's element order (read, not used: whirl meshes the axis itself)
  std::vector<int> member_key_points;  ///< key points of each member (shared at member ends)
  std::vector<BeamDynKeyPoint> key_points;
  bool UsePitchAct = false;
  BeamDynBlade blade;

  /// "file:line: key: reason" in the primary file.
  std::string where(int line, const std::string& key, const std::string& reason) const;
};

/// Reads a BeamDyn primary file (overrides apply to its scalars) and the blade file it names (`BldFile`,
/// relative to it).
/// \throws InputError `file:line: key: reason` for a missing key, a value of the wrong type, a
///   truncated table, a key-point count that does not match the members, key points not along +z
///   (the axis must leave the root towards the tip), stations not increasing from 0 to 1, a 6 × 6
///   matrix not symmetric or not positive definite (naming the station), and the options whirl does
///   not model (UsePitchAct = True, modal damping).
BeamDynInput readBeamDyn(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

/// Reads a blade file alone (no overrides: its tables are positional).
BeamDynBlade readBeamDynBlade(const std::filesystem::path& file);

/// The same from text (the fuzz harness and the tests); `file` names it in messages and resolves `BldFile`.
BeamDynBlade parseBeamDynBlade(std::string_view text, const std::filesystem::path& file);

}  // namespace whirl::io
