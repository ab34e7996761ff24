/**
 * @file
 * A small analysis for the tests of the driver, registered as `test` by every
 * test that includes this header (the registry is filled when the test
 * executable starts).
 */
#ifndef masonry_tests_test_analysis_h
#define masonry_tests_test_analysis_h

#include <masonry/analysis/interface.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fstream>
#include <string>

namespace testing
{
  /**
   * Writes `Number of files` small files, reports `Length` in summary.json
   * and, if asked to, fails during run().
   */
  class TestAnalysis : public masonry::analysis::Interface
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Length",
                        "1",
                        dealii::Patterns::Double(),
                        "A length (m); must be positive.");
      prm.declare_entry("Number of files",
                        "2",
                        dealii::Patterns::Integer(0, 10),
                        "How many files data-<i>.txt the run writes.");
      prm.declare_entry("Fail during run",
                        "false",
                        dealii::Patterns::Bool(),
                        "Throw an exception in run(), after writing files.");
      prm.declare_entry("Fail on rank",
                        "-1",
                        dealii::Patterns::Integer(-1),
                        "This rank alone throws an exception in run() while "
                        "the others wait in a barrier (-1: none).");
    }

    void
    parse_parameters(dealii::ParameterHandler &prm) override
    {
      length = prm.get_double("Length");
      AssertThrow(length > 0,
                  masonry::ExcParameter("Length",
                                        "must be positive, got " +
                                          prm.get("Length")));
      n_files         = prm.get_integer("Number of files");
      fail_during_run = prm.get_bool("Fail during run");
      fail_on_rank    = prm.get_integer("Fail on rank");
    }

    void
    run(masonry::RunContext &context) override
    {
      context.pcout << "Test analysis: length " << length << " m, writing "
                    << n_files << " files\n";
      for (unsigned int i = 0; i < n_files; ++i)
        {
          const std::string name =
            context.output.file("data-" + std::to_string(i) + ".txt");
          if (dealii::Utilities::MPI::this_mpi_process(
                context.mpi_communicator) == 0)
            std::ofstream(name) << "file " << i << " of " << n_files << "\n";
        }
      AssertThrow(!fail_during_run,
                  dealii::ExcMessage("the test analysis fails on purpose"));
      if (fail_on_rank >= 0)
        {
          AssertThrow(int(dealii::Utilities::MPI::this_mpi_process(
                        context.mpi_communicator)) != fail_on_rank,
                      dealii::ExcMessage("a non-finite value in this rank's "
                                         "cells (on purpose)"));
          MPI_Barrier(context.mpi_communicator);
        }
      context.summary["length"] = length;
    }

  private:
    double       length          = 1;
    unsigned int n_files         = 2;
    bool         fail_during_run = false;
    int          fail_on_rank    = -1;
  };
} // namespace testing

MASONRY_REGISTER_ANALYSIS(testing::TestAnalysis,
                          "test",
                          "A small analysis for the tests of the driver.")

#endif
