/**
 * @file
 * Default hooks of the postprocessors and the list of a run.
 */
#include "postprocessor.h"

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      std::unique_ptr<Postprocessor>
      create_curve_tables();
      std::unique_ptr<Postprocessor>
      create_fields();
      std::unique_ptr<Postprocessor>
      create_joint_fields();
      std::unique_ptr<Postprocessor>
      create_curve_plot();
      std::unique_ptr<Postprocessor>
      create_calculix();

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

      std::vector<std::unique_ptr<Postprocessor>>
      create_postprocessors(const WalletteSettings &settings)
      {
        std::vector<std::unique_ptr<Postprocessor>> list;
        list.push_back(create_curve_tables());
        if (settings.output.write_vtu)
          {
            list.push_back(create_fields());
            list.push_back(create_joint_fields());
          }
        if (settings.output.write_plot)
          list.push_back(create_curve_plot());
        if (settings.output.write_calculix)
          list.push_back(create_calculix());
        return list;
      }
    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry
