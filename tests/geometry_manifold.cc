// deal.II's OpenCASCADE::NURBSPatchManifold<2,3> built from the face of a
// patch maps the (OCCT) parameters of a unit-square point to the same 3D
// point as Patch::point(), with the same tangents; a mesh refined with the
// manifold has its new vertices on the sphere.

#include <masonry/geometry/patch_occt.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/opencascade/manifold_lib.h>

#include "geometry_common.h"

using namespace masonry;

int
main()
{
  const auto dome   = test::create("dome", "set Span = 10\nset Rise = 5");
  const auto barrel = test::create("barrel vault", "");
  for (const auto *model : {dome.get(), barrel.get()})
    for (const auto &patch : model->patches())
      {
        const dealii::OpenCASCADE::NURBSPatchManifold<2, 3> manifold(
          geometry::face(patch));
        double err = 0, err_t = 0;
        for (unsigned int i = 0; i <= 8; ++i)
          for (unsigned int j = 0; j <= 8; ++j)
            {
              const dealii::Point<2> uv(i / 8., j / 8.);
              const dealii::Point<2> st = geometry::occt_parameters(patch, uv);
              err =
                std::max(err,
                         manifold.push_forward(st).distance(patch.point(uv)));
              // chain rule: d/du = (u1 - u0) d/ds
              const auto  grad = manifold.push_forward_gradient(st);
              const auto  t    = patch.tangents(uv);
              const auto &s    = patch.surface();
              for (unsigned int d = 0; d < 3; ++d)
                err_t =
                  std::max({err_t,
                            std::abs(grad[d][0] * (s.u1 - s.u0) - t[0][d]),
                            std::abs(grad[d][1] * (s.v1 - s.v0) - t[1][d])});
            }
        test::check(err < 1e-12,
                    "NURBSPatchManifold push_forward = Patch::point for '" +
                      patch.name() + "'");
        test::check(err_t < 1e-10,
                    "NURBSPatchManifold gradient = Patch::tangents for '" +
                      patch.name() + "'");
      }

  // a 2D mesh in the parameter plane of the first dome quadrant, mapped by
  // the manifold: refine and check the new vertices lie on the sphere
  {
    const auto                 &patch = dome->patches()[0];
    const auto                 &s     = patch.surface();
    dealii::Triangulation<2, 3> tria;
    const dealii::Point<2>      a = geometry::occt_parameters(patch, {0, 0});
    const dealii::Point<2>      b = geometry::occt_parameters(patch, {0.9, 1});
    dealii::Triangulation<2, 2> flat;
    dealii::GridGenerator::hyper_rectangle(flat, a, b);
    std::vector<dealii::Point<3>>    vertices;
    std::vector<dealii::CellData<2>> cells(1);
    for (unsigned int v = 0; v < 4; ++v)
      {
        const dealii::Point<2> p = flat.begin_active()->vertex(v);
        const dealii::Point<2> uv((p[0] - s.u0) / (s.u1 - s.u0),
                                  (p[1] - s.v0) / (s.v1 - s.v0));
        vertices.push_back(patch.point(uv));
        cells[0].vertices[v] = v;
      }
    tria.create_triangulation(vertices, cells, dealii::SubCellData());
    tria.set_all_manifold_ids(1);
    tria.set_manifold(
      1, dealii::OpenCASCADE::NURBSPatchManifold<2, 3>(geometry::face(patch)));
    tria.refine_global(3);
    double err = 0;
    for (const auto &v : tria.get_vertices())
      err = std::max(err, std::abs(v.norm() - 5));
    test::check(err < 1e-9,
                "mesh refined with the manifold: vertices on the sphere "
                "(1e-9, the manifold's pull-back tolerance)");
  }
  return test::failures();
}
