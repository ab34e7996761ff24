/**
 * @file
 * Postprocessor `support reactions`: the reaction of the ground on every
 * support label, summed from the contact forces.
 */
#include <masonry/core/json.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <map>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /** Summary entry `support_reactions`: {label: [Rx, Ry, Rz]} in N. */
      class SupportReactions : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        execute(const Result &result, RunContext &context) override
        {
          std::map<std::string, dealii::Tensor<1, 3>> reactions;
          unsigned int                                p = 0;
          for (const auto &i : result.model().interfaces())
            for (const auto &c : i.points)
              {
                if (i.second == rigid_blocks::Interface::support &&
                    p < result.n_forces())
                  {
                    // the force on block `first` is −(F_n n + F_a a + F_l l),
                    // n pointing from the block into the ground
                    const auto f = result.force(p);
                    reactions[i.support_label] -=
                      f[0] * c.normal + f[1] * c.across + f[2] * c.along;
                  }
                ++p;
              }
          Json json = Json::object();
          for (const auto &[label, r] : reactions)
            {
              Json v = Json::array();
              for (unsigned int d = 0; d < 3; ++d)
                v.push_back(r[d]);
              json[label] = v;
            }
          context.summary["support_reactions"] = json;
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::SupportReactions,
  "support reactions",
  "Summary entry `support_reactions': for every support label the sum of "
  "the contact forces (N, global x, y, z) that the ground exerts on the "
  "vault, from the LP dual.")
