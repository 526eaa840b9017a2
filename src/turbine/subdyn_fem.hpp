#pragma once
/// \file
/// A SubDyn substructure as a whirl FE body (src/fem/): SubDyn's discretization and element properties,
/// its boundary conditions and its reduction, built from the input file (src/io/openfast/offshore/subdyn_input.hpp).
///
/// As SubDyn [SubDyn] (SD_FEM.f90, SD_Discrt and SetElementProperties, OpenFAST v4):
/// - nodes: the joints, then NDiv − 1 equally spaced nodes inside each member (member order), whose
///   diameter and thickness are interpolated linearly between the member's two property sets;
/// - elements: NDiv per member, each with a constant circular tubular section of the mean outer
///   diameter and mean thickness of its two nodes (r_o = (D₁ + D₂)/4, t = (t₁ + t₂)/2, r_i = r_o − t,
///   or 0 for a solid section): A = π(r_o² − r_i²), I = π(r_o⁴ − r_i⁴)/4 about both axes, J = 2I,
///   mass ρA per length with rotary inertia ρI about each bending axis; E, G, ρ of the first set;
/// - FEMMod = 3 (Timoshenko): shear stiffness κGA with the thick-tube shear coefficient of
///   Steinboeck et al. (2013) that SubDyn's theory manual gives (eq. 13),
///   κ = 6(1+ν)²(1+m²)² / [(1+m²)²(7+14ν+8ν²) + 4m²(5+10ν+4ν²)], ν = E/(2G) − 1, m = r_i/r_o;
/// - reaction joints hold the DOFs flagged 1; joint lumped masses (mass and inertia about the joint);
/// - the interface joints are tied rigidly to the transition piece (TP) at `tp_reference`, ElastoDyn's
///   platform reference point, whose six DOFs (ground axes) are the body's first coordinates;
/// - Nmodes = 0: Guyan reduction to the TP; Nmodes > 0: Craig–Bampton with Nmodes fixed-interface
///   modes; Nmodes = −1: every fixed-interface mode, i.e. the full FE model (as SubDyn's CBMod = False);
/// - damping: each kept mode 2 ζ ω times its modal mass (JDampings), the TP DOFs C_BB = α M_BB + β K_BB
///   (GuyanDampMod = 1) or the given 6×6 matrix (GuyanDampMod = 2), none otherwise (SubDyn v1.01).
///
/// Differences from SubDyn: the element mass of whirl's Timoshenko element is consistent with its
/// shear-deformable shape functions (SubDyn uses the Euler–Bernoulli consistent mass for both element
/// models: a difference of the order of the shear parameter Φ = 12EI/(κGAL²) in the mass); the shear
/// coefficient of a solid section (t ≤ 0) uses m = 0 (SubDyn's formula takes the inner diameter
/// D − 2t, which for t = 0 gives m = 1). Neither code has geometric stiffness in the substructure.
#include <string>
#include <vector>

#include "src/fem/fem_body.hpp"
#include "src/io/openfast/offshore/subdyn_input.hpp"

namespace whirl {

/// The FE description of a SubDyn file: the body spec (model, TP tie, reduction) and node names.
struct SubDynFem {
  fem::FemBodySpec spec;
  std::vector<std::string> node_names;  ///< "joint 3", "member 2 node 2" (SubDyn's local node numbers)
};

/// The FE model of `sd` with the interface tied to `tp_reference` [m, ground frame]. The TP point of
/// the body is named "TP". Throws InputError naming the SubDyn file (Nmodes larger than the interior
/// DOFs, a reaction that leaves the structure free).
SubDynFem subDynFem(const io::SubDynInput& sd, const Vec3& tp_reference);

/// The substructure as a whirl body: `fem::buildFemBody` of subDynFem plus the damping above. The
/// coordinates are the TP's six DOFs ("TP ux" … "TP rz") then "CB 1" … (Craig–Bampton modes).
/// `added_mass` (optional, on the FE model's full DOFs, 6 per node: e.g. HydroDyn's strip theory) is
/// projected on the body's coordinates: added_mass_e = basisᵀ A basis.
struct SubDynBody {
  fem::FemBody fem;
  MatX damping;     ///< ne × ne [N s/m, …]
  MatX added_mass;  ///< ne × ne [kg, …]; empty without `added_mass`
};
SubDynBody buildSubDynBody(const io::SubDynInput& sd, const Vec3& tp_reference, const MatX& added_mass = MatX());

}  // namespace whirl
