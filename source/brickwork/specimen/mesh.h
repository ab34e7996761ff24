/**
 * @file
 * Mesh of the enlarged bricks: one block of hexahedra per brick (the bricks'
 * meshes match across the joints), optionally distorted or merged into one
 * continuum.
 */
#ifndef masonry_brickwork_model_mesh_h
#define masonry_brickwork_model_mesh_h

#include <masonry/brickwork/bond.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    /** The mesh of enlarged bricks (`Elements along ...', `Joints',
     * `Mesh distortion'). */
    struct MeshSettings
    {
      /** Sizes of the enlarged brick and of the wallette. */
      WalletteSize size;
      /** Elements along the enlarged brick's length, width and height: the
       * mesh spacing is length/n_l, width/n_w, height/n_h everywhere. */
      unsigned int n_l = 4, n_w = 2, n_h = 2;
      /**
       * Merge the coincident vertices of neighbouring bricks (a perfectly
       * bonded continuum without interfaces, as a reference).
       */
      bool bonded = false;
      /**
       * Amplitude of a smooth distortion of the mesh, as a fraction of the
       * mesh spacing in each direction (dimensionless, 0 to 0.2; 0: the
       * regular mesh). With interfaces, each brick's vertices move by a
       * bubble that vanishes on the brick's faces (joint faces and the
       * wallette's faces stay as they are); with `bonded' joints, one
       * global map moves every vertex but keeps each face of the wallette
       * in its plane. For patch tests: the exact solution of uniform
       * compression does not change.
       */
      double distortion = 0;
      /** Gauss (true) or Lobatto (false) points on interfaces. */
      bool gauss = false;
      /**
       * Mesh each unit as two halves that meet at a vertical plane through
       * its middle, normal to its longer horizontal side (in line with the
       * head joints of the next course for a stretcher): the halves do not
       * share vertices, so the plane becomes a splitting interface. Units
       * whose half is not a whole number of cells stay whole.
       */
      bool split_units = false;
      /**
       * The `detailed' model (`Model = detailed'): the units at their actual
       * size (the enlarged box less mortar_thickness along its upper faces in
       * x, y and z), the mortar between them meshed as one layer of
       * hexahedra of thickness mortar_thickness with its own material, and
       * zero-thickness interfaces (the bond) between units and mortar.
       * false: the `simplified' model of enlarged bricks.
       */
      bool detailed = false;
      /** Thickness of the mortar joints of the detailed model, m. */
      double mortar_thickness = 0;
      /**
       * Filled fraction of the height of every head joint and of every
       * collar joint (detailed model; `Head joint fill', `Collar joint
       * fill'), 0 to 1: each vertical joint is mortar from the bed joint
       * below up to this fraction of the course height, the rest up to the
       * bed joint above is a void (no cells; the unit faces there are
       * free). Where a head joint meets the collar joint the column counts
       * as collar joint. 1: full joints.
       */
      double head_joint_fill = 1, collar_joint_fill = 1;
      /**
       * Width of the unfilled strip of every bed joint on each side of a
       * collar joint (detailed model; `Collar bed gap'), m: the bed-joint
       * mortar under and over the collar plane, widened by this on both
       * sides, is a void (the beds of the wythes spread separately and not
       * joined). 0: full bed joints.
       */
      double collar_bed_gap = 0;

      /** Declare the entries (the wallette's size, the model, the mesh,
       * the joints) in the present subsection. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /** Read them; errors name the entry. */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /** Mesh spacing in x, y, z (m). */
    std::array<double, 3>
    mesh_spacing(const MeshSettings &settings);

    /**
     * Check that every box is a whole number of mesh cells in each
     * direction; throws an ExcParameter naming the entry to change.
     */
    void
    check_mesh(const std::vector<Box> &boxes, const MeshSettings &settings);

    /**
     * Check that every unit of the detailed model (a box less one joint,
     * MeshSettings::mortar_thickness) keeps a size in each direction;
     * throws an ExcParameter naming `Joint thickness'.
     */
    void
    check_units(const std::vector<Box> &boxes, const MeshSettings &settings);

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

      /** The direction a unit is split in (its longer horizontal side). */
      unsigned int
      split_direction(const Box &box);

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
