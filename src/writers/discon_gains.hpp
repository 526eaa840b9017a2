#pragma once
/// \file
/// A ROSCO `DISCON.IN` with a new gain schedule: the value fields of `PC_GS_n`, `PC_GS_angles`,
/// `PC_GS_KP`, `PC_GS_KI`, `VS_KP`, `VS_KI` (and of `PC_GS_KD`, `PC_GS_TF` as zeros when the schedule's
/// length changes and they were all zero) replaced, formatted as ROSCO's `write_DISCON` writes them
/// (NREL/ROSCO `rosco/toolbox/utilities.py`: angles `%.3f`, pitch gains `%.3e`, torque gains `%.5e`);
/// each line's comment, and every other line, kept byte for byte (line ends included).
#include <string>

#include "linearize/controller_tuning.hpp"

namespace whirl {

/// \param[in] text the DISCON.IN as read, \param[in] file its name for messages.
/// \throws InputError `file:line: key: reason` when a key is missing or given twice, or `PC_GS_KD` /
/// `PC_GS_TF` hold non-zero gains that a schedule of another length cannot keep.
std::string disconWithGains(const std::string& text, const std::string& file, const GainSchedule& gains);

}  // namespace whirl
