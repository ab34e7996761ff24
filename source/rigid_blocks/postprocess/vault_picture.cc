/**
 * @file
 * Postprocessor `vault picture`: vault.png.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/scripts.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      namespace
      {
        std::string
        xml_escape(const std::string &s)
        {
          std::string out;
          for (const char c : s)
            out += (c == '&') ? "&amp;" :
                   (c == '<') ? "&lt;" :
                   (c == '>') ? "&gt;" :
                                std::string(1, c);
          return out;
        }
      } // namespace

      /**
       * A picture of the deformed vault rendered by the installed script
       * vault_picture.py (matplotlib) from blocks.vtu and interfaces.vtu.
       * The analysis' `Write picture = false` turns it off.
       */
      class VaultPicture : public Interface
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
          const auto start = std::chrono::steady_clock::now();
          if (result.options().write_picture)
            render(result, context);
          context.summary["seconds_picture"] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          start)
              .count();
        }

      private:
        static void
        render(const Result &result, RunContext &context)
        {
          OutputDirectory   &dir = context.output;
          std::ostringstream amplification;
          amplification << std::setprecision(17) << result.amplification();
          const std::string why = run_script(
            "vault_picture.py",
            {dir.path() + "blocks.vtu",
             dir.path() + "vault.png",
             xml_escape(context.summary.at("analysis").get<std::string>()),
             "--amplification",
             amplification.str()},
            {dir.path() + "vault.png"});
          if (why.empty())
            dir.file("vault.png");
          else
            context.pcout << "Note: vault.png not written (" << why << ")\n";
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::VaultPicture,
  "vault picture",
  "vault.png (with the analysis' `Write picture = true'; needs "
  "/usr/bin/python3 with matplotlib): the deformed vault with the blocks "
  "in grey and every interface that opens coloured by its opening (mm), "
  "rendered by the installed script vault_picture.py from blocks.vtu and "
  "interfaces.vtu (runs `blocks vtu' and `interfaces vtu'); summary entry "
  "`seconds_picture'.")
