#pragma once
/// \file
/// Independent tasks spread over MPI ranks, results gathered on rank 0 in task order — the one
/// layer through which sweeps (Campbell points, exported operating points, parameter sets) use
/// MPI. Without mpirun (or built without PETSc) it is a plain loop in this process.
///
/// Task k runs on rank k mod size (cyclic: neighbouring operating points cost alike, so every
/// rank gets a similar share). A task's result travels as bytes (the caller serializes, e.g. CBOR,
/// which keeps every double exact), so what rank 0 assembles is bit for bit what one rank would
/// have computed, as long as each task depends on its index only (no state carried between tasks).
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/base/error.hpp"

namespace whirl::parallel {

struct MapOptions {
  /// Called on rank 0 after each of its own tasks with (tasks done here, tasks assigned here).
  std::function<void(int, int)> progress;
  /// The results on every rank instead of rank 0 alone: for a result every rank goes on from (the
  /// trim schedule, whose points the distributed sweep then needs on each rank).
  bool every_rank = false;
};

/// The number of ranks parallelMapBytes spreads its tasks over: MPI's size under mpirun (MPI is
/// started here if it was not), 1 otherwise. For a caller that cuts its work into one task per rank.
int mapSize();

/// Runs task(k) for k = 0 … n−1 over the ranks; returns the n results on rank 0 (index k = task
/// k) and an empty vector on the other ranks (with MapOptions::every_rank, the n results on each).
/// Errors: a rank stops at its first failing task; afterwards every rank throws the error of the
/// lowest failing task index, with its type (InputError, ComputeError, else std::runtime_error)
/// and message — the error one rank would have stopped on.
std::vector<std::string> parallelMapBytes(int n, const std::function<std::string(int)>& task,
                                          const MapOptions& opt = {});

/// Typed form: `task(k)` returns a T; `encode(const T&)` → bytes, `decode(bytes)` → T. In one process (no
/// mpirun) the tasks run in a loop and their results are kept as they are: the bytes would carry them to rank 0
/// unchanged (the encodings keep every double exact; tests/mpi compares one process with two ranks), and their
/// round trip was 6 % of a Campbell sweep with aerodynamic states. Errors and progress as parallelMapBytes'.
template <class T, class Task, class Encode, class Decode>
std::vector<T> parallelMap(int n, Task&& task, Encode&& encode, Decode&& decode, const MapOptions& opt = {}) {
  std::vector<T> out;
  if (mapSize() == 1) {
    out.reserve(static_cast<std::size_t>(n > 0 ? n : 0));
    for (int k = 0; k < n; ++k) {
      std::exception_ptr failure;
      try {
        out.push_back(task(k));
      } catch (const InputError&) {
        failure = std::current_exception();
      } catch (const ComputeError&) {
        failure = std::current_exception();
      } catch (const std::exception& e) {  // what parallelMapBytes makes of other errors
        failure = std::make_exception_ptr(std::runtime_error(e.what()));
      }
      if (opt.progress) opt.progress(k + 1, n);
      if (failure) std::rethrow_exception(failure);
    }
    return out;
  }
  const std::vector<std::string> bytes = parallelMapBytes(
      n, [&](int k) { return encode(task(k)); }, opt);
  out.reserve(bytes.size());
  for (const auto& b : bytes) out.push_back(decode(b));
  return out;
}

}  // namespace whirl::parallel
