/**
 * @file
 * The joints of a wallette as the model and its postprocessors see them:
 * pairs of coincident cell faces of two bricks (bed, head and collar
 * joints) or of one unit (splitting interfaces), with their type, normal,
 * vertices, area, cells and degrees of freedom. Public: a postprocessor
 * reads them through ModelView::joints.
 */
#ifndef masonry_brickwork_joint_faces_h
#define masonry_brickwork_joint_faces_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <array>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** A joint between two bricks: a pair of coincident cell faces. */
      struct InterfaceFace
      {
        /** 0 bed (normal z), 1 head (normal x), 2 collar (normal y), 3
         * splitting (through a unit: both sides belong to the same brick). */
        unsigned int type;
        /** Axis of the normal (from side A, lower coordinate, to B). */
        unsigned int axis;
        /** Whether this rank assembles it (owner of side A). */
        bool owned;
        /** Degrees of freedom: A vertices 0-3 then B, 3 components each. */
        std::vector<dealii::types::global_dof_index> dofs;
        /** Vertices of side A (face-lexicographic order). */
        std::array<dealii::Point<3>, 4> vertices;
        /** Area, m^2. */
        double area;
        /** Bricks on both sides. */
        unsigned int brick_a, brick_b;
        /** Active cell indices on both sides. */
        unsigned int cell_a, cell_b;
      };

      /** Integration points of a face pair (2 x 2, Gauss or Lobatto):
       * point q of face pair n is 4 n + q. */
      constexpr unsigned int joint_face_points = 4;

      /** InterfaceFace::type of a splitting interface. */
      constexpr unsigned int splitting_type = 3;

      /** Names of the joint types, by InterfaceFace::type. */
      extern const char *joint_type_name[4];

      /** All joints of the wallette. */
      struct Joints
      {
        std::vector<InterfaceFace> faces;
        /** Face pairs and joints (brick pairs) of each type. */
        std::array<unsigned int, 4> n_faces_of_type{{0, 0, 0, 0}},
          n_joints_of_type{{0, 0, 0, 0}};
      };

    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
