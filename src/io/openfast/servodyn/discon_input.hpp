#pragma once
/// \file
/// Reader of ROSCO's controller input file `DISCON.IN` (NREL/ROSCO, `rosco/controller/src/ReadSetParameters.f90`,
/// ReadControlParameterFileSub and CheckInputs), the file a ServoDyn deck hands its Bladed-style controller
/// library through `DLL_InFile` (`PCMode = 5`, `VSContrl = 5`).
///
/// Format, as ROSCO reads it: one parameter per line, `value(s)  ! Key  - description`; lines starting
/// with `!` are comments and section titles. ROSCO finds each key by name (FindLine, case-insensitive)
/// wherever it is, so the order of the lines and the version of the file do not matter: a key a mode
/// does not need may be missing and takes ROSCO's default (0, or the value ROSCO documents), as
/// ReadSetParameters.f90 allows it (its `CheckOptional` argument). whirl is stricter where ROSCO would
/// misread silently: a key given twice, a label that is not a ROSCO key (a typo would otherwise fall
/// back to a default), an array whose length differs from its count key (`PC_GS_n` …), and a value
/// that is not a number are all `file:line: key: reason`.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl::io {

/// Reads a DISCON.IN: every parameter of RoscoController (SI units, `VS_GenEff` turned from % into a
/// fraction), with where each key was written, checked as ROSCO's CheckInputs checks them (the checks
/// of the modes whirl models: positive corner frequencies, non-decreasing `PC_GS_angles` and
/// `PS_WindSpeeds`, `PC_MinPit < PC_MaxPit`, negative `VS_KP/VS_KI`, …), and `notes` naming each active
/// mode whirl does not model with what the linear model assumes instead. Throws InputError
/// "file:line: key: reason" (the file alone for an unreadable file, the key without a line for a
/// missing key). `overrides` (--set KEY=VALUE) replace the values of the keys the file writes.
RoscoController readDiscon(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

/// The ROSCO controller of a ServoDyn deck: with `VSContrl = 5` and a `DLL_InFile` naming a file that
/// exists, that file read as a DISCON.IN (errors as readDiscon's). With `PCMode` other than 5 the pitch is
/// not the library's: PC_ControlMode is set to 0 (pitch held at fine pitch) and a note says so. nullopt
/// without VSContrl = 5 or when `DLL_InFile` is absent, "unused" or names no file (the plant then stays
/// open loop, with ServoDyn's note, externalTorqueController).
std::optional<RoscoController> readServoDynController(const ServoDynInput& servo, OverrideSet* overrides = nullptr);

/// The ROSCO controller of an OpenFAST deck (`.fst` with `CompServo = 1`), with the `--set KEY=VALUE`
/// overrides `sets` applied to the .fst, ServoDyn and DISCON.IN files (keys of other files are ignored here):
/// readServoDynController of its ServoDyn file; nullopt for anything else (an ElastoDyn `.dat`, a YAML
/// case, a deck without ServoDyn or without a ROSCO DISCON.IN).
std::optional<RoscoController> readDeckController(const std::filesystem::path& deck,
                                                  const std::vector<std::string>& sets);

/// As readDiscon, from text (`file` names it in messages).
RoscoController parseDiscon(const std::string& text, const std::filesystem::path& file,
                            OverrideSet* overrides = nullptr);

}  // namespace whirl::io
