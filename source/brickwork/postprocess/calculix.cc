/**
 * @file
 * The CalculiX export: the mesh as C3D8 elements, the elastic brick
 * material, the platen conditions and the final platen displacement as one
 * linear static step (calculix.inp), and this run's final displacements in
 * the same node numbering (nodal_displacements.csv).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/brickwork/protocol.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fstream>
#include <iomanip>

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      using namespace dealii;

      namespace
      {
        /** calculix.inp and nodal_displacements.csv at the end. */
        class CalculiX : public Postprocessor
        {
        public:
          static void
          declare_parameters(dealii::ParameterHandler &)
          {}

          void
          finish(const ModelView &view, Json &) override;
        };

        void
        CalculiX::finish(const ModelView &view, Json &)
        {
          const Platen                       &platen  = view.top_platen();
          const TrilinosWrappers::MPI::Vector ghosted = view.solution();
          const auto &triangulation                   = view.triangulation();
          // the nodes used by the cells, numbered from 1 in vertex order
          const auto               &all = triangulation.get_vertices();
          std::vector<unsigned int> node(all.size(), 0);
          std::vector<std::array<types::global_dof_index, 3>> dofs(all.size());
          for (const auto &cell : view.dof_handler().active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              {
                node[cell->vertex_index(v)] = 1;
                for (unsigned int d = 0; d < 3; ++d)
                  dofs[cell->vertex_index(v)][d] = cell->vertex_dof_index(v, d);
              }
          unsigned int n = 0;
          for (auto &i : node)
            if (i)
              i = ++n;
          const std::string inp = view.context.output.file("calculix.inp");
          const std::string csv =
            view.context.output.file("nodal_displacements.csv");
          if (!view.is_root())
            return;
          const double height = view.height();
          const double tol    = 1e-9 * height;
          const auto  &dir    = platen.direction;
          const double target = view.protocol.target_displacement();
          const bool   fixed  = platen.lateral_fixed;
          OutputFile   out(inp);
          // CalculiX reads fields of at most 20 characters
          out << std::setprecision(15);
          out << "** masonry wallette: " << triangulation.n_active_cells()
              << " C3D8 elements, bottom fixed, top moved by " << target
              << " m along (" << dir[0] << ", " << dir[1] << ", " << dir[2]
              << ")\n*NODE, NSET=NALL\n";
          for (unsigned int v = 0; v < all.size(); ++v)
            if (node[v])
              out << node[v] << ", " << all[v][0] << ", " << all[v][1] << ", "
                  << all[v][2] << "\n";
          out << "*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
          const unsigned int order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
          unsigned int       e        = 0;
          for (const auto &cell : triangulation.active_cell_iterators())
            {
              out << ++e;
              for (const unsigned int v : order)
                out << ", " << node[cell->vertex_index(v)];
              out << "\n";
            }
          for (const bool top : {false, true})
            {
              out << "*NSET, NSET=" << (top ? "TOP" : "BOTTOM") << "\n";
              unsigned int k = 0;
              for (unsigned int v = 0; v < all.size(); ++v)
                if (node[v] && std::abs(all[v][2] - (top ? height : 0.)) < tol)
                  out << node[v] << (++k % 8 == 0 ? ",\n" : ", ");
              out << "\n";
            }
          out << "*MATERIAL, NAME=BRICK\n*ELASTIC\n"
              << view.laws.brick_law(unit_region).youngs_modulus() << ", "
              << view.laws.brick_law(unit_region).poissons_ratio()
              << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=BRICK\n"
              << "*STEP\n*STATIC\n*BOUNDARY\n";
          for (unsigned int d = 0; d < 3; ++d)
            if (fixed || d == 2)
              out << "BOTTOM, " << d + 1 << ", " << d + 1 << "\n";
          for (unsigned int d = 0; d < 3; ++d)
            if (fixed || d == 2)
              out << "TOP, " << d + 1 << ", " << d + 1 << ", "
                  << std::scientific << std::setprecision(12) << target * dir[d]
                  << std::defaultfloat << std::setprecision(15) << "\n";
          out << "*NODE PRINT, NSET=NALL\nU\n*NODE PRINT, NSET=TOP, "
                 "TOTALS=ONLY\nRF\n*END STEP\n";
          out.close();
          OutputFile d(csv);
          d << std::setprecision(17) << "node,x,y,z,u_x,u_y,u_z\n";
          for (unsigned int v = 0; v < all.size(); ++v)
            if (node[v])
              d << node[v] << "," << all[v][0] << "," << all[v][1] << ","
                << all[v][2] << "," << ghosted[dofs[v][0]] << ","
                << ghosted[dofs[v][1]] << "," << ghosted[dofs[v][2]] << "\n";
          d.close();
        }
      } // namespace

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  masonry::brickwork::postprocess::CalculiX,
  "calculix",
  "calculix.inp (the mesh as C3D8 elements, the elastic brick material, the platen conditions and the final platen displacement as one linear static step, for `ccx -i calculix') and nodal_displacements.csv (this run's final displacements, m, in the same node numbering). Needs `Joints = bonded', an elastic brick material and the monotonic protocol.")
