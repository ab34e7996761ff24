/**
 * @file
 * What the crack outputs share: the state of every interface (open, hinge,
 * slip: the classification of the `cracks` postprocessor) and the developed
 * vault surface on which the crack map is drawn (`crack map`, `report`).
 */
#ifndef masonry_rigid_blocks_postprocess_crack_map_h
#define masonry_rigid_blocks_postprocess_crack_map_h

#include <masonry/rigid_blocks/postprocess/interface.h>

#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /**
       * The jumps of one interface and what they make of it. An interface
       * whose largest jump is at most Result::tolerance() is closed; else
       * it is a `hinge' (opens at some points, stays closed at others), a
       * `separation' (opens everywhere) or a `slip' (slides closed).
       */
      struct InterfaceState
      {
        /** Largest normal opening of the points, m (negative: closing). */
        double max_opening = 0;
        /** Smallest normal opening of the points, m. */
        double min_opening = 0;
        /** Largest normal opening of the intrados points, m. */
        double intrados_opening = 0;
        /** Largest normal opening of the extrados points, m. */
        double extrados_opening = 0;
        /** Largest jump (opening and slip), m. */
        double max_jump = 0;
        /** Norm of the relative rotation of the two sides, rad. */
        double relative_rotation = 0;
        /** "closed", "hinge", "separation" or "slip". */
        std::string type = "closed";

        /** Whether it is a crack (not closed). */
        bool
        is_crack() const
        {
          return type != "closed";
        }
      };

      /** The state of interface @p i of @p result's model. */
      InterfaceState
      interface_state(const Result &result, const rigid_blocks::Interface &i);

      /**
       * The developed vault surface: every patch's unit parameter square
       * mapped to the plane by the arc lengths of its intrados (m), s along
       * u measured on the line v = 1/2 and t along v on the line u = 1/2.
       * For a barrel vault or an arch (surfaces extruded along v) this is
       * the unrolled intrados exactly; for doubly curved patches it is the
       * parameter square stretched to the intrados' lengths. Patches whose
       * whole edges meet (the two halves of a barrel at the crown) are laid
       * side by side, mirrored where needed, so the map of a barrel runs
       * from one springing to the other; other patches are drawn apart, in
       * a row, with their names.
       */
      class DevelopedSurface
      {
      public:
        /** Lay out the patches of @p model's geometry. */
        explicit DevelopedSurface(const BlockModel &model);

        /** The point of the map (m) of parameters @p uv of patch @p p. */
        dealii::Point<2>
        map(const unsigned int p, const dealii::Point<2> &uv) const;

        /**
         * The image of the parameter segment @p a → @p b of patch @p p as
         * @p n + 1 points (the map is not linear in the parameters).
         */
        std::vector<dealii::Point<2>>
        segment(const unsigned int      p,
                const dealii::Point<2> &a,
                const dealii::Point<2> &b,
                const unsigned int      n = 6) const;

        /** The centre of patch @p p's image (for its name). */
        dealii::Point<2>
        centre(const unsigned int p) const;

      private:
        /** Arc length of the intrados (m) at the samples of u and v. */
        struct Lengths
        {
          std::vector<double> s, t;
        };
        /** Linear interpolation in a table at n + 1 equidistant samples. */
        static double
        interpolate(const std::vector<double> &table, const double x);

        std::vector<Lengths>               lengths;
        std::vector<std::array<double, 2>> sign;
        std::vector<dealii::Tensor<1, 2>>  offset;
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

#endif
