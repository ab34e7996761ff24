#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch_occt.h>

#include <deal.II/opencascade/utilities.h>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <limits>

namespace masonry
{
  namespace geometry
  {
    /**
     * The middle surface read from an IGES or STEP file.
     *
     * Every face of the file becomes one patch, named "face 1", "face 2",
     * ... in the order of OCCT's face explorer. Faces that are not B-spline
     * surfaces are converted (BRepBuilderAPI_NurbsConvert, exact for
     * planes, cylinders, cones, spheres, tori and surfaces of revolution).
     * The patch is the underlying surface restricted to the rectangle of
     * the face's parameter bounds: trimming curves of non-rectangular faces
     * are IGNORED (model every face as a four-sided patch).
     *
     * Normals are oriented away from the centre of curvature (see
     * NormalOrientation::away_from_curvature_centre), z-up on flat faces;
     * the orientation of the face in the file is not used.
     *
     * Edge labels (u=0, u=1, v=0, v=1): "springing" for an edge that lies
     * at the lowest z of the whole model (within 1e-6 times the size of
     * the model, checked at 9 points along the edge), "degenerate" for an
     * edge collapsed to a point, otherwise "edge u=0", "edge u=1",
     * "edge v=0", "edge v=1".
     */
    class CadFile : public Interface
    {
    public:
      /** Declare `File name`, `Scale factor`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("File name",
                          "",
                          dealii::Patterns::FileName(),
                          "IGES (.igs, .iges) or STEP (.stp, .step) file "
                          "holding the middle surface of the vault, z up; "
                          "a relative name is relative to the working "
                          "directory.");
        prm.declare_entry("Scale factor",
                          "1e-3",
                          dealii::Patterns::Double(0),
                          "Factor (> 0) applied to the coordinates read: "
                          "OpenCASCADE converts the file to millimetres, so "
                          "the default 1e-3 gives metres.");
      }

      /** Read the file and build one patch per face. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        const std::string file_name = prm.get("File name");
        const double      scale     = prm.get_double("Scale factor");
        AssertThrow(scale > 0,
                    ExcParameter("Scale factor", "must be positive."));
        AssertThrow(!file_name.empty(),
                    ExcParameter("File name", "no file given."));
        AssertThrow(std::ifstream(file_name).good(),
                    ExcParameter("File name",
                                 "cannot read '" + file_name +
                                   "': no such file or not readable."));
        std::string extension = file_name.substr(file_name.rfind('.') + 1);
        std::transform(extension.begin(),
                       extension.end(),
                       extension.begin(),
                       [](unsigned char ch) { return std::tolower(ch); });
        const bool iges = (extension == "igs" || extension == "iges");
        const bool step = (extension == "stp" || extension == "step");
        AssertThrow(iges || step,
                    ExcParameter("File name",
                                 "cannot read '" + file_name +
                                   "': the extension must be .igs, .iges, "
                                   ".stp or .step."));

        std::vector<Patch> list;
        try
          {
            TopoDS_Shape shape =
              iges ? dealii::OpenCASCADE::read_IGES(file_name, scale) :
                     dealii::OpenCASCADE::read_STEP(file_name, scale);
            BRepBuilderAPI_NurbsConvert convert(shape);
            shape = convert.Shape();
            std::vector<Handle(Geom_BSplineSurface)> surfaces;
            for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
              {
                const TopoDS_Face f    = TopoDS::Face(e.Current());
                Handle(Geom_Surface) s = BRep_Tool::Surface(f);
                double u0, u1, v0, v1;
                BRepTools::UVBounds(f, u0, u1, v0, v1);
                Handle(Geom_BSplineSurface) b =
                  Handle(Geom_BSplineSurface)::DownCast(s);
                if (b.IsNull())
                  b = GeomConvert::SurfaceToBSplineSurface(
                    new Geom_RectangularTrimmedSurface(s, u0, u1, v0, v1));
                else
                  {
                    b = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
                    double bu0, bu1, bv0, bv1;
                    b->Bounds(bu0, bu1, bv0, bv1);
                    const double tol =
                      1e-9 * (1 + std::abs(bu1 - bu0) + std::abs(bv1 - bv0));
                    if (u0 > bu0 + tol || u1 < bu1 - tol || v0 > bv0 + tol ||
                        v1 < bv1 - tol)
                      b->Segment(u0, u1, v0, v1);
                  }
                surfaces.push_back(b);
              }
            for (unsigned int i = 0; i < surfaces.size(); ++i)
              list.push_back(
                make_patch(surfaces[i],
                           "face " + std::to_string(i + 1),
                           {{"edge u=0", "edge u=1", "edge v=0", "edge v=1"}}));
          }
        catch (const Standard_Failure &failure)
          {
            AssertThrow(false,
                        ExcParameter("File name",
                                     "cannot read '" + file_name +
                                       "': OpenCASCADE error " +
                                       failure.GetMessageString()));
          }
        catch (const std::exception &)
          {
            AssertThrow(false,
                        ExcParameter("File name",
                                     "cannot read '" + file_name + "' as " +
                                       (iges ? "IGES" : "STEP") + "."));
          }
        AssertThrow(!list.empty(),
                    ExcParameter("File name",
                                 "'" + file_name +
                                   "' contains no face (surface); the "
                                   "middle surface of the vault must be "
                                   "given as faces."));
        set_patches(label_edges(list));
      }

    private:
      /** Replace the generic labels by "springing" and "degenerate". */
      static std::vector<Patch>
      label_edges(const std::vector<Patch> &list)
      {
        auto edge_point = [](unsigned int e, double s) {
          return e < 2 ? dealii::Point<2>(e, s) : dealii::Point<2>(s, e - 2);
        };
        double           z_min = std::numeric_limits<double>::max();
        dealii::Point<3> lo, hi;
        bool             first = true;
        for (const auto &p : list)
          for (unsigned int e = 0; e < 4; ++e)
            for (unsigned int k = 0; k <= 8; ++k)
              {
                const auto x = p.point(edge_point(e, k / 8.));
                z_min        = std::min(z_min, x[2]);
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    lo[d] = first ? x[d] : std::min(lo[d], x[d]);
                    hi[d] = first ? x[d] : std::max(hi[d], x[d]);
                  }
                first = false;
              }
        const double       tol = 1e-6 * (hi - lo).norm();
        std::vector<Patch> result;
        for (const auto &p : list)
          {
            auto labels = p.edge_labels();
            for (unsigned int e = 0; e < 4; ++e)
              {
                bool       at_bottom = true, collapsed = true;
                const auto x0 = p.point(edge_point(e, 0));
                for (unsigned int k = 0; k <= 8; ++k)
                  {
                    const auto x = p.point(edge_point(e, k / 8.));
                    at_bottom    = at_bottom && (x[2] - z_min <= tol);
                    collapsed    = collapsed && (x.distance(x0) <= tol);
                  }
                if (collapsed)
                  labels[e] = "degenerate";
                else if (at_bottom)
                  labels[e] = "springing";
              }
            result.push_back(make_patch(bspline_surface(p),
                                        p.name(),
                                        labels,
                                        p.orientation() > 0 ?
                                          NormalOrientation::as_parametrised :
                                          NormalOrientation::reversed));
          }
        return result;
      }
    };
  } // namespace geometry
} // namespace masonry

MASONRY_REGISTER_GEOMETRY_MODEL(
  masonry::geometry::CadFile,
  "cad file",
  "The middle surface read from an IGES or STEP file (File name, chosen by "
  "the extension .igs/.iges or .stp/.step; coordinates times Scale factor, "
  "default 1e-3 from OpenCASCADE's millimetres to metres; z up). Every "
  "face becomes one patch `face 1', `face 2', ... (converted to a B-spline "
  "surface where needed; trimming curves are ignored, the patch is the "
  "face's parameter rectangle). Edge labels: `springing' for edges at the "
  "lowest z of the model, `degenerate' for collapsed edges, otherwise "
  "`edge u=0', `edge u=1', `edge v=0', `edge v=1'.")
