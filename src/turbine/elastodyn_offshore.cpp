// HydroDyn's linear terms and MAP++'s mooring lines on the ElastoDyn platform: what OpenFAST's
// linearization of a floating platform contains about a still-water point.
#include <Eigen/Eigenvalues>
#include <cmath>
#include <optional>

#include "src/base/error.hpp"
#include "src/dynamics/catenary.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/offshore/wamit_input.hpp"
#include "src/io/openfast/offshore/wamit_state_space.hpp"
#include "src/io/openfast/refusals.hpp"
#include "src/turbine/elastodyn_parts.hpp"
#include "src/turbine/hydrodyn_ballast.hpp"

namespace whirl::elastodyn {
namespace {

double gravityOf(const Builder& b) { return -b.model().gravity(2); }

// Water density and depth: HydroDyn (v2, v3) or the .fst (v3.5+).
// A water property from HydroDyn (up to OpenFAST v3.5), SeaState (v4+) or the .fst, the first that
// gives it; `default` in HydroDyn or SeaState means the .fst's (their ParseVarWDefault with the glue
// code's value: HydroDyn_Input.f90 v3.5, SeaState_Input.f90).
double water(const io::OpenFastTurbine& t, std::optional<double> hd, std::optional<double> ss,
             std::optional<double> fst, const char* key) {
  if (hd) return *hd;
  if (ss) return *ss;
  if (fst) return *fst;
  throw InputError(
      t.fst.source.where(key, "not in the .fst nor in the HydroDyn or SeaState file: the platform needs it"));
}

// HydroDyn's state-space radiation memory (`RdtnMod = 2`): the states of each DOF's block named after it.
void addRadiationStates(Builder& b, const PlatformParts& p, const io::RadiationStateSpace& ss) {
  static const char* const kDof[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
  BodyStateSpace bs;
  bs.body = p.body;
  bs.A = ss.A;
  bs.B = ss.B;
  bs.C = ss.C;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < ss.per_dof[k]; ++j) bs.groups.push_back(std::string("HydroDyn radiation ") + kDof[k]);
  b.model().body_states.push_back(std::move(bs));
}

// HydroDyn with a WAMIT body [Jonkman2007]: buoyancy ρ g V0 at the centre of buoyancy, the
// hydrostatic restoring of the `.hst` file (about the platform reference point, the WAMIT origin),
// the infinite-frequency added mass of the `.1` file, AddF0, AddCLin, AddBLin, and the fluid of
// filled members (mass and constant weight, src/turbine/hydrodyn_ballast.hpp). AddBQuad's force
// −B |v| v has zero derivative at a static point (v = 0): nothing in the linear model.
void addHydroDyn(Builder& b, const PlatformParts& p, const io::OpenFastTurbine& t) {
  const io::HydroDynInput& hd = *t.hydrodyn;
  if (!hd.geometry.growth.empty())
    throw InputError(hd.source.where("NMGDepths",
                                     "marine growth on a floating platform is not modelled by whirl (on a "
                                     "SubDyn substructure it is)"));
  for (const io::HydroDynMember& mb : hd.geometry.members)
    if (!mb.PropPot)
      throw InputError(whirl::where(hd.source.path().string(), mb.line, "PropPot",
                                    "False not supported by whirl on a floating platform (strip-theory member " +
                                        std::to_string(mb.id) +
                                        ": its buoyancy and added mass on a rigid platform are not modelled; on a "
                                        "SubDyn substructure they are)"));
  const double rho = waterDensity(t), g = gravityOf(b);
  BodyMatrices bm;
  bm.body = p.body;
  bm.K = hd.AddCLin;
  bm.C = hd.AddBLin;
  Eigen::Matrix<double, 6, 1> f0 = hd.AddF0;
  if (hd.PotMod == 1) {
    // The WAMIT matrices act about the WAMIT origin (0, 0, 0): whirl applies them at the platform
    // reference point, so the two must coincide (OpenFAST maps the loads between the meshes).
    if (p.reference.norm() != 0.0)
      throw InputError(b.where(b.ed.config.PtfmRefzt ? "PtfmRefzt" : "PtfmRef",
                               "the platform reference point must be the WAMIT origin (0, 0, 0) with PotMod = 1"));
    const io::WamitMatrices w = io::dimensional(*t.wamit, rho, g);
    bm.K += w.hydrostatic;
    // WAMIT's added mass is symmetric up to its panel discretization (A15 and A51 of the OC3 spar
    // differ in the 6th digit); the mass matrix wants it symmetric.
    bm.A = 0.5 * (w.added_mass + w.added_mass.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(bm.A, Eigen::EigenvaluesOnly);
    const double scale = bm.A.cwiseAbs().maxCoeff();
    if (es.eigenvalues().minCoeff() < -1e-9 * scale)
      throw InputError(hd.source.where("PotFile",
                                       "the added mass at infinite frequency is not positive semi-definite "
                                       "(eigenvalue " +
                                           io::numberText(es.eigenvalues().minCoeff()) + ")"));
    const double B = rho * g * hd.PtfmVol0;
    f0 += (Eigen::Matrix<double, 6, 1>() << 0, 0, B, B * hd.PtfmCOByt, -B * hd.PtfmCOBxt, 0).finished();
    if (hd.RdtnMod == 2) addRadiationStates(b, p, *t.radiation);
  }
  if (!hd.geometry.fills.empty()) {
    const Ballast ballast = ballastOf(hd.geometry, rho, g, p.reference);
    bm.A += ballast.M;
    f0 += ballast.weight;
  }
  b.model().body_matrices.push_back(bm);
  for (int k = 0; k < 6; ++k)
    if (f0(k) != 0.0) b.model().dof_loads.push_back({p.dofs[k], f0(k), -1});
}

// MAP++ lines, each checked at the undisplaced platform so that a line that cannot reach its anchor
// is an input error with its place rather than a failed operating point.
void addMooring(Builder& b, const PlatformParts& p, const io::OpenFastTurbine& t) {
  const double rho = waterDensity(t), depth = waterDepth(t);
  std::vector<MooringLine> lines = io::mapMooringLines(*t.mooring, p.body, depth, rho, gravityOf(b));
  for (const MooringLine& ln : lines) {
    const Vec3 d = p.reference + ln.fairlead - ln.anchor;
    try {
      mooringFairleadForce<double>(ln, d);
    } catch (const ComputeError& e) {
      throw InputError(e.what());
    }
    b.model().mooring.push_back(ln);
  }
}

// HydroDyn on a SubDyn substructure: its strip theory is in the substructure's added mass
// (hydrodyn_strip.hpp), AddF0, AddCLin and AddBLin on the TP (elastodyn_substructure.cpp); what would
// act on a rigid platform instead is refused.
void checkHydroDynOnSubDyn(const io::HydroDynInput& hd) {
  io::Refusals r(hd.source);
  r.addIf(hd.PotMod != 0, "PotMod", "potential flow on a SubDyn substructure is not modelled", "PotMod = 0");
  io::throwIfAny(r.take());
}

}  // namespace

double waterDensity(const io::OpenFastTurbine& t) {
  return water(t, t.hydrodyn ? t.hydrodyn->WtrDens : std::nullopt, t.seastate ? t.seastate->WtrDens : std::nullopt,
               t.fst.WtrDens, "WtrDens");
}

double waterDepth(const io::OpenFastTurbine& t) {
  return water(t, t.hydrodyn ? t.hydrodyn->WtrDpth : std::nullopt, t.seastate ? t.seastate->WtrDpth : std::nullopt,
               t.fst.WtrDpth, "WtrDpth");
}

void addOffshoreLoads(Builder& b, const PlatformParts& p, const io::OpenFastTurbine& t) {
  if (p.body < 0) return;
  if (t.hydrodyn && t.subdyn) {
    checkHydroDynOnSubDyn(*t.hydrodyn);
  } else if (t.hydrodyn) {
    addHydroDyn(b, p, t);
  }
  if (t.mooring) addMooring(b, p, t);
}

}  // namespace whirl::elastodyn
