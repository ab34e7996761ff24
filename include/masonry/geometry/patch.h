/**
 * @file
 * One exact NURBS patch of the middle surface of a vault.
 *
 * This header does not include OpenCASCADE: the surface is held through an
 * opaque pointer. Code that needs the OCCT surface (for instance to build a
 * dealii::OpenCASCADE::NURBSPatchManifold) includes
 * masonry/geometry/patch_occt.h.
 */
#ifndef masonry_geometry_patch_h
#define masonry_geometry_patch_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <memory>
#include <string>

namespace masonry
{
  /** Geometry of vaults: exact NURBS patches of their middle surface. */
  namespace geometry
  {
    /**
     * The OCCT data of a patch (a `Handle(Geom_BSplineSurface)` and its
     * parameter bounds). Opaque here; defined in
     * masonry/geometry/patch_occt.h.
     */
    struct PatchSurface;

    /**
     * One NURBS patch of the middle surface of a vault: an OpenCASCADE
     * `Geom_BSplineSurface` (rational where needed, so that circular arcs,
     * cylinders and spheres are exact), reparametrised over the unit square:
     * the parameters (u, v) in [0,1]^2 are mapped linearly onto the knot
     * range [U1,U2] x [V1,V2] of the surface.
     *
     * Orientation: normal() is the unit normal pointing towards the
     * EXTRADOS, so that at a point x of the middle surface with thickness t
     * the intrados is x - t/2 n and the extrados x + t/2 n. The sign is fixed
     * once, when the patch is made (see make_patch() in patch_occt.h).
     *
     * Copies are cheap: they share the (immutable) surface.
     */
    class Patch
    {
    public:
      /**
       * Make a patch from OCCT data @p surface; @p orientation is +1 if the
       * extrados normal is d/du x d/dv, -1 if it is the opposite. Normally
       * called through geometry::make_patch() (patch_occt.h).
       */
      Patch(std::shared_ptr<const PatchSurface> surface,
            const std::string                  &name,
            const std::array<std::string, 4>   &edge_labels,
            const double                        orientation);

      /** The point of the middle surface at the parameters @p uv in [0,1]^2. */
      dealii::Point<3>
      point(const dealii::Point<2> &uv) const;

      /**
       * The tangent vectors {dx/du, dx/dv} at @p uv, derivatives with
       * respect to the unit-square parameters (in m per unit parameter).
       * At a degenerate edge (pole of a dome, corner of a cross-vault web)
       * one of them may vanish.
       */
      std::array<dealii::Tensor<1, 3>, 2>
      tangents(const dealii::Point<2> &uv) const;

      /**
       * The unit normal at @p uv, oriented towards the extrados. At a
       * degenerate point, where dx/du x dx/dv vanishes, the normal is the
       * limit taken from inside the patch (evaluated at parameters moved
       * towards the centre of the parameter square by up to 1e-6).
       */
      dealii::Tensor<1, 3>
      normal(const dealii::Point<2> &uv) const;

      /**
       * |dx/du x dx/dv| at @p uv: the area element of the middle surface
       * with respect to the unit-square parameters (m^2).
       */
      double
      jacobian(const dealii::Point<2> &uv) const;

      /** The name of the patch (e.g. "west half", "quadrant north-east"). */
      std::string
      name() const;

      /**
       * The labels of the edges u=0, u=1, v=0, v=1, in this order. They are
       * documented by each geometry model and are used by parameter files to
       * select supports.
       */
      std::array<std::string, 4>
      edge_labels() const;

      /**
       * The index (0..3, in the order of edge_labels()) of the first edge
       * labelled @p label, or -1 if there is none.
       */
      int
      edge_index(const std::string &label) const;

      /** +1 if normal() is along dx/du x dx/dv, -1 if opposite. */
      double
      orientation() const;

      /**
       * The OCCT data (opaque here; include masonry/geometry/patch_occt.h
       * for its definition and for the `Handle(Geom_BSplineSurface)`).
       */
      const PatchSurface &
      surface() const;

    private:
      /** The surface and its parameter bounds. */
      std::shared_ptr<const PatchSurface> surface_data;
      /** Name of the patch. */
      std::string patch_name;
      /** Labels of the edges u=0, u=1, v=0, v=1. */
      std::array<std::string, 4> labels;
      /** +1 or -1, see orientation(). */
      double sign;
    };
  } // namespace geometry
} // namespace masonry

#endif
