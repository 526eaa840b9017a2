#pragma once
/// \file
/// Reader for OpenFAST linearization files (`*.lin`, text), as written by OpenFAST v2.x to v5
/// (FAST_Lin.f90), single or double precision.
///
/// Layout of the file: a header ("Simulation information:" with time, rotor speed, azimuth,
/// wind speed (absent before v2.3), the numbers of continuous/discrete/constraint states, inputs
/// and outputs), then one table per vector ("Order of continuous states:", "... state
/// derivatives:", "... discrete states:", "... constraint states:", "Order of inputs:",
/// "Order of outputs:") with columns Row/Column, Operating Point, Rotating Frame? (T/F),
/// Derivative Order (absent in the oldest files), Description; then the matrices as
/// "A: nx x nx", "B: nx x nu", "C: ny x nx", "D: ny x nu" followed by their rows (optionally preceded
/// by the glue-code Jacobians dUdu, dUdy, which are skipped). B, C, D are absent when there are
/// no inputs or outputs.
///
/// Numbers: Fortran E format, also with 3-digit exponents ("1.2E-003", "1.2-100"); a field
/// printed as `****` (overflow) is read as NaN and counted in `non_finite_values`, so callers can
/// refuse it (the eigen solvers do). Orientation inputs/outputs (v5) print three comma-separated
/// operating-point values per row: the first goes to `op`, all three to `op_values`.
/// Units are as in the file: SI, angles in rad.
#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace whirl {

/// One row of a table (one state, state derivative, input or output).
struct LinVariable {
  double op = 0.0;                ///< operating-point value (NaN if printed as ****)
  std::vector<double> op_values;  ///< all values of the row when it prints more than one, else empty
  bool rotating = false;          ///< "Rotating Frame?" column: T = in the rotating (blade) frame
  int derivative_order = -1;      ///< "Derivative Order" column (0, 1 or 2); -1 if the file has none
  std::string description;        ///< e.g. "ED 1st flapwise bending-mode DOF of blade 1 (...), m"
  int line = 0;                   ///< 1-based line in the file, for messages
};

/// Contents of one `.lin` file. Vectors and matrices are in the order of the file.
struct OpenFastLin {
  std::string path;                                  ///< file as given to the reader
  std::string generator;                             ///< "Predictions were generated on ... using OpenFAST ..." line
  double time = 0.0;                                 ///< simulation time of the linearization (s)
  double rotor_speed = 0.0;                          ///< Ω (rad/s)
  double azimuth = 0.0;                              ///< rotor azimuth ψ (rad), blade 1
  std::optional<double> wind_speed;                  ///< hub-height wind speed (m/s), absent in older files
  int n_x = 0, n_xd = 0, n_z = 0, n_u = 0, n_y = 0;  ///< numbers of states, inputs, outputs
  bool has_jacobians = false;                        ///< "Jacobians included in this file?"
  std::vector<LinVariable> x;                        ///< continuous states (dim n_x)
  std::vector<LinVariable> xdot;                     ///< their time derivatives (dim n_x)
  std::vector<LinVariable> xd;                       ///< discrete states (dim n_xd)
  std::vector<LinVariable> z;                        ///< constraint states (dim n_z)
  std::vector<LinVariable> u;                        ///< inputs (dim n_u)
  std::vector<LinVariable> y;                        ///< outputs (dim n_y)
  Eigen::MatrixXd A;                                 ///< ∂ẋ/∂x (n_x × n_x), empty if n_x = 0
  Eigen::MatrixXd B;                                 ///< ∂ẋ/∂u (n_x × n_u), empty if absent
  Eigen::MatrixXd C;                                 ///< ∂y/∂x (n_y × n_x), empty if absent
  Eigen::MatrixXd D;                                 ///< ∂y/∂u (n_y × n_u), empty if absent
  int non_finite_values = 0;                         ///< values printed as ****, NaN or Infinity anywhere in the file
  std::map<std::string, int>
      first_non_finite;  ///< matrix ("A") or table key → 1-based line of its first non-finite value
};

/// Reads one `.lin` file.
/// \throws InputError naming file, line and reason: missing file, missing header key, table or
///         matrix shorter than declared (truncated file), non-numeric value, wrong matrix size, a count
///         or matrix size above limits::kMaxLinDimension. Memory follows the rows actually read.
OpenFastLin readOpenFastLin(const std::string& path);

}  // namespace whirl
