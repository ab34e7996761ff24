/**
 * @file
 * The OpenCASCADE side of geometry::Patch: the definition of PatchSurface,
 * access to the `Handle(Geom_BSplineSurface)`, construction of patches and
 * of exact rational arcs. Include only where OCCT is needed.
 */
#ifndef masonry_geometry_patch_occt_h
#define masonry_geometry_patch_occt_h

#include <masonry/geometry/patch.h>

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>

#include <vector>

namespace masonry
{
  namespace geometry
  {
    /** The OCCT data of a Patch. */
    struct PatchSurface
    {
      /** The B-spline (NURBS) surface. */
      Handle(Geom_BSplineSurface) bspline;
      /** Its parameter bounds: u in [u0,u1], v in [v0,v1]. */
      double u0, u1, v0, v1;
    };

    /**
     * How make_patch() chooses the sign of the normal.
     */
    enum class NormalOrientation
    {
      /** The extrados normal is d/du x d/dv of the OCCT surface. */
      as_parametrised,
      /** The extrados normal is -(d/du x d/dv). */
      reversed,
      /**
       * Away from the centre of curvature: the sign for which the mean
       * curvature, evaluated at the centre (0.5,0.5) of the patch, is
       * negative (the surface bends away from the normal, as a vault seen
       * from above). If the patch is flat there (|H| < 1e-9 / diameter),
       * the normal with non-negative z-component is chosen.
       */
      away_from_curvature_centre
    };

    /**
     * Make a patch from a B-spline surface over its whole parameter range.
     */
    Patch
    make_patch(const Handle(Geom_BSplineSurface) & surface,
               const std::string                &name,
               const std::array<std::string, 4> &edge_labels,
               const NormalOrientation           orientation =
                 NormalOrientation::away_from_curvature_centre);

    /** The B-spline surface of @p patch (shared, do not modify it). */
    Handle(Geom_BSplineSurface) bspline_surface(const Patch &patch);

    /**
     * A face bounded by the whole parameter range of the surface of
     * @p patch, e.g. for dealii::OpenCASCADE::NURBSPatchManifold (whose
     * chart uses the OCCT parameters, see occt_parameters()).
     */
    TopoDS_Face
    face(const Patch &patch);

    /** The OCCT parameters of the unit-square parameters @p uv. */
    dealii::Point<2>
    occt_parameters(const Patch &patch, const dealii::Point<2> &uv);

    /**
     * A weighted control point (x, z, weight) of a rational curve in the
     * vertical plane.
     */
    struct WeightedPoint2D
    {
      /** Horizontal coordinate (m). */
      double x;
      /** Vertical coordinate (m). */
      double z;
      /** Weight. */
      double w;
    };

    /**
     * The exact rational quadratic Bezier segment of the circular arc with
     * centre (@p cx, @p cz) and radius @p radius from the point at angle
     * @p a0 to the point at angle @p a1 (radians, |a1-a0| < pi): three
     * control points, the middle one at the intersection of the end
     * tangents with weight cos((a1-a0)/2).
     */
    std::array<WeightedPoint2D, 3>
    circular_arc(const double cx,
                 const double cz,
                 const double radius,
                 const double a0,
                 const double a1);

    /**
     * A rational B-spline surface of degree (p, q) with the given control
     * points (index [i][j], i along u) and weights, on clamped knot vectors
     * built from the distinct knots @p u_knots (with multiplicity p+1 at the
     * ends and @p u_interior_multiplicity inside) and likewise in v.
     */
    Handle(Geom_BSplineSurface) make_bspline_surface(
      const std::vector<std::vector<dealii::Point<3>>> &points,
      const std::vector<std::vector<double>>           &weights,
      const unsigned int                                p,
      const unsigned int                                q,
      const std::vector<double>                        &u_knots,
      const unsigned int                                u_interior_multiplicity,
      const std::vector<double>                        &v_knots,
      const unsigned int v_interior_multiplicity);
  } // namespace geometry
} // namespace masonry

#endif
