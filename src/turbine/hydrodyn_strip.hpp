#pragma once
/// \file
/// HydroDyn's strip-theory added mass (members with PropPot = False) on the beam FE model of a
/// SubDyn substructure, as HydroDyn's Morison module carries it into a linearization (Jonkman et al.,
/// HydroDyn theory; Morison.f90 of OpenFAST):
/// - along each member, in the water column (seabed to still-water level): ρ Ca π R² (I − k kᵀ) per
///   unit length, k the member axis, R and Ca linear between its two ends; on a taper also
///   2 AxCa ρ π R² |dR/dl| k kᵀ;
/// - at each joint in the water (end effects): JAxCa ρ V_n V_nᵀ / |V_n|, V_n = Σ ± (2π/3) R³ k over the
///   strip-theory members meeting there (− where a member starts), JAxCa from the AXIAL COEFFICIENTS
///   row the joint names.
/// The members must lie on the FE model's elements (SubDyn and HydroDyn describe one structure):
/// each element's share goes to its two nodes with the linear weights of OpenFAST's line-to-point
/// load mapping, the joints' to the node at the joint. Buoyancy and drag are not in the added mass:
/// HydroDyn's strip-theory buoyancy is a constant load (not recomputed with the displaced position)
/// and SubDyn has no geometric stiffness, so it does not change the linear model; drag has no linear
/// part about still water.
#include "src/fem/beam_model.hpp"
#include "src/io/hydrodyn_input.hpp"

namespace whirl::elastodyn {

/// The added mass on `model`'s DOFs (6 per node, translations only), ndof × ndof [kg]; the water of
/// density `rho` [kg/m³] and depth `depth` [m], z = 0 at still water. InputError naming the HydroDyn
/// file and line: a member in the water that lies on no element, a joint in the water on no node,
/// MCoefMod = 2, a JointAxID with no row.
MatX stripTheoryAddedMass(const io::HydroDynInput& hd, const fem::BeamModel& model, double rho, double depth);

}  // namespace whirl::elastodyn
