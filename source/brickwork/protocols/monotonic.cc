/**
 * @file
 * The monotonic protocol: one ramp of the platen to the target strain.
 */
#include <masonry/brickwork/protocol.h>

namespace masonry
{
  namespace brickwork
  {
    namespace
    {
      /** One ramp to `Target strain' times the height. */
      class Monotonic : public Protocol
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        initialize(const double height) override
        {
          target = target_strain * height;
        }

        std::vector<Leg>
        legs() const override
        {
          return {{target, false, 1}};
        }

        double
        amplitude(const unsigned int) const override
        {
          return target;
        }

        double
        target_displacement() const override
        {
          return target;
        }

      private:
        /** Platen displacement at the end, m. */
        double target = 0;
      };
    } // namespace
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_PROTOCOL(masonry::brickwork::Monotonic,
                          "monotonic",
                          "The top platen moves to the target strain in one "
                          "ramp.")
