/**
 * @file
 * Mesh of the enlarged bricks: the entries of the mesh, its spacing, the
 * check of the boxes against it, and the hexahedra of the enlarged-brick
 * model (the detailed model of units and meshed mortar:
 * detailed_mesh.cc).
 */
#include <masonry/core/parameters.h>

#include <deal.II/grid/grid_tools.h>

#include "mesh.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    using namespace dealii;

    namespace
    {
      /** Declare the sizes of a unit without mortar and of the joints, m. */
      void
      declare_unit_entries(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        declare_ranged_entry(prm,
                             "Brick length",
                             "0.215",
                             {0, 10, "m"},
                             "Length of a brick without mortar, m (>= 1e-6).");
        declare_ranged_entry(prm,
                             "Brick width",
                             "0.1025",
                             {0, 10, "m"},
                             "Width of a brick without mortar, m (>= 1e-6).");
        declare_ranged_entry(prm,
                             "Brick height",
                             "0.065",
                             {0, 10, "m"},
                             "Height of a brick without mortar, m (>= 1e-6).");
        declare_ranged_entry(
          prm,
          "Joint thickness",
          "0.010",
          {0, 1, "m"},
          "Thickness of the mortar joints, m (>= 0): each "
          "enlarged brick is the brick plus half a joint on "
          "every side. `Model = simplified': the joints "
          "become zero-thickness interfaces; `detailed': the "
          "mortar is meshed as one layer of hexahedra of "
          "this thickness (>= 1e-6 then).");
      }

      /** Declare the model of the mortar (`Model') and the unfilled strips
       * of the bed joints along the collar joints of the detailed model
       * (`Collar bed gap', m). */
      void
      declare_model_entries(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        using dealii::Patterns::Selection;
        prm.declare_entry(
          "Model",
          "simplified",
          Selection("simplified|detailed"),
          "`simplified': enlarged bricks (brick plus half a joint all "
          "round) joined by zero-thickness interfaces that stand for the "
          "mortar (`Interface law', whose penalties then represent the "
          "mortar's stiffness, e.g. Lourenco-Rots from E_b, E_m, nu and "
          "the joint thickness). `detailed': the units at their actual "
          "size (`Brick length/width/height'), the mortar of bed and head "
          "joints (and collar joints) meshed as one layer of hexahedra "
          "`Joint thickness' thick with `subsection Mortar material' (any "
          "brick material), and the zero-thickness interfaces of the "
          "`Interface law' between units and mortar as the bond, whose "
          "penalties should then be stiff contact penalties (the mortar's "
          "compliance is in its cells); the wallette is one joint "
          "thickness shorter, thinner and lower than the enlarged one "
          "(outer faces are unit faces). Cells along the length, width "
          "and height of a unit are about its size / the enlarged mesh "
          "spacing; mortar layers are one cell thick. Not with `Mesh "
          "distortion'.");
        prm.declare_entry(
          "Collar bed gap",
          "0",
          Double(),
          "Width of the unfilled strip of every bed joint on each side of "
          "every collar joint, m (`Model = detailed' only, >= 0; the strips "
          "must stay apart and off the faces, e.g. g < 0.1025 m in a double "
          "and g < 0.05125 m in a triple english wall of 215 mm units): the "
          "bed-joint mortar in the plane of a collar joint, widened by this "
          "on both sides, is a void (no cells; the unit faces above and "
          "below it are free), as where the mortar beds of the wythes are "
          "spread separately and do not meet. A workmanship input, as a "
          "dismantled specimen shows it; no effect on a wall without collar "
          "joints. The plan area of the voids (`bed_void_area', m^2, summed "
          "over the bed joints) is in log.txt and summary.json.");
      }

      /** Declare the size of the wallette in units (courses, length) and
       * the hexahedra per enlarged unit (the mesh spacing). */
      void
      declare_size_entries(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Integer;
        prm.declare_entry("Courses",
                          "5",
                          Integer(1, 1000),
                          "Number of courses (rows of bricks) of the "
                          "wallette.");
        prm.declare_entry("Length in bricks",
                          "2",
                          Integer(1, 1000),
                          "Length of the wallette in (enlarged) brick "
                          "lengths.");
        prm.declare_entry("Elements along the length",
                          "4",
                          Integer(1, 64),
                          "Hexahedra along the length of an enlarged "
                          "stretcher; the mesh spacing (enlarged length / "
                          "this number) is used for every brick, so that the "
                          "meshes of neighbouring bricks match across the "
                          "joints (simplified model: even for the stretcher "
                          "bond, a multiple of 4 for the english bond; the "
                          "detailed model's grid runs through every unit "
                          "face and takes any number).");
        prm.declare_entry("Elements along the width",
                          "2",
                          Integer(1, 64),
                          "Hexahedra across the width of an enlarged "
                          "stretcher (mesh spacing across the wall).");
        prm.declare_entry("Elements along the height",
                          "2",
                          Integer(1, 64),
                          "Hexahedra over the height of an enlarged brick.");
      }

      /** Declare how the joints are modelled (interfaces or bonded) and the
       * splitting interfaces through the units. */
      void
      declare_joint_entries(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Selection;
        prm.declare_entry(
          "Joints",
          "interfaces",
          Selection("interfaces|bonded"),
          "`interfaces': every joint is a zero-thickness interface of the "
          "`Interface law'; `bonded': the bricks share the vertices of "
          "coincident faces, so the wallette is one continuum without "
          "joints (a perfectly bonded reference).");
        prm.declare_entry(
          "Splitting interfaces",
          "false",
          Bool(),
          "Potential vertical splitting cracks: each unit is meshed as two "
          "halves joined by a zero-thickness interface through its middle, "
          "normal to its longer horizontal side (in line with the head "
          "joints of the next course for a stretcher; units whose half is "
          "not a whole number of elements, such as closers, stay whole). "
          "The interface follows `subsection Splitting interface law'; by "
          "default (`from the units') the composite law with the unit's "
          "tensile strength and fracture energy as its tension cut-off, "
          "Coulomb friction through the unit's uniaxial strengths (c = "
          "sqrt(f_c f_t) / 2, tan(phi) = (f_c - f_t) / (2 sqrt(f_c f_t))), "
          "G_II = 10 G_f and no cap (10 f_c); the values used are printed "
          "in log.txt and summary.json (derived_values / "
          "splitting_interfaces). Needs "
          "`Joints = interfaces'.");
      }

      /** Declare the distortion of the hexahedra (patch tests) and the
       * integration points of the interface elements. */
      void
      declare_discretisation_entries(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        using dealii::Patterns::Selection;
        prm.declare_entry(
          "Mesh distortion",
          "0",
          Double(0, 0.2),
          "Amplitude of a smooth distortion of the hexahedra, as a "
          "fraction of the mesh spacing in each direction (dimensionless; "
          "0: the regular mesh). With `Joints = interfaces' the vertices "
          "inside each brick move by a bubble that vanishes on the brick's "
          "faces, so joint faces and the wallette's faces stay unchanged; "
          "with `Joints = bonded' one smooth map moves all vertices and "
          "keeps each face of the wallette in its plane. For patch tests "
          "(uniform compression has the same exact solution).");
        prm.declare_entry("Interface integration",
                          "lobatto",
                          Selection("lobatto|gauss"),
                          "Integration points of the interface elements: "
                          "`lobatto' (2 x 2 points at the nodes, avoids "
                          "traction oscillations at high penalty) or "
                          "`gauss' (2 x 2 Gauss points).");
      }

      /** Declare the filled fractions of the head and collar joints
       * (workmanship of the detailed model, dimensionless). */
      void
      declare_fill_entries(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        for (const char *joint : {"Head", "Collar"})
          prm.declare_entry(
            std::string(joint) + " joint fill",
            "1",
            Double(),
            std::string("Filled fraction of the height of every ") +
              (joint[0] == 'H' ?
                 "head joint (perpend)" :
                 "collar joint (the vertical joint between the wythes of "
                 "the english bond; where a head joint meets it, the "
                 "column counts as collar joint)") +
              ", dimensionless, 0 to 1 (`Model = detailed' only): the "
              "joint is mortar from the bed joint below up to this "
              "fraction of the unit height, the rest, up to the bed joint "
              "above, is a void (no cells; the unit faces there are free). "
              "A workmanship input, as a survey or a dismantled specimen "
              "shows it. The areas of the joints and of their voids and "
              "the fill meshed (the grid line lies at the fraction "
              "exactly) are printed in log.txt and summary.json; 1: full "
              "joints.");
      }
    } // namespace

    void
    MeshSettings::declare_parameters(dealii::ParameterHandler &prm)
    {
      declare_unit_entries(prm);
      declare_model_entries(prm);
      declare_size_entries(prm);
      declare_joint_entries(prm);
      declare_discretisation_entries(prm);
      declare_fill_entries(prm);
    }

    void
    MeshSettings::parse_parameters(dealii::ParameterHandler &prm)
    {
      const double joint = prm.get_double("Joint thickness");
      size.length        = positive_entry(prm, "Brick length") + joint;
      size.width         = positive_entry(prm, "Brick width") + joint;
      size.height        = positive_entry(prm, "Brick height") + joint;
      size.courses       = prm.get_integer("Courses");
      size.bricks_long   = prm.get_integer("Length in bricks");
      n_l                = prm.get_integer("Elements along the length");
      n_w                = prm.get_integer("Elements along the width");
      n_h                = prm.get_integer("Elements along the height");
      gauss              = prm.get("Interface integration") == "gauss";
      bonded             = prm.get("Joints") == "bonded";
      distortion         = prm.get_double("Mesh distortion");
      split_units        = prm.get_bool("Splitting interfaces");
      detailed           = prm.get("Model") == "detailed";
      mortar_thickness   = joint;
      AssertThrow(!detailed || joint > 0,
                  ExcParameter("Joint thickness",
                               "must be positive with `Model = detailed' "
                               "(the mortar layer's thickness)"));
      // sizes too small to mesh (1e-30 m gave units or mortar of no cells)
      for (const std::string e :
           {"Brick length", "Brick width", "Brick height", "Joint thickness"})
        AssertThrow(prm.get_double(e) >= 1e-6 || (e[0] == 'J' && !detailed),
                    ExcParameter(e,
                                 "must be at least 1e-6 m, got " + prm.get(e)));
      for (const char *entry : {"Head joint fill", "Collar joint fill"})
        {
          const double f = prm.get_double(entry);
          AssertThrow(f >= 0 && f <= 1,
                      ExcParameter(entry, "must lie in [0, 1]"));
          AssertThrow(f == 1 || detailed,
                      ExcParameter(entry, "needs `Model = detailed'"));
          (entry[0] == 'H' ? head_joint_fill : collar_joint_fill) = f;
        }
      collar_bed_gap = prm.get_double("Collar bed gap");
      AssertThrow(collar_bed_gap >= 0,
                  ExcParameter("Collar bed gap", "must not be negative"));
      AssertThrow(collar_bed_gap == 0 || detailed,
                  ExcParameter("Collar bed gap", "needs `Model = detailed'"));
      AssertThrow(!detailed || distortion == 0,
                  ExcParameter("Mesh distortion",
                               "is not supported with `Model = detailed'"));
      AssertThrow(!split_units || !bonded,
                  ExcParameter("Splitting interfaces",
                               "needs `Joints = interfaces'"));
    }

    std::array<double, 3>
    mesh_spacing(const MeshSettings &s)
    {
      return {
        {s.size.length / s.n_l, s.size.width / s.n_w, s.size.height / s.n_h}};
    }

    void
    check_mesh(const std::vector<Box> &boxes, const MeshSettings &s)
    {
      static const char *element_entry[3] = {"Elements along the length",
                                             "Elements along the width",
                                             "Elements along the height"};
      const auto         h                = mesh_spacing(s);
      for (const auto &b : boxes)
        for (unsigned int d = 0; d < 3; ++d)
          if (model::divisions(b, d, h[d]) == 0)
            {
              std::ostringstream m;
              m << "a " << b.kind << " of the bond is "
                << b.upper[d] - b.lower[d] << " m long in direction "
                << "xyz"[d] << ", not a whole number of elements of " << h[d]
                << " m (the half bats of the stretcher bond need an even "
                   "number of elements along the length, the headers and "
                   "closers of the english bond a multiple of 4)";
              AssertThrow(false, ExcParameter(element_entry[d], m.str()));
            }
    }

    namespace model
    {
      unsigned int
      divisions(const Box &box, const unsigned int d, const double h)
      {
        const double extent = box.upper[d] - box.lower[d];
        const double n      = std::round(extent / h);
        if (n < 1 || std::abs(n * h - extent) > 1e-9 * extent)
          return 0;
        return static_cast<unsigned int>(n);
      }

      namespace
      {
        /**
         * The distortion of a vertex at @p p (position @p xi in its brick):
         * waves of a few cells' length (so that the cells are not
         * parallelepipeds), times a factor that vanishes on the faces of
         * the brick (interfaces) or of the wallette (bonded).
         */
        Point<3>
        distort(const Point<3> &p,
                const double (&xi)[3],
                const MeshSettings          &settings,
                const std::array<double, 3> &h,
                const double (&extent)[3])
        {
          const double pi = numbers::PI, delta = settings.distortion;
          if (delta == 0)
            return p;
          const double w[3] = {
            std::cos(1.7 * pi * p[2] / h[2] + 0.9 * pi * p[1] / h[1]),
            std::cos(1.3 * pi * p[0] / h[0] + 0.7 * pi * p[2] / h[2]),
            std::cos(1.1 * pi * p[0] / h[0] + 1.9 * pi * p[1] / h[1])};
          // sin(pi t), exactly 0 on the faces
          auto bump = [&](const double t) {
            return t <= 1e-12 || t >= 1 - 1e-12 ? 0. : std::sin(pi * t);
          };
          Point<3> q = p;
          for (unsigned int d = 0; d < 3; ++d)
            {
              const double factor = settings.bonded ?
                                      bump(p[d] / extent[d]) :
                                      bump(xi[0]) * bump(xi[1]) * bump(xi[2]);
              q[d] += delta * h[d] * factor * w[d];
            }
          return q;
        }
      } // namespace

      unsigned int
      split_direction(const Box &box)
      {
        return box.upper[1] - box.lower[1] > box.upper[0] - box.lower[0] ? 1 :
                                                                           0;
      }

      Geometry
      make_mesh(const std::vector<Box> &boxes,
                const MeshSettings     &settings,
                Triangulation<3>       &triangulation)
      {
        const auto               h = mesh_spacing(settings);
        std::vector<Point<3>>    vertices;
        std::vector<CellData<3>> cells;
        Geometry                 g;
        for (const Box &box : boxes)
          {
            g.height    = std::max(g.height, box.upper[2]);
            g.length    = std::max(g.length, box.upper[0]);
            g.thickness = std::max(g.thickness, box.upper[1]);
          }
        const double extent[3] = {g.length, g.thickness, g.height};
        // the blocks of cells: one per brick, or its two halves when the
        // unit is split (same material id: the faces between them are the
        // splitting interface)
        std::vector<std::pair<Box, unsigned int>> blocks;
        for (unsigned int b = 0; b < boxes.size(); ++b)
          {
            const Box         &box = boxes[b];
            const unsigned int d   = split_direction(box);
            const unsigned int n   = divisions(box, d, h[d]);
            if (settings.split_units && !settings.bonded && n >= 2 &&
                n % 2 == 0)
              {
                Box          first = box, second = box;
                const double middle = 0.5 * (box.lower[d] + box.upper[d]);
                first.upper[d]      = middle;
                second.lower[d]     = middle;
                blocks.emplace_back(first, b);
                blocks.emplace_back(second, b);
                ++g.n_split_units;
              }
            else
              blocks.emplace_back(box, b);
          }
        for (const auto &[box, b] : blocks)
          {
            unsigned int n[3];
            for (unsigned int d = 0; d < 3; ++d)
              {
                n[d] = divisions(box, d, h[d]);
                Assert(n[d] > 0, ExcInternalError());
              }
            const unsigned int first = vertices.size();
            for (unsigned int k = 0; k <= n[2]; ++k)
              for (unsigned int j = 0; j <= n[1]; ++j)
                for (unsigned int i = 0; i <= n[0]; ++i)
                  {
                    const double xi[3] = {double(i) / n[0],
                                          double(j) / n[1],
                                          double(k) / n[2]};
                    vertices.push_back(distort(
                      Point<3>(
                        box.lower[0] + (box.upper[0] - box.lower[0]) * xi[0],
                        box.lower[1] + (box.upper[1] - box.lower[1]) * xi[1],
                        box.lower[2] + (box.upper[2] - box.lower[2]) * xi[2]),
                      xi,
                      settings,
                      h,
                      extent));
                  }
            auto index = [&](unsigned int i, unsigned int j, unsigned int k) {
              return first + i + (n[0] + 1) * (j + (n[1] + 1) * k);
            };
            for (unsigned int k = 0; k < n[2]; ++k)
              for (unsigned int j = 0; j < n[1]; ++j)
                for (unsigned int i = 0; i < n[0]; ++i)
                  {
                    CellData<3> c;
                    for (unsigned int v = 0; v < 8; ++v)
                      c.vertices[v] =
                        index(i + v % 2, j + (v / 2) % 2, k + v / 4);
                    c.material_id = b;
                    cells.push_back(c);
                  }
          }
        g.n_bricks   = boxes.size();
        g.gross_area = g.length * g.thickness;
        if (settings.bonded)
          {
            SubCellData               sub;
            std::vector<unsigned int> considered;
            GridTools::delete_duplicated_vertices(
              vertices, cells, sub, considered, 1e-9 * g.height);
          }
        triangulation.create_triangulation(vertices, cells, SubCellData());
        return g;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
