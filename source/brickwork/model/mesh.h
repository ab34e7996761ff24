/**
 * @file
 * Mesh of the enlarged bricks: one block of hexahedra per brick (the bricks'
 * meshes match across the joints), optionally distorted or merged into one
 * continuum.
 */
#ifndef masonry_brickwork_model_mesh_h
#define masonry_brickwork_model_mesh_h

#include <masonry/brickwork/wallette.h>

#include <deal.II/grid/tria.h>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The overall dimensions of the wallette, m and m^2. */
      struct Geometry
      {
        double       height = 0, length = 0, thickness = 0, gross_area = 0;
        unsigned int n_bricks = 0;
        /** Units meshed as two halves (MeshSettings::split_units). */
        unsigned int n_split_units = 0;
        /** Cells of mortar (the detailed model; material id n_bricks). */
        unsigned int n_mortar_cells = 0;
        /**
         * Areas of the head joints and the collar joints in their planes
         * (height x width of a head joint, height x length of the collar
         * joint, crossings counted as collar), and of their unfilled parts
         * (MeshSettings::head_joint_fill, collar_joint_fill), m^2.
         */
        double head_joint_area = 0, head_void_area = 0;
        double collar_joint_area = 0, collar_void_area = 0;
        /**
         * Plan area of the unfilled strips of the bed joints along the
         * collar joints (MeshSettings::collar_bed_gap), summed over the bed
         * joints, m^2.
         */
        double bed_void_area = 0;
        /** Void (omitted) mortar cells. */
        unsigned int n_void_cells = 0;
      };

      /** Cells of @p box along direction @p d of spacing @p h; 0 if not a
       * whole number. */
      unsigned int
      divisions(const Box &box, const unsigned int d, const double h);

      /**
       * Fill @p triangulation with the bricks @p boxes (material id = brick
       * index) meshed as @p settings say; returns the dimensions.
       */
      /**
       * The detailed model (MeshSettings::detailed): each unit is its box
       * less the mortar thickness h_m along the box's upper faces in x, y
       * and z (so every unit has the actual brick size and the wallette is
       * h_m shorter, thinner and lower than its enlarged boxes), the rest of
       * the wallette's bounding box is mortar. All cells lie on one tensor
       * grid through every unit's faces (and mid-planes of split units),
       * mortar intervals one cell thick, the others divided at about the
       * mesh spacing; the mortar cells (material id = number of bricks)
       * share their vertices, each unit (or half unit) has its own, unless
       * `bonded'.
       */
      Geometry
      make_detailed_mesh(const std::vector<Box>   &boxes,
                         const MeshSettings       &settings,
                         dealii::Triangulation<3> &triangulation);

      Geometry
      make_mesh(const std::vector<Box>   &boxes,
                const MeshSettings       &settings,
                dealii::Triangulation<3> &triangulation);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
