/**
 * @file
 * Postprocessor `vault pvd`: vault.pvd.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/rigid_blocks/postprocess/interface.h>


namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /** A ParaView collection of blocks.vtu and interfaces.vtu. */
      class VaultPvd : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        std::vector<std::string>
        required_plugins() const override
        {
          return {"blocks vtu", "interfaces vtu"};
        }

        void
        execute(const Result &result, RunContext &context) override
        {
          if (!result.is_root())
            return;
          OutputFile pvd(context.output.file("vault.pvd"));
          pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                 "version=\"0.1\">\n<Collection>\n"
              << "<DataSet timestep=\"0\" part=\"0\" file=\"blocks.vtu\" "
                 "name=\"blocks\"/>\n"
              << "<DataSet timestep=\"0\" part=\"1\" file=\"interfaces.vtu\" "
                 "name=\"interfaces\"/>\n</Collection>\n</VTKFile>\n";
          pvd.close();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::VaultPvd,
  "vault pvd",
  "vault.pvd: blocks.vtu and interfaces.vtu as one ParaView collection "
  "(runs `blocks vtu' and `interfaces vtu').")
