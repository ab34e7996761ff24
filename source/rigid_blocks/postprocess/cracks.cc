/**
 * @file
 * Postprocessor `cracks`: the list of interfaces that open or rotate.
 */
#include <masonry/core/json.h>
#include <masonry/rigid_blocks/postprocess/crack_map.h>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /**
       * Summary entries `n_cracks`, `n_hinges` and `cracks` (every interface
       * whose jump exceeds Result::tolerance(), classified as hinge,
       * separation or slip by interface_state()) and one screen line.
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
          Json         cracks     = Json::array();
          unsigned int n_hinges   = 0;
          for (unsigned int k = 0; k < interfaces.size(); ++k)
            {
              const rigid_blocks::Interface &i     = interfaces[k];
              const InterfaceState           state = interface_state(result, i);
              if (!state.is_crack())
                continue;
              if (state.type == "hinge")
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
              crack["type"]              = state.type;
              crack["max_opening"]       = state.max_opening;
              crack["relative_rotation"] = state.relative_rotation;
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
