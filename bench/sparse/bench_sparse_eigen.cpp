// Sparse eigen benchmark: the lowest modes of a ~1e5-DOF finite-element frame with SLEPc
// (shift-and-invert Krylov–Schur, MUMPS). Prints figures; run on 1 or 2 ranks:
//   build/bench/whirl_bench_sparse [SIDE LEVELS NEV]
//   mpirun -n 2 build/bench/whirl_bench_sparse
// Default model: a lattice tower of 3D Euler–Bernoulli frame elements, 8 × 8 nodes per level,
// 261 levels above the clamped base: 100,224 DOFs (tests/support/sparse_models.hpp).
// TODO(after the fem:: merge): build the matrices with the fem:: beam/tower model instead.
#include <mpi.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "modal/sparse_eigen.hpp"
#include "src/parallel/session.hpp"
#include "tests/support/sparse_models.hpp"

int main(int argc, char** argv) {
  const int side = argc > 1 ? std::atoi(argv[1]) : 8;
  const int levels = argc > 2 ? std::atoi(argv[2]) : 261;
  const int nev = argc > 3 ? std::atoi(argv[3]) : 20;
  try {
    whirl::parallel::Session session({});
    whirl::parallel::requirePetsc("benchmark");
    const int rank = whirl::parallel::rank(), size = whirl::parallel::size();
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const whirl::test::SparseModel s = whirl::test::latticeTower(side, levels);
    const double t_build = std::chrono::duration<double>(clock::now() - t0).count();

    whirl::SparseEigenOptions opt;
    opt.nev = nev;
    opt.distributed = true;
    opt.tol = 1e-10;
    const auto t1 = clock::now();
    const whirl::SparseEigenResult r = whirl::sparseGeneralizedEigen(s.K, s.M, opt);
    const double t_solve = std::chrono::duration<double>(clock::now() - t1).count();

    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    long rss_kb = ru.ru_maxrss, rss_sum = 0, rss_max = 0;
    MPI_Reduce(&rss_kb, &rss_sum, 1, MPI_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Reduce(&rss_kb, &rss_max, 1, MPI_LONG, MPI_MAX, 0, MPI_COMM_WORLD);
    if (rank == 0) {
      double worst = 0;
      for (const auto& p : r.pairs) worst = std::max(worst, p.residual);
      std::printf("sparse eigen benchmark: lattice frame tower %dx%d nodes x %d levels\n", side, side, levels);
      std::printf("  DOFs                 %ld\n", static_cast<long>(s.K.rows()));
      std::printf("  nonzeros K / M       %ld / %ld\n", static_cast<long>(s.K.nonZeros()),
                  static_cast<long>(s.M.nonZeros()));
      std::printf("  MPI ranks            %d\n", size);
      std::printf("  method               %s\n", r.method.c_str());
      std::printf("  model build          %.2f s (Eigen triplets, not part of the solve)\n", t_build);
      std::printf("  solve (%d modes)     %.2f s (PETSc matrices, factorization, Krylov-Schur, %d restarts)\n", nev,
                  t_solve, r.iterations);
      std::printf("  peak RSS             %.1f MiB per rank (max), %.1f MiB all ranks\n", rss_max / 1024.0,
                  rss_sum / 1024.0);
      std::printf("  largest backward err %.2e\n", worst);
      std::printf("  frequencies [Hz]    ");
      for (size_t k = 0; k < r.pairs.size() && k < 8; ++k)
        std::printf(" %.5f", std::sqrt(std::max(0.0, r.pairs[k].value.real())) / (2 * std::numbers::pi));
      std::printf(" ...\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "whirl_bench_sparse: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
