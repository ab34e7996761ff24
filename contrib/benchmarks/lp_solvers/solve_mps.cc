// Solve an MPS file with masonry's LP solver plugin in-process and print the
// wall-clock and CPU seconds of lp::Interface::solve() (process start, MPS
// reading and matrix building excluded), to compare with the solve time that
// `clp` prints for the same file. The MPS file states a minimisation; with
// MAXIMISE=1 in the environment the LP is read back as masonry built it
// (maximise -c^T x), which is how masonry hands it to Clp.
//
// Build (from the top of the checkout, after contrib/setup):
//   mpicxx -O2 -std=c++17 -DNDEBUG -Iinclude -Ibuild/include \
//     -I/usr/include/deal.II -isystem /usr/include/trilinos \
//     -isystem /usr/include/coin contrib/benchmarks/lp_solvers/solve_mps.cc \
//     -o build/solve_mps -Lbuild -lmasonry -Wl,-rpath,$PWD/build -ldeal.ii \
//     -lClp -lCoinUtils -ltrilinos_teuchoscomm -ltrilinos_teuchoscore
// Run:
//   MAXIMISE=1 build/solve_mps lp.mps clp automatic [presolve=true] [repeat=1]

#include <masonry/lp/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <coin/CoinMpsIO.hpp>
#include <coin/CoinTime.hpp>

#include <cstdio>
#include <cstdlib>

using namespace masonry;

int
main(int argc, char **argv)
{
  if (argc < 4)
    {
      std::fprintf(stderr,
                   "usage: solve_mps FILE.mps clp|glpk ALGORITHM "
                   "[PRESOLVE] [REPEAT]\n");
      return 2;
    }
  CoinMpsIO io;
  io.messageHandler()->setLogLevel(0);
  if (io.readMps(argv[1]) != 0)
    return 1;
  const bool        maximise = std::getenv("MAXIMISE") != nullptr;
  lp::LinearProgram lp;
  lp.maximize      = maximise;
  const auto bound = [](const double v) {
    return v >= 1e30 ? lp::infinity : v <= -1e30 ? -lp::infinity : v;
  };
  for (int j = 0; j < io.getNumCols(); ++j)
    lp.add_column((maximise ? -1 : 1) * io.getObjCoefficients()[j],
                  bound(io.getColLower()[j]),
                  bound(io.getColUpper()[j]));
  for (int i = 0; i < io.getNumRows(); ++i)
    lp.add_row(bound(io.getRowLower()[i]), bound(io.getRowUpper()[i]));
  const CoinPackedMatrix *a = io.getMatrixByCol();
  for (int j = 0; j < a->getNumCols(); ++j)
    for (CoinBigIndex k = a->getVectorStarts()[j];
         k < a->getVectorStarts()[j] + a->getVectorLengths()[j];
         ++k)
      lp.add_entry(a->getIndices()[k], j, a->getElements()[k]);

  const std::string        plugin = argv[2];
  dealii::ParameterHandler prm;
  plugins::Registry<lp::Interface>::declare_parameters(prm);
  prm.enter_subsection("LP solver");
  prm.enter_subsection(plugin == "clp" ? "Clp" : "Glpk");
  prm.set(plugin == "clp" ? "Algorithm" : "Method", argv[3]);
  if (argc > 4)
    prm.set("Presolve", argv[4]);
  prm.leave_subsection();
  prm.leave_subsection();
  const auto solver = plugins::Registry<lp::Interface>::create(prm, plugin);
  const int  repeat = argc > 5 ? std::atoi(argv[5]) : 1;
  for (int r = 0; r < repeat; ++r)
    {
      const double       cpu = CoinCpuTime();
      const lp::Solution s   = solver->solve(lp);
      std::printf("%s %s: %s, objective %.12g, %u iterations, wall %.4f s, "
                  "cpu %.4f s\n",
                  argv[2],
                  argv[3],
                  lp::to_string(s.status).c_str(),
                  s.objective,
                  s.iterations,
                  s.seconds,
                  CoinCpuTime() - cpu);
    }
}
