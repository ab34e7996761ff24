/**
 * @file
 * What a wallette run reports about its model: the size, the joints and
 * the derived values of every law (summary.json and the screen), the
 * detailed model's own derived values, and the largest damages of the
 * converged states (curve.csv).
 */
#ifndef masonry_brickwork_model_report_h
#define masonry_brickwork_model_report_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/view.h>

#include <utility>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /**
       * The model's size, joints, detailed model and splitting interfaces
       * and every value a law computed from its inputs, into summary.json
       * and on the screen.
       */
      void
      describe_model(const ModelView &view);

      /**
       * The detailed model's derived values (none with @p mortar nullptr):
       * the bond's penalty k_n, the compliance of a bed joint's two
       * interfaces against the mortar layer's, (2/k_n)/(h_m/E_m), and the
       * Lourenco-Rots stiffness the simplified model would use (not used).
       */
      std::vector<DerivedValue>
      detailed_values(const BrickMaterial &material,
                      const BrickMaterial *mortar,
                      const InterfaceLaw  &law,
                      const double         mortar_thickness);

      /** Largest damages of the converged states over all ranks: joints
       * and splitting interfaces, and each damage of the bricks (deleted
       * cells left out). */
      std::pair<double, std::vector<double>>
      max_damages(const ModelView &view);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
