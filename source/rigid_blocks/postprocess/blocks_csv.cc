/**
 * @file
 * Postprocessor `blocks csv`: blocks.csv.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <iomanip>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /** The rigid motion of every block, to full precision. */
      class BlocksCsv : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        execute(const Result &result, RunContext &context) override
        {
          if (!result.is_root())
            return;
          const auto &blocks = result.model().blocks();
          const auto &motion = result.motion();
          OutputFile  csv(context.output.file("blocks.csv"));
          csv << "block,patch,centroid_x,centroid_y,centroid_z,"
                 "translation_x_m,translation_y_m,translation_z_m,"
                 "rotation_x_rad,rotation_y_rad,rotation_z_rad\n"
              << std::setprecision(17);
          for (unsigned int b = 0; b < blocks.size(); ++b)
            {
              csv << b << "," << blocks[b].patch;
              for (unsigned int d = 0; d < 3; ++d)
                csv << "," << blocks[b].centroid[d];
              for (unsigned int d = 0; d < 3; ++d)
                csv << "," << motion.translation[b][d];
              for (unsigned int d = 0; d < 3; ++d)
                csv << "," << motion.rotation[b][d];
              csv << "\n";
            }
          csv.close();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::BlocksCsv,
  "blocks csv",
  "blocks.csv: per block its patch, centroid (m), translation of the "
  "centroid (m) and rotation (rad), to full precision (17 digits).")
