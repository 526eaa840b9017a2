#include "src/parallel/parallel_map.hpp"

#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "src/base/error.hpp"
#include "src/parallel/session.hpp"

#ifdef WHIRL_HAVE_PETSC
#include <petscsys.h>
#endif

namespace whirl::parallel {
namespace {

enum class Status : std::int64_t { ok = 0, input_error = 1, compute_error = 2, other_error = 3 };

struct Outcome {
  Status status = Status::ok;
  std::string bytes;  ///< the result, or the error message
};

Outcome runTask(const std::function<std::string(int)>& task, int k) {
  try {
    return {Status::ok, task(k)};
  } catch (const InputError& e) {
    return {Status::input_error, e.what()};
  } catch (const ComputeError& e) {
    return {Status::compute_error, e.what()};
  } catch (const std::exception& e) {
    return {Status::other_error, e.what()};
  }
}

[[noreturn]] void rethrow(Status s, const std::string& msg) {
  if (s == Status::input_error) throw InputError(msg);
  if (s == Status::compute_error) throw ComputeError(msg);
  throw std::runtime_error(msg);
}

void putInt(std::string& buf, std::int64_t v) { buf.append(reinterpret_cast<const char*>(&v), sizeof v); }

std::int64_t getInt(const char*& p) {
  std::int64_t v;
  std::memcpy(&v, p, sizeof v);
  p += sizeof v;
  return v;
}

#ifdef WHIRL_HAVE_PETSC
void check(int mpi_err, const char* what) {
  if (mpi_err != MPI_SUCCESS) throw ComputeError(std::string("parallel sweep: ") + what + " failed");
}

/// Every rank's records [k, status, length, bytes]… concatenated on rank 0.
std::string gatherOnRoot(const std::string& mine, MPI_Comm comm, int rank, int size) {
  const int len = static_cast<int>(mine.size());
  if (static_cast<size_t>(len) != mine.size()) throw ComputeError("parallel sweep: results over 2 GB on one rank");
  std::vector<int> lens(rank == 0 ? size : 0), displs(rank == 0 ? size : 0);
  check(MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, comm), "MPI_Gather");
  std::string all;
  if (rank == 0) {
    std::int64_t total = 0;
    for (int r = 0; r < size; ++r) {
      displs[r] = static_cast<int>(total);
      total += lens[r];
    }
    if (total > INT32_MAX) throw ComputeError("parallel sweep: gathered results over 2 GB");
    all.resize(static_cast<size_t>(total));
  }
  check(MPI_Gatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), displs.data(), MPI_CHAR, 0, comm),
        "MPI_Gatherv");
  return all;
}

/// Every rank's records, concatenated in rank order on every rank (MapOptions::every_rank).
std::string gatherOnAll(const std::string& mine, MPI_Comm comm, int size) {
  const int len = static_cast<int>(mine.size());
  if (static_cast<size_t>(len) != mine.size()) throw ComputeError("parallel sweep: results over 2 GB on one rank");
  std::vector<int> lens(static_cast<size_t>(size)), displs(static_cast<size_t>(size));
  check(MPI_Allgather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, comm), "MPI_Allgather");
  std::int64_t total = 0;
  for (int r = 0; r < size; ++r) {
    displs[static_cast<size_t>(r)] = static_cast<int>(total);
    total += lens[static_cast<size_t>(r)];
  }
  if (total > INT32_MAX) throw ComputeError("parallel sweep: gathered results over 2 GB");
  std::string all(static_cast<size_t>(total), '\0');
  check(MPI_Allgatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), displs.data(), MPI_CHAR, comm),
        "MPI_Allgatherv");
  return all;
}

/// Rank 0's verdict (status of the lowest failing task and its message) sent to every rank.
void broadcastVerdict(Status& s, std::string& msg, MPI_Comm comm) {
  std::int64_t head[2] = {static_cast<std::int64_t>(s), static_cast<std::int64_t>(msg.size())};
  check(MPI_Bcast(head, 2, MPI_INT64_T, 0, comm), "MPI_Bcast");
  s = static_cast<Status>(head[0]);
  msg.resize(static_cast<size_t>(head[1]));
  if (head[1] > 0) check(MPI_Bcast(msg.data(), static_cast<int>(head[1]), MPI_CHAR, 0, comm), "MPI_Bcast");
}
#endif

}  // namespace

int mapSize() {
  if (launchedByMpi()) requirePetsc("mpirun (distributed sweep)");
  return petscStarted() ? size() : 1;
}

std::vector<std::string> parallelMapBytes(int n, const std::function<std::string(int)>& task, const MapOptions& opt) {
  const int sz = mapSize(), rk = rank();

  // This rank's tasks, in order; stop at the first failure (later ones cannot be the lowest).
  std::string mine;
  const int assigned = n > rk ? (n - rk + sz - 1) / sz : 0;
  int done = 0;
  for (int k = rk; k < n; k += sz) {
    const Outcome o = runTask(task, k);
    putInt(mine, k);
    putInt(mine, static_cast<std::int64_t>(o.status));
    putInt(mine, static_cast<std::int64_t>(o.bytes.size()));
    mine += o.bytes;
    if (rk == 0 && opt.progress) opt.progress(++done, assigned);
    if (o.status != Status::ok) break;
  }

  std::string all = mine;
#ifdef WHIRL_HAVE_PETSC
  if (sz > 1)
    all = opt.every_rank ? gatherOnAll(mine, PETSC_COMM_WORLD, sz) : gatherOnRoot(mine, PETSC_COMM_WORLD, rk, sz);
#endif

  // Rank 0 (every rank, with every_rank) puts the records in task order and finds the lowest failing task.
  std::vector<std::string> results;
  Status verdict = Status::ok;
  std::string message;
  if (rk == 0 || opt.every_rank) {
    results.resize(static_cast<size_t>(n));
    std::vector<bool> have(static_cast<size_t>(n), false);
    int lowest_error = n;
    for (const char *p = all.data(), *end = all.data() + all.size(); p < end;) {
      const auto k = static_cast<int>(getInt(p));
      const auto s = static_cast<Status>(getInt(p));
      const auto len = static_cast<size_t>(getInt(p));
      std::string bytes(p, len);
      p += len;
      if (s != Status::ok) {
        if (k < lowest_error) {
          lowest_error = k;
          verdict = s;
          message = std::move(bytes);
        }
      } else {
        results[static_cast<size_t>(k)] = std::move(bytes);
        have[static_cast<size_t>(k)] = true;
      }
    }
    if (verdict == Status::ok)
      for (int k = 0; k < n; ++k)
        if (!have[static_cast<size_t>(k)]) {
          verdict = Status::other_error;
          message = "parallel sweep: task " + std::to_string(k) + " has no result";
          break;
        }
  }
#ifdef WHIRL_HAVE_PETSC
  if (sz > 1) broadcastVerdict(verdict, message, PETSC_COMM_WORLD);
#endif
  if (verdict != Status::ok) rethrow(verdict, message);
  return results;
}

}  // namespace whirl::parallel
