/**
 * @file
 * Helpers for the brickwork tests: a parameter file for a wallette and the
 * curve a run wrote.
 */
#ifndef masonry_tests_brickwork_tests_h
#define masonry_tests_brickwork_tests_h

#include <masonry/core/application.h>
#include <masonry/core/json.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace brickwork_tests
{
  /**
   * A wallette parameter file: the analysis entries in @p wallette, the
   * other subsections verbatim in @p plugins. No pictures, no VTU.
   */
  inline std::string
  prm(const std::string &wallette, const std::string &plugins)
  {
    return "set Analysis = wallette\n"
           "subsection Wallette\n"
           "  set Write plot = false\n"
           "  set Write VTU = false\n" +
           wallette + "end\n" + plugins;
  }

  /**
   * Write @p text to NAME.prm on rank 0 (output into results/NAME), run
   * masonry on @p comm with the screen discarded and return summary.json.
   * The test fails if masonry fails.
   */
  inline masonry::Json
  run(const std::string &name,
      const std::string &text,
      const MPI_Comm     comm = MPI_COMM_WORLD)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      std::ofstream(name + ".prm")
        << "set Output directory = results/" << name << "\n"
        << text;
    MPI_Barrier(comm);
    std::ostringstream screen;
    std::streambuf    *old  = std::cout.rdbuf(screen.rdbuf());
    const int          code = masonry::run_application({name + ".prm"}, comm);
    std::cout.rdbuf(old);
    if (code != 0)
      {
        std::cout << "FAILED: masonry returned " << code << " for " << name
                  << "\n"
                  << screen.str();
        std::exit(1);
      }
    MPI_Barrier(comm);
    std::ifstream     in("results/" + name + "/summary.json");
    std::stringstream s;
    s << in.rdbuf();
    return masonry::Json::parse(s.str());
  }

  /** The columns of results/NAME/curve.csv, row by row. */
  inline std::vector<std::vector<double>>
  curve(const std::string &name)
  {
    std::ifstream                    in("results/" + name + "/curve.csv");
    std::string                      line;
    std::vector<std::vector<double>> rows;
    std::getline(in, line); // header
    while (std::getline(in, line))
      {
        std::vector<double> row;
        std::stringstream   s(line);
        std::string         cell;
        while (std::getline(s, cell, ','))
          row.push_back(std::stod(cell));
        rows.push_back(row);
      }
    return rows;
  }

  /** Print "OK what" or "FAILED what". */
  inline bool
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "OK " : "FAILED ") << what << "\n";
    return ok;
  }

  /** Relative difference of @p a and @p b. */
  inline double
  relative(const double a, const double b)
  {
    return std::abs(a - b) / std::max(std::abs(b), 1e-300);
  }
} // namespace brickwork_tests

#endif
