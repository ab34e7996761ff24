#include <masonry/geometry/patch_occt.h>

#include <deal.II/base/exceptions.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <cmath>

namespace masonry
{
  namespace geometry
  {
    namespace
    {
      dealii::Tensor<1, 3>
      to_tensor(const gp_Vec &v)
      {
        dealii::Tensor<1, 3> t;
        t[0] = v.X();
        t[1] = v.Y();
        t[2] = v.Z();
        return t;
      }
    } // namespace

    Patch::Patch(std::shared_ptr<const PatchSurface> surface,
                 const std::string                  &name,
                 const std::array<std::string, 4>   &edge_labels,
                 const double                        orientation)
      : surface_data(std::move(surface))
      , patch_name(name)
      , labels(edge_labels)
      , sign(orientation < 0 ? -1. : 1.)
    {
      AssertThrow(surface_data && !surface_data->bspline.IsNull(),
                  dealii::ExcMessage("Patch '" + name + "' has no surface."));
    }

    dealii::Point<3>
    Patch::point(const dealii::Point<2> &uv) const
    {
      const dealii::Point<2> p = occt_parameters(*this, uv);
      const gp_Pnt           x = surface_data->bspline->Value(p[0], p[1]);
      return dealii::Point<3>(x.X(), x.Y(), x.Z());
    }

    std::array<dealii::Tensor<1, 3>, 2>
    Patch::tangents(const dealii::Point<2> &uv) const
    {
      const dealii::Point<2> p = occt_parameters(*this, uv);
      gp_Pnt                 x;
      gp_Vec                 du, dv;
      surface_data->bspline->D1(p[0], p[1], x, du, dv);
      return {{to_tensor(du) * (surface_data->u1 - surface_data->u0),
               to_tensor(dv) * (surface_data->v1 - surface_data->v0)}};
    }

    double
    Patch::jacobian(const dealii::Point<2> &uv) const
    {
      const auto t = tangents(uv);
      return dealii::cross_product_3d(t[0], t[1]).norm();
    }

    dealii::Tensor<1, 3>
    Patch::normal(const dealii::Point<2> &uv) const
    {
      // step towards the centre of the parameter square at a degenerate point
      const dealii::Point<2> centre(0.5, 0.5);
      double                 shift = 0;
      for (unsigned int attempt = 0; attempt < 8; ++attempt)
        {
          const dealii::Point<2> q = uv + shift * (centre - uv);
          const auto             t = tangents(q);
          const auto             n = dealii::cross_product_3d(t[0], t[1]);
          if (n.norm() > 1e-10 * (t[0].norm_square() + t[1].norm_square()) &&
              n.norm() > 0)
            return sign * n / n.norm();
          shift = (shift == 0 ? 1e-9 : shift * 10);
        }
      AssertThrow(false,
                  dealii::ExcMessage("The normal of patch '" + patch_name +
                                     "' is undefined near (" +
                                     std::to_string(uv[0]) + ", " +
                                     std::to_string(uv[1]) + ")."));
      return {};
    }

    std::string
    Patch::name() const
    {
      return patch_name;
    }

    std::array<std::string, 4>
    Patch::edge_labels() const
    {
      return labels;
    }

    int
    Patch::edge_index(const std::string &label) const
    {
      for (unsigned int e = 0; e < 4; ++e)
        if (labels[e] == label)
          return static_cast<int>(e);
      return -1;
    }

    double
    Patch::orientation() const
    {
      return sign;
    }

    const PatchSurface &
    Patch::surface() const
    {
      return *surface_data;
    }

    Patch
    make_patch(const Handle(Geom_BSplineSurface) & surface,
               const std::string                &name,
               const std::array<std::string, 4> &edge_labels,
               const NormalOrientation           orientation)
    {
      auto data     = std::make_shared<PatchSurface>();
      data->bspline = surface;
      surface->Bounds(data->u0, data->u1, data->v0, data->v1);
      double sign = 1;
      if (orientation == NormalOrientation::reversed)
        sign = -1;
      else if (orientation == NormalOrientation::away_from_curvature_centre)
        {
          const double u = 0.5 * (data->u0 + data->u1);
          const double v = 0.5 * (data->v0 + data->v1);
          gp_Pnt       x;
          gp_Vec       su, sv, suu, svv, suv;
          surface->D2(u, v, x, su, sv, suu, svv, suv);
          const gp_Vec n_raw = su.Crossed(sv);
          AssertThrow(n_raw.Magnitude() > 0,
                      dealii::ExcMessage("Patch '" + name +
                                         "' is degenerate at its centre."));
          const gp_Vec n = n_raw / n_raw.Magnitude();
          const double E = su.Dot(su), F = su.Dot(sv), G = sv.Dot(sv);
          const double L = suu.Dot(n), M = suv.Dot(n), N = svv.Dot(n);
          const double H = (L * G - 2 * M * F + N * E) / (2 * (E * G - F * F));
          const double size = std::sqrt(E) + std::sqrt(G);
          if (std::abs(H) * size > 1e-9)
            sign = (H > 0 ? -1. : 1.);
          else
            sign = (n.Z() < 0 ? -1. : 1.);
        }
      return Patch(data, name, edge_labels, sign);
    }

    Handle(Geom_BSplineSurface) bspline_surface(const Patch &patch)
    {
      return patch.surface().bspline;
    }

    TopoDS_Face
    face(const Patch &patch)
    {
      const PatchSurface     &s = patch.surface();
      BRepBuilderAPI_MakeFace maker(s.bspline, s.u0, s.u1, s.v0, s.v1, 1e-9);
      AssertThrow(maker.IsDone(),
                  dealii::ExcMessage("Cannot make a face of patch '" +
                                     patch.name() + "'."));
      return maker.Face();
    }

    dealii::Point<2>
    occt_parameters(const Patch &patch, const dealii::Point<2> &uv)
    {
      const PatchSurface &s = patch.surface();
      return dealii::Point<2>(s.u0 + uv[0] * (s.u1 - s.u0),
                              s.v0 + uv[1] * (s.v1 - s.v0));
    }

    std::array<WeightedPoint2D, 3>
    circular_arc(const double cx,
                 const double cz,
                 const double radius,
                 const double a0,
                 const double a1)
    {
      const double half = 0.5 * (a1 - a0);
      AssertThrow(std::abs(half) < 0.5 * M_PI - 1e-12,
                  dealii::ExcMessage(
                    "circular_arc: the sweep must be less than 180 degrees."));
      const double am = 0.5 * (a0 + a1);
      const double w  = std::cos(half);
      const double rm = radius / w;
      return {{{cx + radius * std::cos(a0), cz + radius * std::sin(a0), 1.},
               {cx + rm * std::cos(am), cz + rm * std::sin(am), w},
               {cx + radius * std::cos(a1), cz + radius * std::sin(a1), 1.}}};
    }

    Handle(Geom_BSplineSurface) make_bspline_surface(
      const std::vector<std::vector<dealii::Point<3>>> &points,
      const std::vector<std::vector<double>>           &weights,
      const unsigned int                                p,
      const unsigned int                                q,
      const std::vector<double>                        &u_knots,
      const unsigned int                                u_interior_multiplicity,
      const std::vector<double>                        &v_knots,
      const unsigned int                                v_interior_multiplicity)
    {
      const int            nu = points.size(), nv = points[0].size();
      TColgp_Array2OfPnt   poles(1, nu, 1, nv);
      TColStd_Array2OfReal w(1, nu, 1, nv);
      for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
          {
            const auto &x = points[i][j];
            poles.SetValue(i + 1, j + 1, gp_Pnt(x[0], x[1], x[2]));
            w.SetValue(i + 1, j + 1, weights[i][j]);
          }
      auto knots = [](const std::vector<double> &k,
                      const unsigned int         degree,
                      const unsigned int         interior,
                      TColStd_Array1OfReal      &values,
                      TColStd_Array1OfInteger   &mults) {
        for (unsigned int i = 0; i < k.size(); ++i)
          {
            values.SetValue(i + 1, k[i]);
            mults.SetValue(i + 1,
                           (i == 0 || i + 1 == k.size()) ? degree + 1 :
                                                           interior);
          }
      };
      TColStd_Array1OfReal    uk(1, u_knots.size()), vk(1, v_knots.size());
      TColStd_Array1OfInteger um(1, u_knots.size()), vm(1, v_knots.size());
      knots(u_knots, p, u_interior_multiplicity, uk, um);
      knots(v_knots, q, v_interior_multiplicity, vk, vm);
      return new Geom_BSplineSurface(poles, w, uk, vk, um, vm, p, q);
    }
  } // namespace geometry
} // namespace masonry
