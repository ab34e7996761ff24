// LinearProgram::write_mps() read back by the `clp` and `glpsol` programs
// (Debian packages coinor-clp and glpk-utils; the test fails if they are
// missing): both report the optimum of the in-memory problem. A maximisation
// is written as the minimisation of -c^T x, so they report minus the maximum.

#include <cstdlib>
#include <fstream>

#include "lp_common.h"

using namespace lp_test;
using masonry::lp::infinity;

namespace
{
  /** The first number after @p key in the file @p filename (NaN if none). */
  double
  find_number(const std::string &filename, const std::string &key)
  {
    std::ifstream in(filename);
    std::string   line;
    while (std::getline(in, line))
      {
        const auto p = line.find(key);
        if (p != std::string::npos)
          {
            std::istringstream s(line.substr(p + key.size()));
            double             v;
            if (s >> v)
              return v;
          }
      }
    return NAN;
  }

  bool
  have(const std::string &program)
  {
    return std::system(
             ("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
  }

  void
  check(const std::string &name, const LinearProgram &lp)
  {
    const Solution s =
      create("clp", "Algorithm", "dual simplex", false)->solve(lp);
    const double      expected = lp.maximize ? -s.objective : s.objective;
    const std::string file     = name + ".mps";
    lp.write_mps(file);

    // clp: "Optimal objective <value> - <n> iterations ..."
    std::system(
      ("clp " + file + " -solve > " + name + ".clp.txt 2>&1").c_str());
    const double clp = find_number(name + ".clp.txt", "Optimal objective ");
    // glpsol: "Objective:  OBJ = <value> (MINimum)" in the -o report
    std::system(("glpsol --freemps " + file + " -o " + name +
                 ".glpsol.txt > /dev/null 2>&1")
                  .c_str());
    const double glpsol = find_number(name + ".glpsol.txt", "OBJ = ");

    // both programs print 10 significant digits
    for (const auto &[program, value] :
         {std::make_pair("clp", clp), std::make_pair("glpsol", glpsol)})
      if (close(value, expected, 1e-7))
        std::cout << "OK " << name << ": " << program << " reads the MPS file, "
                  << "optimum " << round6(value) << std::endl;
      else
        std::cout << "FAILED " << name << ": " << program << " gives "
                  << std::setprecision(17) << value << ", expected " << expected
                  << std::endl;
  }
} // namespace

int
main()
{
  for (const std::string program : {"clp", "glpsol"})
    if (!have(program))
      std::cout << "FAILED: program '" << program
                << "' not found (install coinor-clp and glpk-utils)"
                << std::endl;

  // max 3x + 2y s.t. x + y <= 4, x + 3y <= 6, 0 <= x <= 3, y >= 0: 11 at
  // (3, 1); in the file: min -3x - 2y = -11. Named rows and columns.
  LinearProgram lp1;
  {
    const unsigned int x = lp1.add_column(3, 0, 3, "x");
    const unsigned int y = lp1.add_column(2, 0, infinity, "y");
    const unsigned int r = lp1.add_row(-infinity, 4, "r1");
    const unsigned int s = lp1.add_row(-infinity, 6, "r2");
    lp1.add_entry(r, x, 1);
    lp1.add_entry(r, y, 1);
    lp1.add_entry(s, x, 1);
    lp1.add_entry(s, y, 3);
  }
  check("max_small", lp1);

  // min 2a + 3b - c s.t. a + b + c = 10, a - b = 2, -1 <= b + c <= 5.5
  // (RANGES), a + c free (free row), a, b free (FR), 0 <= c <= 4: 13.5 at
  // (4.5, 2.5, 3). Names too long for MPS: generated names.
  LinearProgram lp4;
  lp4.maximize = false;
  {
    const unsigned int a  = lp4.add_column(2, -infinity, infinity, "alpha_1");
    const unsigned int b  = lp4.add_column(3, -infinity, infinity, "a name");
    const unsigned int c  = lp4.add_column(-1, 0, 4, "gamma_gamma");
    const unsigned int r1 = lp4.add_row(10, 10);
    const unsigned int r2 = lp4.add_row(2, 2);
    const unsigned int r3 = lp4.add_row(-1, 5.5);
    const unsigned int r4 = lp4.add_row(-infinity, infinity);
    lp4.add_entry(r1, a, 1);
    lp4.add_entry(r1, b, 1);
    lp4.add_entry(r1, c, 1);
    lp4.add_entry(r2, a, 1);
    lp4.add_entry(r2, b, -1);
    lp4.add_entry(r3, b, 1);
    lp4.add_entry(r3, c, 1);
    lp4.add_entry(r4, a, 1);
    lp4.add_entry(r4, c, 1);
  }
  check("min_equalities", lp4);

  // A column with a negative upper bound and a fixed column:
  // min x - y s.t. x + y >= -10, -5 <= x <= -1, y = 2: x = -5, -7.
  LinearProgram lp5;
  lp5.maximize = false;
  lp5.add_column(1, -5, -1);
  lp5.add_column(-1, 2, 2);
  lp5.add_row(-10, infinity);
  lp5.add_entry(0, 0, 1);
  lp5.add_entry(0, 1, 1);
  check("bounds", lp5);

  check("random", random_lp(200, 300, 20240607));
}
