/**
 * @file
 * Postprocessor `interface forces`: interface_forces.csv.
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
      /** The contact forces of every contact point (from the LP dual). */
      class InterfaceForces : public Interface
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
          const auto &interfaces = result.model().interfaces();
          OutputFile  csv(context.output.file("interface_forces.csv"));
          csv << "interface,first_block,second_block,x,y,z,intrados,"
                 "normal_force_N,shear_across_N,shear_along_N\n"
              << std::setprecision(10);
          unsigned int p = 0;
          for (unsigned int k = 0; k < interfaces.size(); ++k)
            for (const auto &c : interfaces[k].points)
              {
                const auto f = result.force(p++);
                csv << k << "," << interfaces[k].first << ","
                    << (interfaces[k].second ==
                            rigid_blocks::Interface::support ?
                          std::string("support") :
                          std::to_string(interfaces[k].second))
                    << "," << c.position[0] << "," << c.position[1] << ","
                    << c.position[2] << "," << (c.intrados ? 1 : 0) << ","
                    << f[0] << "," << f[1] << "," << f[2] << "\n";
              }
          csv.close();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::InterfaceForces,
  "interface forces",
  "interface_forces.csv: per contact point the interface, its blocks, the "
  "position (m), an intrados flag and the normal and shear forces (N, "
  "compression positive) from the LP dual (a statically admissible state). "
  "Where the vault is statically indeterminate at collapse these forces are "
  "not unique: with `Crossover = never' (the default) they are the "
  "barrier's point inside the set of optimal states, with `always' one "
  "vertex of it; on the Bothwell and barrel settlement examples the "
  "interfaces' normal resultants differ by up to 18 % between the two, the "
  "support reactions' sum not at all. With `no tension no sliding' joints "
  "the set is unbounded (self-stress) and the barrier's point (from 2000 "
  "rows of the dual LP up) is its centre cut off at the total load per "
  "force: on the vertical Bothwell settlement at 12 x 16 blocks per half the "
  "resultants reach 2.0 times the vertex's largest.")
