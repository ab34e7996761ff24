/**
 * @file
 * Postprocessor `vault picture`: vault.png.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/scripts.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

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
       * A picture of the deformed vault for a paper, rendered by the
       * installed script vault_picture.py (matplotlib) from blocks.vtu and
       * interfaces.vtu: the blocks shaded by displacement magnitude, the
       * cracks, the supports and the prescribed motion of the settling
       * ones, a scale bar, seen from the side that moves most
       * (Result::view_direction()). Queued with the run's other pictures
       * (Result::render()); the analysis' `Write picture = false' turns it
       * off.
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
          if (!result.is_root() || !result.options().write_picture)
            return;
          OutputDirectory           &dir  = context.output;
          RunContext                *c    = &context;
          const dealii::Tensor<1, 2> view = result.view_direction();
          result.render(
            {"vault_picture.py",
             {dir.path() + "blocks.vtu",
              "{output}",
              xml_escape(context.summary.at("analysis").get<std::string>()),
              "--amplification",
              number(result.amplification()),
              "--view",
              number(view[0]) + "," + number(view[1])},
             dir.path() + "vault.png"},
            [&dir, c](const std::string &why) {
              if (why.empty())
                dir.file("vault.png");
              else
                c->pcout << "Note: vault.png not written (" << why << ")\n";
            });
        }

      private:
        static std::string
        number(const double x)
        {
          std::ostringstream s;
          s << std::setprecision(17) << x;
          return s.str();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::VaultPicture,
  "vault picture",
  "vault.png (with the analysis' `Write picture = true'; needs "
  "/usr/bin/python3 with matplotlib): a figure of the deformed vault, the "
  "blocks shaded by their displacement magnitude (mm), the cracks drawn "
  "by their opening, the fixed and settling supports (with the "
  "prescribed motion), a scale bar, seen from the side that moves most, "
  "rendered by the installed script vault_picture.py from blocks.vtu and "
  "interfaces.vtu (runs `blocks vtu' and `interfaces vtu') in the run's "
  "one Python process for pictures; summary entry `seconds_picture' (the "
  "time of all pictures).")
