/**
 * @file
 * Default hooks of the postprocessors and the list of a run.
 */
#include <masonry/brickwork/postprocessor.h>

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      const char *
      Postprocessor::default_plugin()
      {
        return "curve tables, fields, joint fields, curve plot";
      }

      std::string
      Postprocessor::selection_documentation()
      {
        return "The outputs of the wallette analysis, run in the order of "
               "the list (`curve tables' always runs first: the other "
               "outputs and summary.json use its curve). `fields' and "
               "`joint fields' run only with `Write VTU = true', `curve "
               "plot' only with `Write plot = true'; `Write CalculiX input "
               "= true' adds `calculix'. Postprocessors of an `Additional "
               "shared libraries' file can be listed too.";
      }

      void
      Postprocessor::declare_common_parameters(dealii::ParameterHandler &)
      {}

      void
      Postprocessor::parse_common_parameters(dealii::ParameterHandler &)
      {}

      void
      Postprocessor::parse_parameters(dealii::ParameterHandler &)
      {}

      void
      Postprocessor::start(const ModelView &)
      {}

      void
      Postprocessor::resume(const ModelView &)
      {}

      void
      Postprocessor::step(const ModelView &)
      {}

      void
      Postprocessor::output(const ModelView &, const unsigned int, const double)
      {}

      void
      Postprocessor::finish(const ModelView &, Json &)
      {}

      std::string
      Postprocessor::save() const
      {
        return {};
      }

      void
      Postprocessor::load(const std::string &)
      {}

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry
