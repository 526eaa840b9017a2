#pragma once
/// \file
/// An AeroDyn v14 main file in the terms of AeroDyn v15, so that a FAST v8 deck with `CompAero = 1`
/// builds the same blade elements and BEMT as one with `CompAero = 2`.
///
/// What carries over: the induction model (IndModel NONE → no induction, WAKE → axial only, SWIRL →
/// axial and tangential), Prandtl tip and hub losses (TLModel, HLModel), air density, UseCm, the airfoil
/// files and the element table. What whirl does instead of AeroDyn v14 (notes): the equilibrium BEMT of
/// AeroDyn v15 (inflow-angle residual, Buhl's high-thrust correction; drag in the inductions as InfModel
/// says: EQUIL none, EQUILDA/DT/DB axial/tangential/both, DYNIN none) rather than
/// AeroDyn v14's induction-factor iteration; quasi-steady inflow for dynamic inflow (InfModel = DYNIN),
/// static airfoil tables for Beddoes' dynamic stall (StallMod = BEDDOES); no tower shadow (TwrShad).
/// Refused: the Georgia Tech tip loss (TLModel = GTECH), which AeroDyn v15 does not have, and interpolation
/// between an airfoil file's tables (multiple-table option RENUM or USER), as AFTabMod ≠ 1 is for v15.
#include <optional>
#include <string>
#include <vector>

#include "src/io/openfast/aerodyn/aerodyn14_input.hpp"
#include "src/io/openfast/aerodyn/aerodyn_blade_input.hpp"
#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"

namespace whirl::io {

/// The v15 description of `v14`'s options (source, AFNames and their lines carried over; no blade files,
/// no tower). Throws InputError "file:line: TLModel: GTECH not supported by whirl (…)".
AeroDynInput aerodynFromV14(const AeroDyn14Input& v14);

/// One note per option whirl replaces by its steady counterpart (InfModel = DYNIN, StallMod = BEDDOES,
/// TwrShad ≠ 0), "file:line: key: value: what whirl does instead", and one on IndModel saying that the
/// BEMT is AeroDyn v15's.
std::vector<std::string> steadySubstitutes(const AeroDyn14Input& v14);

/// The multiple-table option against the airfoil files read: nothing when no file has several tables or
/// the option is SINGLE; a note when it is absent (AeroDyn v14 then uses the first tables). Throws
/// InputError "file:line: MultiTab: RENUM not supported by whirl (…)" for RENUM, USER or another word.
std::optional<std::string> multipleTables(const AeroDyn14Input& v14, const std::vector<AirfoilInput>& airfoils);

/// The element table as a blade: BlSpn = RNodes (from the rotor centre), element_width = DRNodes, BlTwist
/// = AeroTwst, BlChord = Chord, BlAFID = NFoil, no aerodynamic-centre offsets.
AeroDynBladeInput bladeFromV14(const AeroDyn14Input& v14);

}  // namespace whirl::io
