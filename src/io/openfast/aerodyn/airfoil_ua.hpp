#pragma once
/// \file
/// The unsteady-airfoil data of an airfoil file's table as AeroDyn's continuous UA models use them:
/// the constants read by name (`AirfoilUAData`, file units) turned into SI and completed with AeroDyn's
/// defaults and the values it computes from the polar, and the separation columns f_st, Cl_fs, Cl_fa
/// (aero::uaTable; AirfoilInfo.f90 `ReadAFfile`, `CalculateUACoeffs`).
///
/// A table without UA constants (`InclUAdata` false) gets every constant by default, as AeroDyn does;
/// a constant table (fewer than 3 rows or all rows equal, AeroDyn's ConstData) gets no UA at all.
#include <cstddef>

#include "src/aero/ua_coefficients.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"

namespace whirl::io {

/// The given UA constants of a table in SI: angles (alpha0, alpha1, alpha2, alphaUpper, alphaLower,
/// UACutout, UACutout_delta) from degrees to radians, the rest as written.
aero::UaGiven uaGiven(const AirfoilUAData& ua);

/// The UA data of table `table` (0-based) of `af` for UA model `ua_mod` (Cm0 from the Cm column when
/// the file has one, whatever UseBlCm says, as AeroDyn).
/// \throws InputError "file:line: key: reason" (line of the table's `Re`) when the table index is out of
///         range or aero::uaTable refuses the table.
aero::UaTable airfoilUa(const AirfoilInput& af, std::size_t table, int ua_mod);

}  // namespace whirl::io
