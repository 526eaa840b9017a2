#pragma once
/// \file
/// Multiblade transform input from OpenFAST `.lin` files: which states, inputs and outputs are
/// rotating and on which blade, which states are velocities, and the per-azimuth sample.
///
/// Rotating entries are those flagged T in the "Rotating Frame?" column. Their blade number is
/// read from the description, first match of: "Blade root <n>", "blade <n>"/"Blade <n>", "BD_<n>"
/// (BeamDyn instance), "B<n>" as a word start (AeroDyn "B1N3..."), else the trailing digits of the
/// channel name (ElastoDyn outputs "RootMxc1"). Sets pair the j-th rotating entry of each blade
/// (linearize/mbc.hpp); the helper checks that their descriptions agree once the blade number is masked.
///
/// Second-order states: a state of derivative order 2 (or any, in files without that column) whose
/// description is "<module> First time derivative of <d>" is the rate of the state described
/// "<module> <d>" (units aside), wherever it sits: ElastoDyn's q, q̇ then BeamDyn's q, q̇ pair
/// as MBC3 pairs them. Where the descriptions do not say, a run of consecutive states of one module
/// (first word of the description, "ED", "BD_1", …) with derivative order 2 is split in halves:
/// state k of the second half is the rate of state k of the first. States of derivative order
/// 1 (HydroDyn radiation, aerodynamic, controller states) are first-order states.
#include <cstddef>
#include <string>
#include <vector>

#include "linearize/mbc.hpp"
#include "src/io/lin/openfast_lin.hpp"

namespace whirl {

/// Blade number (1-based) named in an OpenFAST description, 0 if none is found.
int bladeNumberInDescription(const std::string& description);

/// Layout of the states, inputs and outputs of one `.lin` file.
/// \param[in] num_blades N; 0 = the highest blade number found among rotating entries (3 if none).
/// \param[out] left_out_outputs null: outputs that do not pair across blades are an error. Otherwise
///         they are left out of the transform (kept in the fixed frame) and their indices (0-based,
///         ascending) are appended here: a channel listed twice for one blade (the toolbox Standstill
///         files list RootFxc1 twice) or missing on another blade; every rotating output when the rest
///         still does not pair.
/// \throws InputError naming the file and line of a rotating entry without a blade number, of a
///         set whose descriptions differ between blades, or of an unequal number of entries per blade.
MbcLayout mbcLayoutFromLin(const OpenFastLin& lin, int num_blades = 0,
                           std::vector<std::size_t>* left_out_outputs = nullptr);

/// The file's A, B, C, D with ψ = header azimuth, Ω = header rotor speed, and Ω̇ = the sum of the
/// derivatives of the generator-azimuth and drivetrain rate states (DOF_GeAz, DOF_DrTr) in the
/// state-derivative table, as MBC3 does (0 if those DOFs are absent).
/// \throws InputError("file:line: A: value is not finite …") when A holds NaN, Infinity or `****`.
MbcSample mbcSampleFromLin(const OpenFastLin& lin);

}  // namespace whirl
