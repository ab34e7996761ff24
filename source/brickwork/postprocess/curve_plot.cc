/**
 * @file
 * curve.png (stress-strain curve with the cycle peaks) and degradation.png
 * (unloading modulus over the initial modulus per cycle), drawn by
 * the installed script contrib/plot/wallette_curve.py (matplotlib) from
 * curve.csv and cycles.csv.
 */
#include <masonry/brickwork/postprocessor.h>
#include <masonry/brickwork/protocol.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/scripts.h>

#include <filesystem>

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      namespace
      {
        /** Runs the plot script at the end of the run. */
        class CurvePlot : public Postprocessor
        {
        public:
          static void
          declare_parameters(dealii::ParameterHandler &)
          {}

          void
          finish(const ModelView &view, Json &) override
          {
            // the pictures are named as files of this run only once drawn:
            // a file named but not written makes the run `failed'
            const bool cyclic = view.protocol.is_cyclic();
            if (!view.is_root())
              return;
            const std::string why =
              run_script("wallette_curve.py",
                         {view.context.output.path()},
                         {view.context.output.path() + "curve.png",
                          view.context.output.path() + "degradation.png"});
            if (why.empty())
              {
                view.context.output.file("curve.png");
                if (cyclic)
                  view.context.output.file("degradation.png");
              }
            else
              view.context.pcout << "Warning: the plots could not be drawn ("
                                 << why << ")\n";
          }
        };
      } // namespace

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  masonry::brickwork::postprocess::CurvePlot,
  "curve plot",
  "curve.png (stress over strain with the cycle peaks) and, for the cyclic protocol, degradation.png (unloading modulus over the initial modulus), drawn at the end of the run by the installed script wallette_curve.py with /usr/bin/python3 and matplotlib.")
