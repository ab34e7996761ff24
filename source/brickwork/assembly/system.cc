/**
 * @file
 * DoFs, platen conditions, sparsity, vectors.
 */
#include <masonry/core/parameters.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include "system.h"

#include <cmath>
#include <map>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      void
      PlatenSettings::declare_parameters(ParameterHandler &prm)
      {
        using Patterns::Double;
        using Patterns::Selection;
        prm.declare_entry(
          "Platen lateral restraint",
          "fixed",
          Selection("fixed|free"),
          "`fixed': the platens hold the top and bottom faces in all "
          "directions (full friction); `free': they only act along z "
          "(frictionless; rigid motions in the plane are removed by "
          "pinning two points of the bottom face).");
        declare_ranged_list(
          prm,
          "Platen direction",
          "0, 0, -1",
          {-1000, 1000, "(dimensionless)"},
          3,
          ",",
          "Direction of the top platen's motion (x, y, z; normalised): "
          "`0, 0, -1' compresses the wallette, `0, 0, 1' pulls it, `1, 0, "
          "0' shears it (needs fixed platens). Stresses and strains are "
          "reported along this direction.");
        declare_ranged_entry(prm,
                             "Gauge length",
                             "0",
                             {0, 100, "m"},
                             "Length of a virtual displacement transducer "
                             "(LVDT) on the front face (y = 0) at mid-length, "
                             "centred at mid-height, m (>= 0; its ends snap "
                             "to the nearest mesh points, the length used is "
                             "reported as gauge_length). Its strain along the "
                             "platen direction is written as gauge_strain in "
                             "curve.csv, with gauge_strain_at_peak and "
                             "initial_modulus_gauge in summary.json; 0: no "
                             "gauge (strain over the whole height only).");
      }

      void
      PlatenSettings::parse_parameters(ParameterHandler &prm)
      {
        lateral_fixed = prm.get("Platen lateral restraint") == "fixed";
        const auto dir =
          split_doubles(prm.get("Platen direction"), "Platen direction");
        const double norm =
          std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        AssertThrow(norm > 0,
                    ExcParameter("Platen direction", "must not be zero"));
        for (unsigned int d = 0; d < 3; ++d)
          direction[d] = dir[d] / norm;
        AssertThrow(lateral_fixed || (dir[0] == 0 && dir[1] == 0),
                    ExcParameter("Platen direction",
                                 "a sideways motion needs `Platen lateral "
                                 "restraint = fixed'"));
        gauge_length = prm.get_double("Gauge length");
      }

      System::System(const parallel::shared::Triangulation<3> &tria,
                     MPI_Comm                                  comm)
        : comm(comm)
        , triangulation(tria)
        , fe(FE_Q<3>(1), 3)
        , dof_handler(tria)
      {}

      void
      System::distribute_dofs()
      {
        dof_handler.distribute_dofs(fe);
        owned    = dof_handler.locally_owned_dofs();
        relevant = complete_index_set(dof_handler.n_dofs());
      }

      namespace
      {
        /** The mesh vertices nearest to the ends of a gauge of @p length on
         * the front face at mid-length, centred at mid-height. */
        void
        find_gauge(const DoFHandler<3> &dof_handler,
                   const Geometry      &g,
                   const double         length,
                   std::array<std::array<types::global_dof_index, 3>, 2> &dofs,
                   double                                                &span)
        {
          const double   tol     = 1e-9 * g.height;
          const Point<3> ends[2] = {
            Point<3>(g.length / 2, 0, (g.height - length) / 2),
            Point<3>(g.length / 2, 0, (g.height + length) / 2)};
          double   best[2] = {1e300, 1e300};
          Point<3> where[2];
          for (const auto &cell : dof_handler.active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              if (std::abs(cell->vertex(v)[1]) < tol)
                for (unsigned int e = 0; e < 2; ++e)
                  if (cell->vertex(v).distance(ends[e]) < best[e] - tol)
                    {
                      best[e]  = cell->vertex(v).distance(ends[e]);
                      where[e] = cell->vertex(v);
                      for (unsigned int d = 0; d < 3; ++d)
                        dofs[e][d] = cell->vertex_dof_index(v, d);
                    }
          span = where[1][2] - where[0][2];
          AssertThrow(span > 0,
                      ExcMessage("the gauge length is shorter than an "
                                 "element: no two mesh points along it"));
        }
      } // namespace

      void
      System::setup(const Joints         &joints,
                    const Geometry       &g,
                    const PlatenSettings &platen,
                    const bool            gauss,
                    const Protocol       &held_by)
      {
        protocol  = &held_by;
        direction = platen.direction;
        // Dirichlet conditions of the platens; increments are zero there
        const double tol = 1e-9 * g.height;
        const bool   vertical =
          std::abs(direction[0]) < 1e-12 && std::abs(direction[1]) < 1e-12;
        AssertThrow(platen.lateral_fixed || vertical,
                    ExcMessage("the platens must be laterally fixed "
                               "('Platen lateral restraint = fixed') when "
                               "the platen moves sideways"));
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() && f / 2 == 2)
              {
                const double z = cell->face(f)->center()[2];
                if (std::abs(z) > tol && std::abs(z - g.height) > tol)
                  continue;
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    const Point<3> p = cell->face(f)->vertex(v);
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        const auto i = cell->face(f)->vertex_dof_index(v, d);
                        // the top platen is the protocol's
                        if (std::abs(z - g.height) < tol)
                          {
                            top_dofs.emplace_back(i, d);
                            continue;
                          }
                        bool fix = platen.lateral_fixed || d == 2;
                        // free platens: pin the rigid motions in the plane
                        if (!fix && std::abs(p[1]) < tol &&
                            (std::abs(p[0]) < tol ||
                             (d == 1 && std::abs(p[0] - g.length) < tol)))
                          fix = true;
                        if (fix)
                          platen_lines.push_back(i);
                      }
                  }
              }
        std::sort(platen_lines.begin(), platen_lines.end());
        platen_lines.erase(std::unique(platen_lines.begin(),
                                       platen_lines.end()),
                           platen_lines.end());
        // remove duplicates of the top DOFs (shared vertices within a brick)
        std::sort(top_dofs.begin(), top_dofs.end());
        top_dofs.erase(std::unique(top_dofs.begin(), top_dofs.end()),
                       top_dofs.end());
        // the top platen's nodes (by their x DoF), held by the protocol
        std::map<std::array<types::global_dof_index, 3>, Point<3>> top_nodes;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (std::abs(cell->vertex(v)[2] - g.height) < tol)
              top_nodes[{{cell->vertex_dof_index(v, 0),
                          cell->vertex_dof_index(v, 1),
                          cell->vertex_dof_index(v, 2)}}] = cell->vertex(v);
        top.direction     = direction;
        top.lateral_fixed = platen.lateral_fixed;
        top.centre        = Point<3>(g.length / 2, g.thickness / 2, g.height);
        for (const auto &[dof, position] : top_nodes)
          {
            top.positions.push_back(position);
            top.dofs.push_back(dof);
          }
        top_constraints.clear();
        top_constraints.reinit(relevant);
        protocol->hold_platen(top, top_constraints);
        top_constraints.close();
        make_constraints();

        if (platen.gauge_length > 0)
          find_gauge(
            dof_handler, g, platen.gauge_length, gauge_dofs, gauge_span);

        DynamicSparsityPattern dsp(relevant);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        zero_constraints,
                                        false,
                                        Utilities::MPI::this_mpi_process(comm));
        // a joint's tangent at Lobatto points (the nodes) couples each
        // node only with the node facing it: its other entries between
        // the sides are zeros (shape values 0 exactly), which the
        // assemblies leave out, and which would only add fill to the
        // factorisation (single cyclic example: 28 % fewer flops,
        // contrib/benchmarks/wallette_cyclic/results-2026-11-25d.md); the
        // couplings within a side are the cell's
        std::vector<types::global_dof_index> pair(6);
        for (const auto &face : joints.faces)
          if (face.owned && gauss)
            zero_constraints.add_entries_local_to_global(face.dofs, dsp, false);
          else if (face.owned)
            for (unsigned int v = 0; v < 4; ++v)
              {
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    pair[d]     = face.dofs[3 * v + d];
                    pair[3 + d] = face.dofs[12 + 3 * v + d];
                  }
                zero_constraints.add_entries_local_to_global(pair, dsp, false);
              }
        SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
        matrix.reinit(owned, owned, dsp, comm);

        u.reinit(owned, comm);
        last_increment.reinit(owned, comm);
        f_int.reinit(owned, comm);
        ghosted.reinit(owned, relevant, comm);
      }

      void
      System::make_constraints()
      {
        zero_constraints.clear();
        zero_constraints.reinit(relevant);
        for (const auto i : platen_lines)
          zero_constraints.add_line(i);
        only_fixed = true;
        for (const auto &line : top_constraints.get_lines())
          if (!zero_constraints.is_constrained(line.index))
            {
              zero_constraints.add_line(line.index);
              zero_constraints.add_entries(line.index, line.entries);
              only_fixed = only_fixed && line.entries.empty();
            }
        for (const auto i : orphans)
          if (!zero_constraints.is_constrained(i))
            zero_constraints.add_line(i);
        zero_constraints.close();
      }

      void
      System::condense(Vector &r) const
      {
        if (only_fixed)
          zero_constraints.set_zero(r);
        else
          zero_constraints.condense(r);
      }

      void
      System::distribute(Vector &du) const
      {
        if (only_fixed)
          zero_constraints.set_zero(du);
        else
          zero_constraints.distribute(du);
      }

      void
      System::set_platen(Vector &v, const double disp) const
      {
        protocol->move_platen(top, disp, top_constraints, v);
      }

      double
      System::reaction() const
      {
        double r = 0;
        for (const auto &td : top_dofs)
          if (owned.is_element(td.first))
            r += f_int[td.first] * direction[td.second];
        return Utilities::MPI::sum(r, comm);
      }

      double
      System::gauge_strain()
      {
        if (gauge_span <= 0)
          return 0;
        ghosted_solution();
        double e = 0;
        for (unsigned int d = 0; d < 3; ++d)
          e += (ghosted[gauge_dofs[1][d]] - ghosted[gauge_dofs[0][d]]) *
               direction[d] / gauge_span;
        return e;
      }

      const System::Vector &
      System::ghosted_solution()
      {
        ghosted = u;
        return ghosted;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
