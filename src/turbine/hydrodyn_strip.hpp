#pragma once
/// \file
/// HydroDyn's masses on the beam FE model of a SubDyn substructure, as HydroDyn's Morison module
/// carries them into a linearization (Jonkman et al., HydroDyn theory; Morison.f90 of OpenFAST):
/// - strip-theory members (PropPot = False), in the water column (seabed to still-water level): the
///   added water ρ Ca π R² (I − k kᵀ) per unit length, k the member axis, R and Ca linear between its
///   ends (under marine growth R + t_MG and Ca_MG); on a taper also 2 AxCa ρ π R² |dR/dl| k kᵀ;
/// - at each joint in the water (end effects): JAxCa ρ V_n V_nᵀ / |V_n|, V_n = Σ ± (2π/3) R³ k over the
///   strip-theory members meeting there (− where a member starts), JAxCa from the AXIAL COEFFICIENTS
///   row the joint names;
/// - marine growth (any member): its mass ρ_MG π ((R + t_MG)² − R²) per length, t_MG and ρ_MG linear
///   between the table's depths, none outside;
/// - filled members (any member): the fluid ρ_f π (R − t)² per length below the group's FillFSLoc.
/// The growth's and the fill's weight are constant loads in HydroDyn (v2) and SubDyn has no geometric
/// stiffness, so they are left out with the members' buoyancy: they would only settle the TP. Drag has
/// no linear part about still water.
/// The members must lie on the FE model's elements (SubDyn and HydroDyn describe one structure):
/// each element's share goes to its two nodes with the linear weights of OpenFAST's line-to-point
/// load mapping, the joints' to the node at the joint.
#include "src/fem/beam_model.hpp"
#include "src/io/openfast/offshore/hydrodyn_input.hpp"

namespace whirl::elastodyn {

/// These masses on `model`'s DOFs (6 per node, translations only), ndof × ndof [kg]; the water of
/// density `rho` [kg/m³] and depth `depth` [m], z = 0 at still water. InputError naming the HydroDyn
/// file and line: a member's part in the water (or in its fill) that lies on no element, a joint in the
/// water on no node, MCoefMod = 2, a JointAxID with no row.
MatX stripTheoryAddedMass(const io::HydroDynInput& hd, const fem::BeamModel& model, double rho, double depth);

}  // namespace whirl::elastodyn
