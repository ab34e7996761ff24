/**
 * @file
 * Postprocessor `cracks`: the list of interfaces that open or rotate.
 */
#include <masonry/core/json.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /**
       * Summary entries `n_cracks`, `n_hinges` and `cracks` (every interface
       * whose jump exceeds Result::tolerance(), classified as hinge,
       * separation or slip) and one screen line.
       */
      class Cracks : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        execute(const Result &result, RunContext &context) override
        {
          const auto  &interfaces = result.model().interfaces();
          const auto  &motion     = result.motion();
          const double tolerance  = result.tolerance();
          Json         cracks     = Json::array();
          unsigned int n_hinges   = 0;
          for (unsigned int k = 0; k < interfaces.size(); ++k)
            {
              const rigid_blocks::Interface &i = interfaces[k];
              double max_opening = 0, min_opening = 0, max_jump = 0;
              bool   first = true;
              for (const auto &c : i.points)
                {
                  const auto   j       = result.jump(i, c);
                  const double opening = j * c.normal;
                  max_opening =
                    first ? opening : std::max(max_opening, opening);
                  min_opening =
                    first ? opening : std::min(min_opening, opening);
                  max_jump = std::max(max_jump, j.norm());
                  first    = false;
                }
              if (max_jump <= tolerance)
                continue;
              const dealii::Tensor<1, 3> omega =
                (i.second == rigid_blocks::Interface::support ?
                   dealii::Tensor<1, 3>() :
                   motion.rotation[i.second]) -
                motion.rotation[i.first];
              const std::string type =
                min_opening <= tolerance ?
                  (max_opening > tolerance ? "hinge" : "slip") :
                  "separation";
              if (type == "hinge")
                ++n_hinges;
              Json crack           = Json::object();
              crack["interface"]   = k;
              crack["first_block"] = i.first;
              crack["second"] = i.second == rigid_blocks::Interface::support ?
                                  Json("support: " + i.support_label) :
                                  Json(i.second);
              Json position   = Json::array();
              for (unsigned int d = 0; d < 3; ++d)
                position.push_back(i.centre[d]);
              crack["position"]          = position;
              crack["type"]              = type;
              crack["max_opening"]       = max_opening;
              crack["relative_rotation"] = omega.norm();
              cracks.push_back(crack);
            }
          context.summary["n_cracks"] = cracks.size();
          context.summary["n_hinges"] = n_hinges;
          context.summary["cracks"]   = cracks;
          context.pcout << "Cracks: " << cracks.size()
                        << " interfaces open or rotate (" << n_hinges
                        << " hinges)\n";
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::Cracks,
  "cracks",
  "Summary entries `n_cracks', `n_hinges' and `cracks': every interface "
  "that opens or rotates (a jump above 1e-4 of the largest displacement or "
  "support motion: below that the jumps of an interior point of the LP, "
  "not cracks), "
  "with its position (m), type (`hinge': opens at one face and stays "
  "closed at the other, `separation': opens everywhere, `slip': slides "
  "closed), `max_opening' (m) and `relative_rotation' (rad); and the "
  "screen line `Cracks: ...'.")
