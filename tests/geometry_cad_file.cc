// The "cad file" geometry model: write the patches of a barrel vault (scaled
// to millimetres, OpenCASCADE's unit) to STEP and IGES with OCCT's writers,
// read them back through the model (default Scale factor 1e-3) and compare
// points; a file without faces is an error naming the entry.

#include <masonry/geometry/patch_occt.h>

#include <deal.II/opencascade/utilities.h>

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>

#include "geometry_common.h"

using namespace masonry;

int
main()
{
  // OCCT's readers and writers report to stdout: keep the output clean
  Message::DefaultMessenger()->RemovePrinters(
    STANDARD_TYPE(Message_PrinterOStream));
  const auto vault = test::create("barrel vault",
                                  "set Shape = pointed\nset Span = 6.1\n"
                                  "set Rise = 3.8\nset Length = 4");
  // compound of the faces, in millimetres
  BRep_Builder    builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const auto &p : vault->patches())
    {
      Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(
        geometry::bspline_surface(p)->Copy());
      gp_Trsf to_mm;
      to_mm.SetScale(gp_Pnt(0, 0, 0), 1000);
      s->Transform(to_mm);
      builder.Add(compound,
                  geometry::face(geometry::make_patch(s, p.name(), {})));
    }
  dealii::OpenCASCADE::write_STEP(compound, "vault.step");
  dealii::OpenCASCADE::write_IGES(compound, "vault.igs");

  for (const std::string file : {"vault.step", "vault.igs"})
    {
      const auto model = test::create("cad file", "set File name = " + file);
      test::check(model->patches().size() == 2, file + ": two faces read");
      // each original patch must be matched by a read patch, point by point
      // (the parametrisation may be reversed or swapped: compare sets of
      // points via the nearest sampled point of the read patch)
      double err = 0;
      for (const auto &original : vault->patches())
        {
          double best = 1e30;
          for (const auto &read : model->patches())
            {
              double worst = 0;
              for (unsigned int i = 0; i <= 6; ++i)
                for (unsigned int j = 0; j <= 6; ++j)
                  {
                    const auto x = original.point({i / 6., j / 6.});
                    double     d = 1e30;
                    for (const double u : {i / 6., 1 - i / 6.})
                      for (const double v : {j / 6., 1 - j / 6.})
                        d = std::min({d,
                                      read.point({u, v}).distance(x),
                                      read.point({v, u}).distance(x)});
                    worst = std::max(worst, d);
                  }
              best = std::min(best, worst);
            }
          err = std::max(err, best);
        }
      test::check(err < 1e-9,
                  file + ": read patches reproduce the vault (1e-9 m)");
      // springings detected, normals to the extrados (outwards/up)
      unsigned int n_springing = 0;
      bool         up          = true;
      for (const auto &p : model->patches())
        {
          for (const auto &l : p.edge_labels())
            n_springing += (l == "springing");
          const auto x = p.point({0.5, 0.5});
          const auto n = p.normal({0.5, 0.5});
          up           = up && n[2] > 0 && n[0] * x[0] > 0;
        }
      test::check(n_springing == 2, file + ": two edges labelled springing");
      test::check(up, file + ": normals point to the extrados");
      std::cout << "  labels of " << model->patches()[0].name() << ":";
      for (const auto &l : model->patches()[0].edge_labels())
        std::cout << " '" << l << "'";
      std::cout << std::endl;
    }

  // a file with a vertex only: no face
  dealii::OpenCASCADE::write_STEP(
    BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 0)).Vertex(), "point.step");
  const std::string message = test::error_of(
    [&]() { test::create("cad file", "set File name = point.step"); });
  test::check(message.find("'Geometry model/Cad file/File name'") !=
                  std::string::npos &&
                message.find("no face") != std::string::npos,
              "a file without faces is an error naming File name",
              message);
  return test::failures();
}
