#pragma once
/// \file
/// The serial N_Vector of SUNDIALS with its frequent operations compiled here (linearize/simulate.cpp).
///
/// Debian's SUNDIALS 6.4.1 (libsundials-dev) is built without optimization: its vector kernels
/// keep every loop variable on the stack, and at the 32 states of the NREL 5MW the vector
/// operations IDA performs each step (predictor, corrector, error weights and norms, history
/// update: about 40 per step) cost as much as a residual evaluation (callgrind, README *Speed*).
/// SUNDIALS lets a user supply the operations of a vector (the N_Vector_Ops table, copied to every
/// clone); these are the serial vector's, the same arithmetic in the same order — results are
/// bitwise those of N_VNew_Serial — compiled with the project's flags.
#include <nvector/nvector_serial.h>

namespace whirl {

/// A serial vector of length n whose linear sums, scalings, weighted norms, linear combinations and
/// element-wise operations are this file's. Null when SUNDIALS cannot allocate it.
N_Vector newFastSerialVector(sunindextype n, SUNContext ctx);

}  // namespace whirl
