/**
 * @file
 * Implicit and IMPL-EX integration.
 */
#include "integrator.h"

#include <algorithm>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      double
      Integrator::extrapolated(const double d, const double d_older) const
      {
        return std::clamp(d + ratio * (d - d_older), d, 1.);
      }

      const char *
      Integrator::default_plugin()
      {
        return "implicit";
      }

      std::string
      Integrator::selection_documentation()
      {
        return "How the brick and joint laws are integrated in a load step.";
      }



    } // namespace model
  }   // namespace brickwork
} // namespace masonry
