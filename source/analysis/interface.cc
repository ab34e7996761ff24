#include <masonry/analysis/interface.h>

namespace masonry
{
  namespace analysis
  {
    const char *
    Interface::default_plugin()
    {
      return "settlement";
    }

    std::string
    Interface::selection_documentation()
    {
      return "What this run computes.";
    }



    void
    Interface::setup(dealii::ParameterHandler &)
    {}

    void
    Interface::check_output_directory(const std::string &, const MPI_Comm) const
    {}
  } // namespace analysis
} // namespace masonry
