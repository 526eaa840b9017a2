#pragma once
/// \file
/// HydroDyn input file: what OpenFAST's linearization of HydroDyn contains for a floating platform
/// modelled by potential flow (PotMod = 1, one WAMIT body): water density and depth, the WAMIT files'
/// root name and length scale, the displaced volume and centre of buoyancy, the radiation model, and
/// the additional preload, stiffness and damping matrices. The layouts of the OpenFAST
/// certification decks (HydroDyn v2.03) and the v3–v5 keys of the same names are read. Incident
/// waves, currents and second-order forces do not enter a linearization about a still-water point:
/// they are ignored, each with one line in `notes`.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/base/types.hpp"
#include "src/io/openfast/offshore/hydrodyn_members.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

struct HydroDynInput {
  OpenFastFile source;             ///< the parsed file (path, line of every key)
  std::optional<double> WtrDens;   ///< water density (kg/m³); in the .fst from OpenFAST v3.5 (then absent here)
  std::optional<double> WtrDpth;   ///< water depth (m); idem
  int PotMod = 0;                  ///< potential-flow model {0 none, 1 WAMIT, 2 FIT}
  std::filesystem::path PotFile;   ///< root name of the WAMIT files (.hst, .1), resolved against this file
  double WAMITULEN = 1.0;          ///< WAMIT length scale (m)
  double PtfmVol0 = 0.0;           ///< displaced volume at the undisplaced position (m³)
  double PtfmCOBxt = 0.0;          ///< centre of buoyancy from the platform reference point, downwind (m)
  double PtfmCOByt = 0.0;          ///< idem, lateral (m)
  int RdtnMod = 0;                 ///< radiation memory {0 none, 1 convolution, 2 state space}
  std::optional<int> NBody;        ///< number of WAMIT bodies (v3+)
  Vec6 AddF0 = Vec6::Zero();       ///< additional preload (N, N m)
  Mat6 AddCLin = Mat6::Zero();     ///< additional linear stiffness (N/m, N/rad, N m/m, N m/rad)
  Mat6 AddBLin = Mat6::Zero();     ///< additional linear damping (N/(m/s), …)
  Mat6 AddBQuad = Mat6::Zero();    ///< additional quadratic drag (N/(m/s)², …)
  HydroDynMembers geometry;        ///< member joints, properties, members and fill groups
  std::vector<std::string> notes;  ///< inputs read and ignored for linearization, one line each
};

/// Reads a HydroDyn file. Refuses (InputError "file:line: key: value not supported by whirl (reason)")
/// what would change the linear model and is not modelled: PotMod = 2 (FIT), RdtnMod = 1 (convolution,
/// which OpenFAST refuses for linearization too), NBody > 1, and a v2 force flag (PtfmSgF … PtfmYF) set
/// to False. A 6×6 matrix whose rows are missing or not numbers names the key's line.
HydroDynInput readHydroDyn(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io
