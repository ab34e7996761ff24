/**
 * @file
 * The wallette analysis's solver entries (load stepping, Newton, linear
 * solver, assembly threads): declared and read apart from the model's
 * entries to keep wallette_compression.cc readable. Private to
 * source/analysis.
 */
#ifndef masonry_analysis_wallette_solver_entries_h
#define masonry_analysis_wallette_solver_entries_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace masonry
{
  namespace brickwork
  {
    struct WalletteSettings;
  }

  namespace analysis
  {
    /** Declare the solver entries in the present subsection of @p prm. */
    void
    declare_solver_entries(dealii::ParameterHandler &prm);

    /** The value of @p entry of @p prm; throws ExcParameter naming the
     * entry unless it is positive. */
    double
    positive_entry(dealii::ParameterHandler &prm, const std::string &entry);

    /** Read the solver entries of @p prm into @p s. */
    void
    parse_solver_entries(dealii::ParameterHandler    &prm,
                         brickwork::WalletteSettings &s);
  } // namespace analysis
} // namespace masonry

#endif
