/**
 * @file
 * Rigid blocks cut from NURBS patches in parameter space, and the contact
 * interfaces between them and with the supports.
 */
#ifndef masonry_rigid_blocks_block_model_h
#define masonry_rigid_blocks_block_model_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <set>
#include <string>
#include <vector>

namespace masonry
{
  namespace geometry
  {
    class Interface;
  }

  /** Rigid-block models of vaults. */
  namespace rigid_blocks
  {
    /**
     * A block: the solid between intrados and extrados over one cell of a
     * patch's parameter mesh. Its six degrees of freedom are the
     * translation of its centroid and its rotation.
     */
    struct Block
    {
      /** Index of the patch the block belongs to. */
      unsigned int patch;
      /** Cell corners in the patch's unit parameter square (counter-clockwise:
       * (0,0), (1,0), (1,1), (0,1) of the reference cell). */
      std::array<dealii::Point<2>, 4> corners;
      /** Volume, m³. */
      double volume;
      /** Centroid, m. */
      dealii::Point<3> centroid;
      /** Self weight, N (density × g × volume). */
      double weight;
      /** Resultant of extra dead loads on the block, N. */
      dealii::Tensor<1, 3> extra_force;
      /** Moment of the extra dead loads about the centroid, N·m. */
      dealii::Tensor<1, 3> extra_moment;
    };

    /**
     * A point of an interface where contact conditions are written, with
     * its local frame: @p normal from the first block into the second (or
     * into the ground), @p across the thickness (shell normal), @p along
     * the interface edge.
     */
    struct ContactPoint
    {
      /** Position, m. */
      dealii::Point<3> position;
      /** Unit normal of the interface, from block `first` to `second`. */
      dealii::Tensor<1, 3> normal;
      /** Unit tangent across the thickness. */
      dealii::Tensor<1, 3> across;
      /** Unit tangent along the edge. */
      dealii::Tensor<1, 3> along;
      /** Tributary area, m² (the interface area shared among its points). */
      double area;
      /** Whether the point lies on the intrados (else on the extrados). */
      bool intrados;
    };

    /**
     * An interface: the ruled surface across the thickness along a cell
     * edge, between two blocks or between a block and a support.
     */
    struct Interface
    {
      /** The first block. */
      unsigned int first;
      /** The second block, or `support` for the ground. */
      unsigned int second;
      /** Label of the supported edge (supports only). */
      std::string support_label;
      /** Contact points: intrados and extrados at every station. */
      std::vector<ContactPoint> points;
      /** Area, m². */
      double area;
      /** Centre of the interface, m. */
      dealii::Point<3> centre;
      /** The patch of block `first`. */
      unsigned int patch = 0;
      /**
       * The interface's edge in the unit parameter square of that patch,
       * from its first station to its last (for pictures drawn in
       * parameter space: the crack map).
       */
      std::array<dealii::Point<2>, 2> edge;

      /** Marker for the ground as second body. */
      static constexpr unsigned int support = static_cast<unsigned int>(-1);
    };

    /**
     * What a BlockModel evaluated on the middle surface at one quadrature
     * point of a block (BlockModel::quadrature()): kept so that neither a
     * change of the thickness factor (BlockModel::update_thickness()) nor
     * the integration of surface loads evaluates the NURBS patch again.
     */
    struct SurfaceSample
    {
      /** Parameters in the patch's unit square. */
      dealii::Point<2> uv;
      /** Quadrature weight (parameter area, Jacobian of the cell map
       * included). */
      double weight;
      /** Point of the middle surface, m. */
      dealii::Point<3> point;
      /** dx/du and dx/dv, m per unit parameter. */
      std::array<dealii::Tensor<1, 3>, 2> tangents;
      /** Unit normal towards the extrados. */
      dealii::Tensor<1, 3> normal;
      /** Derivatives of the unit normal along u and v. */
      std::array<dealii::Tensor<1, 3>, 2> normal_derivatives;
      /** Thickness without the geometry's thickness factor, m. */
      double unscaled_thickness;
    };

    /**
     * Options of the discretisation into blocks.
     */
    struct Discretisation
    {
      /** Blocks along u in every patch. */
      unsigned int n_u = 3;
      /** Blocks along v in every patch. */
      unsigned int n_v = 4;
      /** Stations along every interface edge (≥ 2; ends included). */
      unsigned int n_stations = 3;
      /** Gauss points per parameter direction for volumes and loads. */
      unsigned int n_quadrature = 6;
      /** Edge labels (from the geometry plugin) that rest on supports. */
      std::set<std::string> supported_edges;
      /**
       * Local refinement of the parameter meshes, replayed on the
       * n_u × n_v mesh of every patch: splits[p][r] are the centres (unit
       * parameter square) of the cells of patch p split into four in
       * round r. The mesh stays graded (deal.II splits a neighbour too
       * where two cells sharing an edge would differ by more than one
       * level), and an edge between a cell and two split neighbours
       * carries one interface per neighbour, along the common half of the
       * edge (non-conforming blocks; also across patches). Empty: no
       * local refinement.
       */
      std::vector<std::vector<std::vector<dealii::Point<2>>>> splits;
    };

    /**
     * Blocks and interfaces of a vault. The parameter mesh of each patch is
     * given by its cell corners, so an optimiser can move them; the model is
     * rebuilt from the corners.
     */
    class BlockModel
    {
    public:
      /**
       * Cut every patch of @p geometry into n_u × n_v cells of its unit
       * parameter square (uniform) and build blocks and interfaces.
       */
      BlockModel(const geometry::Interface &geometry,
                 const Discretisation      &options);

      /**
       * Build blocks and interfaces from given parameter meshes: for every
       * patch, the (n_u + 1) × (n_v + 1) vertices in lexicographic order
       * (u fastest) of a structured mesh of its unit square.
       */
      BlockModel(const geometry::Interface                        &geometry,
                 const Discretisation                             &options,
                 const std::vector<std::vector<dealii::Point<2>>> &vertices);

      /** The blocks. */
      const std::vector<Block> &
      blocks() const;

      /** The interfaces (between blocks, then with supports). */
      const std::vector<Interface> &
      interfaces() const;

      /** Total number of contact points. */
      unsigned int
      n_contact_points() const;

      /** The geometry. */
      const geometry::Interface &
      geometry() const;

      /** The options. */
      const Discretisation &
      discretisation() const;

      /** The vertices of every patch's parameter mesh. */
      const std::vector<std::vector<dealii::Point<2>>> &
      parameter_vertices() const;

      /**
       * A point of block @p b at parameters @p uv of its patch and
       * @p zeta ∈ [-1/2, 1/2] across the thickness (−½ intrados, +½
       * extrados).
       */
      dealii::Point<3>
      solid_point(const unsigned int      b,
                  const dealii::Point<2> &reference,
                  const double            zeta) const;

      /**
       * Quadrature on the middle surface of block @p b: parameter points and
       * weights (in parameter area, including the Jacobian of the cell map).
       * Axis-aligned cells are split at the knot lines of the NURBS patch so
       * that Gauss quadrature integrates smooth (rational) functions on
       * every piece; other cells use a Gauss rule on the bilinear cell map.
       */
      std::vector<std::pair<dealii::Point<2>, double>>
      quadrature(const unsigned int b) const;

      /**
       * The surface samples of block @p b at the points of quadrature(b),
       * in the same order, as evaluated when the model was built.
       */
      const std::vector<SurfaceSample> &
      surface_samples(const unsigned int b) const;

      /**
       * Recompute what depends on the geometry's thickness factor (block
       * volumes, centroids and weights; contact points and areas of the
       * interfaces) after geometry::Interface::set_thickness_factor(), from
       * the samples of the middle surface kept when the model was built:
       * no NURBS evaluation, and the same numbers, bit for bit, as a model
       * built anew with that factor. Blocks, interfaces and their order
       * do not change.
       */
      void
      update_thickness();

      /** A characteristic length of the model (m): the bounding-box size. */
      double
      length_scale() const;

    private:
      struct BoundaryFace;
      struct InnerFace;

      void
      build();
      /** The blocks of patch @p p (cells of its parameter mesh); its faces
       * into @p boundary_faces and @p inner_faces. */
      void
      add_patch_blocks(const unsigned int         p,
                       std::vector<BoundaryFace> &boundary_faces,
                       std::vector<InnerFace>    &inner_faces);
      /**
       * The interface along the edge uv[0] -> uv[1] of a block of patch
       * @p p between blocks @p first and @p second (or a support): contact
       * points at the stations, normal along the parameter-space direction
       * @p outward mapped to 3D (out of block @p first). None if the edge
       * has no area.
       */
      void
      add_interface(const unsigned int                     p,
                    const std::array<dealii::Point<2>, 2> &uv,
                    const dealii::Point<2>                &outward,
                    const unsigned int                     first,
                    const unsigned int                     second);
      /** What an interface keeps of one station: the middle-surface
       * point, the interface normal, the shell normal, the trapezoidal
       * length weight (m) and the unscaled thickness (m). */
      struct Station
      {
        dealii::Point<3>     x;
        dealii::Tensor<1, 3> normal, across;
        double               weight, unscaled_thickness;
      };
      /** Volume, centroid and weight of block @p b from its samples. */
      void
      compute_mass(const unsigned int b);
      /** Contact points, area and centre of @p interface from its
       * stations. */
      void
      compute_contact_points(Interface                  &interface,
                             const std::vector<Station> &stations) const;
      /** Boundary faces glued to another patch's face, on a support, or
       * free. */
      void
      connect_boundary_faces(const std::vector<BoundaryFace> &boundary_faces);

      const geometry::Interface                 &geom;
      Discretisation                             options;
      std::vector<std::vector<dealii::Point<2>>> vertices;
      std::vector<Block>                         block_list;
      std::vector<Interface>                     interface_list;
      /** Surface samples of every block (see surface_samples()). */
      std::vector<std::vector<SurfaceSample>> block_samples;
      /** Stations of every interface, in the order of interface_list. */
      std::vector<std::vector<Station>> interface_stations;
      double                            size;
    };

    /**
     * Velocity of the point @p x of a block with centroid @p g, translation
     * @p u and rotation @p theta: u + θ × (x − g).
     */
    inline dealii::Tensor<1, 3>
    rigid_motion(const dealii::Tensor<1, 3> &u,
                 const dealii::Tensor<1, 3> &theta,
                 const dealii::Point<3>     &g,
                 const dealii::Point<3>     &x)
    {
      return u + dealii::cross_product_3d(theta, x - g);
    }
  } // namespace rigid_blocks
} // namespace masonry

#endif
