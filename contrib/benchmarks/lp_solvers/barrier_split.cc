// Where the time of `Algorithm = automatic' goes on a Mohr-Coulomb LP: Clp's
// explicit dual of the LP (as masonry's clp back-end builds it), solved
// without presolve (1) by the barrier alone (no crossover) and (2) by the
// barrier with crossover, as masonry does; (2) - (1) is the crossover. CPU
// seconds of each solve (reading the MPS file and building the dual
// excluded), iterations, and the size of the barrier's Cholesky factor that
// Clp prints (log level 1 shows it: "elements in sparse Cholesky, flop
// count").
//
// Build: g++ -O2 -std=c++17 contrib/benchmarks/lp_solvers/barrier_split.cc \
//          -o build/barrier_split -I/usr/include/coin -lClp -lCoinUtils
// Run:   build/barrier_split DIR/lp.mps   (an `Export MPS file' of masonry)

#include <coin/ClpSimplex.hpp>
#include <coin/ClpSimplexOther.hpp>
#include <coin/ClpSolve.hpp>
#include <coin/CoinTime.hpp>

#include <cstdio>
#include <memory>

int
main(int argc, char **argv)
{
  if (argc < 2)
    {
      std::fprintf(stderr, "usage: barrier_split FILE.mps\n");
      return 2;
    }
  ClpSimplex model;
  model.setLogLevel(0);
  if (model.readMps(argv[1], true) != 0)
    return 1;
  for (const bool crossover : {false, true})
    {
      std::unique_ptr<ClpSimplex> dual(
        static_cast<ClpSimplexOther &>(model).dualOfModel());
      dual->setLogLevel(crossover ? 0 : 1);
      ClpSolve options;
      options.setPresolveType(ClpSolve::presolveOff);
      options.setSolveType(crossover ? ClpSolve::useBarrier :
                                       ClpSolve::useBarrierNoCross);
      const double start = CoinCpuTime();
      dual->initialSolve(options);
      std::printf("%s: %d x %d dual, barrier%s: %.2f s CPU, %d iterations, "
                  "status %d, objective %.12g\n",
                  argv[1],
                  dual->numberRows(),
                  dual->numberColumns(),
                  crossover ? " and crossover" : " alone",
                  CoinCpuTime() - start,
                  dual->numberIterations(),
                  dual->status(),
                  dual->objectiveValue());
      std::fflush(stdout);
    }
}
