#pragma once
/// \file
/// Modes compared with a reference table (`whirl compare`, the Python `whirl.compare`): each
/// reference mode matched to a computed mode by name, and its frequency checked within a relative
/// tolerance. The reference table is `mode,freq_hz[,whirl_mode]` (e.g. cases/nrel5mw/table9_1.csv,
/// [Jonkman2009, Table 9-1]): `whirl_mode` names the computed mode; rows sharing a name set `a|b` are
/// matched as a set (sorted frequencies against sorted frequencies: two modes of one name, such as
/// the two first tower modes); `*` takes the computed mode nearest in frequency.
#include <optional>
#include <string>
#include <vector>

namespace whirl {

/// A computed mode: its name and natural frequency [Hz].
struct NamedFrequency {
  std::string name;
  double freq_hz = 0;
};

/// A row of the reference table.
struct ReferenceMode {
  std::string mode;        ///< the reference's name of the mode (printed)
  double freq_hz = 0;      ///< reference frequency [Hz]
  std::string whirl_mode;  ///< the computed mode(s) it is matched with: a name, `a|b`, or `*`
};

/// The outcome for one reference row.
struct ModeComparison {
  ReferenceMode reference;
  std::optional<NamedFrequency> match;  ///< empty: no computed mode of that name left (missing)
  double rel_error = 0;                 ///< (f − f_ref)/f_ref, 0 when missing
  bool ok = false;                      ///< matched and |rel_error| ≤ tolerance
};

/// The modes of a result CSV: a `whirl modes` table (columns `name` or `mode`, `freq_hz`), or a
/// Campbell table (with a column `rpm`) at rotor speed `rpm` [rpm] (within 1e-9).
/// \throws InputError "file: …" for a missing column, a Campbell table without `rpm`, no modes;
///         "file:line: column: not a number: '…'" for a bad value
std::vector<NamedFrequency> readResultModes(const std::string& path, std::optional<double> rpm);

/// The rows of a reference CSV (`mode`, `freq_hz`, optional `whirl_mode`; without it the mode's own
/// name is the computed mode's name). \throws InputError as readResultModes
std::vector<ReferenceMode> readReferenceModes(const std::string& path);

/// Each reference row matched (rules in the file comment) and checked against `tol_rel` (≥ 0).
std::vector<ModeComparison> compareModes(const std::vector<NamedFrequency>& modes,
                                         const std::vector<ReferenceMode>& reference, double tol_rel);

}  // namespace whirl
