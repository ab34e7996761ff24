/**
 * @file
 * The zero-thickness interface element of a face pair (4 + 4 nodes): the
 * displacement jumps at its integration points and its force vector and
 * tangent from the law's tractions and tangents. Pure functions of the
 * face's geometry (normal axis, area) and its 24 nodal displacements, so
 * that they can be tested on their own.
 */
#ifndef masonry_brickwork_model_interface_element_h
#define masonry_brickwork_model_interface_element_h

#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/joint_faces.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /**
       * A bilinear interface element on an axis-aligned face pair. Nodal
       * values: side A vertices 0-3 (face-lexicographic order) then side B,
       * 3 global components each; the local frame of a face of normal axis
       * a is (a, a + 1, a + 2) mod 3, so the jump's component 0 is the
       * normal opening (B minus A) and 1, 2 the slips.
       */
      class InterfaceElement
      {
      public:
        /** Number of integration points (2 x 2). */
        static constexpr unsigned int n_points = joint_face_points;

        /** Gauss (true) or Lobatto (false: the nodes) points. */
        explicit InterfaceElement(const bool gauss);

        /** The four bilinear shape values at point q (q = qx + 2 qy). */
        std::array<double, 4>
        shapes(const unsigned int q) const;

        /** Openings (local frame) at the points from the 24 nodal values
         * @p ue of a face of normal @p axis. */
        void
        jumps(const unsigned int            axis,
              const dealii::Vector<double> &ue,
              std::array<Local3, n_points> &jumps) const;

        /**
         * Force vector @p fi and (if @p ki) tangent of a face of normal
         * @p axis and @p area from the tractions and tangents at its
         * points.
         */
        void
        local(const unsigned int                   axis,
              const double                         area,
              const std::array<Local3, n_points>  &tractions,
              const std::array<Local33, n_points> &tangents,
              dealii::Vector<double>              &fi,
              dealii::FullMatrix<double>          *ki) const;

      private:
        std::array<double, 2> q_points, q_weights;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
