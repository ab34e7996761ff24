/**
 * @file
 * Assembly of bricks and joints: the elastic caches, the internal forces
 * and the tangent (the update of the states after a step:
 * state_update.cc).
 */
#include <deal.II/base/quadrature_lib.h>

#include "assembler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "guarded_work_stream.h"
#include "one_thread.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;
      using Clock = std::chrono::steady_clock;

      namespace
      {
        bool
        all_finite(const Vector<double> &v)
        {
          for (const double x : v)
            if (!std::isfinite(x))
              return false;
          return true;
        }

        /** A thread's work space for the brick cells. */
        struct BrickScratch
        {
          Vector<double>                       ue = Vector<double>(24);
          std::array<SymmetricTensor<2, 3>, 8> strain;
        };

        /** A thread's work space for the interfaces. */
        struct JointScratch
        {
          Vector<double> ue = Vector<double>(24);
          std::array<Local3, InterfaceElement::n_points>  jumps, tractions;
          std::array<Local33, InterfaceElement::n_points> tangents;
          std::vector<double>                             damages;
        };

        /** One cell's or interface's force and matrix, summed in order. */
        struct LocalContribution
        {
          /** The item is assembled (owned and not deleted). */
          bool active = false;
          /** The interface's joint face number. */
          unsigned int index = 0;
          /** The elastic matrix used (the law was not evaluated), or
           * nullptr: k holds the tangent. */
          const FullMatrix<double>            *cached = nullptr;
          std::vector<types::global_dof_index> dofs =
            std::vector<types::global_dof_index>(24);
          Vector<double>     f = Vector<double>(24);
          FullMatrix<double> k = FullMatrix<double>(24, 24);
          /** The interface's tangent and states are the initial ones. */
          bool initial = true;
          /** non_finite_bits of the item. */
          unsigned int non_finite = 0;
          /** The factor of a brick cell fading out before its deletion
           * (Specimen::fade): f and the matrix are scaled by it. */
          double fade = 1;
        };
      } // namespace

      std::vector<unsigned int>
      active_faces(const AssemblyParts &parts)
      {
        const auto               &faces = parts.joints.faces;
        std::vector<unsigned int> items;
        items.reserve(faces.size());
        for (unsigned int n = 0; n < faces.size(); ++n)
          if (faces[n].owned && !parts.specimen.face_deleted[n])
            items.push_back(n);
        return items;
      }

      void
      AssemblySettings::declare_parameters(ParameterHandler &prm)
      {
        using Patterns::Integer;
        prm.declare_entry(
          "Assembly threads",
          "1",
          Integer(0),
          "Threads of each MPI rank that evaluate the laws of the cells and "
          "interfaces in an assembly (dimensionless count; 0: the cores "
          "divided among the ranks; the environment variable "
          "DEAL_II_NUM_THREADS caps it). The forces and tangents are summed "
          "in the order of the cells and what comes from deal.II's FEValues "
          "is computed on one thread, so the results are the same bit for "
          "bit with any number of threads. More threads shorten the "
          "assembly, some 40 % of the CPU time of a detailed wallette, on "
          "idle cores; on cores shared with other jobs they cost CPU time "
          "and gain little wall time (doc/notes/wallette-solver-speed.md).");
      }

      void
      AssemblySettings::parse_parameters(ParameterHandler &prm)
      {
        threads = prm.get_integer("Assembly threads");
      }

      std::string
      Assembler::non_finite() const
      {
        static const char *names[] = {"the stresses of the bricks",
                                      "the tractions of the joints",
                                      "the damages of the bricks",
                                      "the damages of the joints"};
        for (unsigned int k = 0; k < 4; ++k)
          if ((non_finite_bits & (1u << k)) != 0)
            return names[k];
        return "";
      }

      void
      Assembler::gather_non_finite()
      {
        // a flag of every rank: the run stops on all of them together
        const unsigned int mine = non_finite_bits;
        const int          ierr = MPI_Allreduce(
          &mine, &non_finite_bits, 1, MPI_UNSIGNED, MPI_BOR, parts.system.comm);
        AssertThrowMPI(ierr);
      }

      Assembler::Assembler(const AssemblyParts &parts,
                           const bool           gauss,
                           const double         spacing)
        : parts(parts)
        , interface_element(gauss)
        , spacing(spacing)
      {}

      void
      Assembler::make_elastic_caches()
      {
        // the values of the serial assemblies before the geometries were
        // kept, whatever `Assembly threads' says (OneThread)
        const OneThread one_thread;
        // the elastic matrix of every cell, one per cell shape: all cells
        // of a linear material, the cells of a nonlinear one while they
        // stay elastic
        const System &system = parts.system;
        // the initial stiffness of each region's law (units, mortar)
        std::vector<SymmetricTensor<4, 3>> Cs;
        for (unsigned int r = 0; r < parts.laws.n_regions(); ++r)
          Cs.push_back(parts.laws.brick_law(r).elastic_stiffness());
        QGauss<3>   quadrature(2);
        FEValues<3> fe_values(system.fe,
                              quadrature,
                              update_gradients | update_JxW_values),
          cell_values(system.fe,
                      quadrature,
                      update_gradients | update_JxW_values);
        matrix_of_cell.assign(system.triangulation.n_active_cells(), nullptr);
        geometry_of_cell.assign(system.triangulation.n_active_cells(), 0);
        geometries.clear();
        for (unsigned int i = 0; i < 24; ++i)
          component[i] = system.fe.system_to_component_index(i).first;
        // the geometries by cell shape, each checked bit for bit
        std::map<std::vector<long>, std::vector<unsigned int>> geometries_of;
        const FEValuesExtractors::Vector                       displacement(0);
        for (const auto &cell : system.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const unsigned int region =
                parts.region_of(cell->active_cell_index());
              const SymmetricTensor<4, 3> &C = Cs[region];
              std::vector<long>            shape{long(region)};
              for (unsigned int v = 1; v < 8; ++v)
                for (unsigned int d = 0; d < 3; ++d)
                  shape.push_back(std::lround(
                    (cell->vertex(v)[d] - cell->vertex(0)[d]) * 1e12));
              // every cell in order, as the assemblies did (deal.II reuses
              // the values of the last cell for one that is a translation
              // of it, to round-off)
              cell_values.reinit(cell);
              CellGeometry geometry;
              for (unsigned int q = 0; q < 8; ++q)
                {
                  geometry.JxW[q] = cell_values.JxW(q);
                  for (unsigned int i = 0; i < 24; ++i)
                    geometry.grad[q][i] =
                      cell_values.shape_grad_component(i, q, component[i]);
                }
              auto &same = geometries_of[shape];
              auto  it =
                std::find_if(same.begin(),
                             same.end(),
                             [&](const unsigned int g) {
                               return std::memcmp(&geometries[g],
                                                  &geometry,
                                                  sizeof(geometry)) == 0;
                             });
              if (it == same.end())
                {
                  same.push_back(geometries.size());
                  geometries.push_back(geometry);
                  it = same.end() - 1;
                }
              geometry_of_cell[cell->active_cell_index()] = *it;
              auto &m = cell_matrices[shape];
              if (m.m() == 0)
                {
                  m.reinit(24, 24);
                  fe_values.reinit(cell);
                  for (unsigned int q = 0; q < quadrature.size(); ++q)
                    for (unsigned int j = 0; j < 24; ++j)
                      {
                        const SymmetricTensor<2, 3> C_eps_j =
                          C * fe_values[displacement].symmetric_gradient(j, q);
                        for (unsigned int i = 0; i < 24; ++i)
                          m(i, j) +=
                            scalar_product(
                              fe_values[displacement].symmetric_gradient(i, q),
                              C_eps_j) *
                            fe_values.JxW(q);
                      }
                }
              matrix_of_cell[cell->active_cell_index()] = &m;
            }

        // the elastic matrix of every interface this rank assembles, one
        // per (normal axis, area): used while the interface stays intact
        // and below the damage onset
        const auto &faces = parts.joints.faces;
        matrix_of_interface.assign(faces.size(), nullptr);
        std::array<Local3, 4>  no_traction{};
        std::array<Local33, 4> elastic;
        Vector<double>         f(24);
        for (unsigned int n = 0; n < faces.size(); ++n)
          if (faces[n].owned)
            {
              const auto &face = faces[n];
              // by the face's law (its slot) and normal axis
              const unsigned int key =
                3 * parts.laws.slot_of_type(face.type) + face.axis;
              auto &m = interface_matrices[std::make_pair(
                key, std::lround(face.area * 1e12))];
              if (m.m() == 0)
                {
                  elastic.fill(parts.law_of(n).elastic_tangent());
                  m.reinit(24, 24);
                  interface_element.local(
                    face.axis, face.area, no_traction, elastic, f, &m);
                }
              matrix_of_interface[n] = &m;
            }
      }

      void
      Assembler::invalidate()
      {
        matrix_valid = brick_matrix_valid = false;
      }

      BrickPoint
      Assembler::brick_point(const unsigned int c, const double time_step) const
      {
        BrickPoint point;
        point.characteristic_length = parts.specimen.cell_length[c];
        point.strength_factor       = parts.specimen.cell_factor[c];
        point.time_step             = time_step;
        return point;
      }

      void
      Assembler::assemble(const bool need_matrix, const double time_step)
      {
        const auto start  = Clock::now();
        System    &system = parts.system;
        system.ghosted    = system.u;
        system.f_int      = 0;
        non_finite_bits   = 0;
        const bool linear_model =
          parts.laws.bricks_linear() && parts.laws.joints_linear();
        const bool with_matrix = need_matrix && !(linear_model && matrix_valid);
        is_initial             = true;
        // elastic bricks and nonlinear joints: the bricks' part of the
        // matrix never changes (until cells are deleted), so it is kept
        // and copied instead of summed cell by cell every iteration
        const bool keep_bricks =
          parts.laws.bricks_linear() && !linear_model && with_matrix;
        bool bricks_assembled = false;
        if (with_matrix)
          {
            if (keep_bricks && brick_matrix_valid)
              {
                system.matrix.copy_from(brick_matrix);
                bricks_assembled = true;
              }
            else
              system.matrix = 0;
            ++statistics.n_matrix_assemblies;
            adder.prepare(system);
          }
        assemble_bricks(with_matrix, bricks_assembled, time_step);
        if (keep_bricks && !bricks_assembled)
          {
            system.matrix.compress(VectorOperation::add);
            brick_matrix.copy_from(system.matrix);
            brick_matrix_valid = true;
          }
        assemble_joints(with_matrix, time_step);
        system.f_int.compress(VectorOperation::add);
        gather_non_finite();
        is_initial = Utilities::MPI::min(int(is_initial), system.comm) == 1;
        if (with_matrix)
          {
            matrix_valid = true;
            system.matrix.compress(VectorOperation::add);
            // DOFs of deleted cells belong to no element: a unit diagonal
            // keeps the matrix regular (their increments are constrained)
            if (!system.orphans.empty())
              {
                const double scale =
                  parts.laws.brick_law(unit_region).youngs_modulus() * spacing;
                for (const auto i : system.orphans)
                  if (system.owned.is_element(i))
                    system.matrix.set(i, i, scale);
                system.matrix.compress(VectorOperation::insert);
              }
          }
        statistics.seconds +=
          std::chrono::duration<double>(Clock::now() - start).count();
      }

      void
      Assembler::assemble_bricks(const bool   with_matrix,
                                 const bool   bricks_assembled,
                                 const double time_step)
      {
        System               &system  = parts.system;
        const bool            linear  = parts.laws.bricks_linear();
        const System::Vector &ghosted = system.ghosted;
        // the cells' laws on the threads, the sums into f_int and the
        // matrix in the order of the cells (results independent of the
        // number of threads)
        const auto worker = [&](const DoFHandler<3>::active_cell_iterator &cell,
                                BrickScratch                              &s,
                                LocalContribution &copy) {
          const unsigned int c = cell->active_cell_index();
          copy.active = cell->is_locally_owned() && !parts.specimen.deleted[c];
          copy.index  = c;
          if (!copy.active)
            return;
          cell->get_dof_indices(copy.dofs);
          for (unsigned int i = 0; i < 24; ++i)
            s.ue[i] = ghosted[copy.dofs[i]];
          bool                elastic  = linear;
          const BrickPoint    point    = brick_point(c, time_step);
          const CellGeometry &geometry = geometries[geometry_of_cell[c]];
          if (!linear)
            {
              cell_strains(geometry, s.ue, s.strain);
              elastic = true;
              for (unsigned int q = 0; q < 8 && elastic; ++q)
                elastic =
                  parts.integrator.brick_is_elastic(parts.brick_law(c),
                                                    s.strain[q],
                                                    parts.brick_states(c),
                                                    8 * c + q,
                                                    point);
            }
          if (elastic)
            {
              // the response cannot differ from the cached elastic one
              copy.cached = matrix_of_cell[c];
              copy.cached->vmult(copy.f, s.ue);
              if (!linear)
                for (unsigned int q = 0; q < 8; ++q)
                  parts.brick_states(c).keep(8 * c + q);
            }
          else
            {
              copy.cached = nullptr;
              brick_cell(
                geometry, s.strain, c, point, with_matrix, copy.f, copy.k);
            }
          // a cell fading out before its deletion
          copy.fade = parts.specimen.fade[c];
          if (copy.fade < 1)
            {
              copy.f *= copy.fade;
              if (!copy.cached && with_matrix)
                copy.k *= copy.fade;
            }
          copy.non_finite = all_finite(copy.f) ? 0u : 1u;
        };
        const auto copier = [&](const LocalContribution &copy) {
          if (!copy.active)
            return;
          non_finite_bits |= copy.non_finite;
          system.f_int.add(copy.dofs, copy.f);
          if (copy.cached)
            {
              if (with_matrix && !bricks_assembled && copy.fade < 1)
                {
                  FullMatrix<double> k(*copy.cached);
                  k *= copy.fade;
                  adder.add(CrsAdder::cell, copy.index, k, copy.dofs);
                }
              else if (with_matrix && !bricks_assembled)
                adder.add(CrsAdder::cell, copy.index, *copy.cached, copy.dofs);
              if (!linear)
                ++statistics.n_elastic_cells;
              return;
            }
          ++statistics.n_material_cells;
          is_initial = false;
          if (with_matrix)
            adder.add(CrsAdder::cell, copy.index, copy.k, copy.dofs);
        };
        run_guarded(system.dof_handler.begin_active(),
                    system.dof_handler.end(),
                    worker,
                    copier,
                    BrickScratch(),
                    LocalContribution());
      }

      void
      Assembler::cell_strains(
        const CellGeometry                   &geometry,
        const Vector<double>                 &ue,
        std::array<SymmetricTensor<2, 3>, 8> &strain) const
      {
        // deal.II's value * symmetrize_single_row(c, g) summed over the
        // shape functions in order, without its zero terms: (c, c) gets
        // u g[c], (c, b) u (g[b] / 2); entries [00, 11, 22, 01, 02, 12]
        static constexpr unsigned int off[3][3] = {{0, 3, 4},
                                                   {3, 1, 5},
                                                   {4, 5, 2}};
        for (unsigned int q = 0; q < 8; ++q)
          {
            double e[6] = {0, 0, 0, 0, 0, 0};
            for (unsigned int i = 0; i < 24; ++i)
              {
                const double        u = ue[i];
                const unsigned int  a = component[i];
                const Tensor<1, 3> &g = geometry.grad[q][i];
                for (unsigned int b = 0; b < 3; ++b)
                  e[off[a][b]] += b == a ? u * g[b] : u * (g[b] / 2);
              }
            strain[q] = SymmetricTensor<2, 3>(e);
          }
      }

      void
      Assembler::brick_cell(const CellGeometry &geometry,
                            const std::array<SymmetricTensor<2, 3>, 8> &strain,
                            const unsigned int                          c,
                            const BrickPoint                           &point,
                            const bool          with_matrix,
                            Vector<double>     &fe_local,
                            FullMatrix<double> &ke)
      {
        SymmetricTensor<2, 3> stress;
        SymmetricTensor<4, 3> C;
        fe_local = 0;
        if (with_matrix)
          ke = 0;
        for (unsigned int q = 0; q < 8; ++q)
          {
            parts.integrator.brick_response(parts.brick_law(c),
                                            strain[q],
                                            parts.brick_states(c),
                                            8 * c + q,
                                            point,
                                            stress,
                                            with_matrix ? &C : nullptr);
            // every shape function has one nonzero component c_i with
            // gradient g_i, so stress : B_i = sigma[c_i] . g_i and
            // B_i : C : B_j = g_i . C[c_i][.][c_j][.] g_j (C has the minor
            // symmetries)
            const double                        JxW  = geometry.JxW[q];
            const std::array<Tensor<1, 3>, 24> &grad = geometry.grad[q];
            for (unsigned int i = 0; i < 24; ++i)
              {
                for (unsigned int b = 0; b < 3; ++b)
                  fe_local[i] += stress[component[i]][b] * grad[i][b] * JxW;
              }
            if (!with_matrix)
              continue;
            double Cf[3][3][3][3];
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                for (unsigned int k = 0; k < 3; ++k)
                  for (unsigned int e = 0; e < 3; ++e)
                    Cf[a][b][k][e] = C[a][b][k][e] * JxW;
            // h[a][b][j] = sum_e C[a][b][c_j][e] g_j[e] JxW, by j last so
            // that the sums below run along the rows of ke (vectorised)
            double h[3][3][24];
            for (unsigned int j = 0; j < 24; ++j)
              {
                const unsigned int cj = component[j];
                for (unsigned int a = 0; a < 3; ++a)
                  for (unsigned int b = 0; b < 3; ++b)
                    h[a][b][j] = Cf[a][b][cj][0] * grad[j][0] +
                                 Cf[a][b][cj][1] * grad[j][1] +
                                 Cf[a][b][cj][2] * grad[j][2];
              }
            for (unsigned int i = 0; i < 24; ++i)
              {
                const double(&hi)[3][24] = h[component[i]];
                const double g0 = grad[i][0], g1 = grad[i][1], g2 = grad[i][2];
                double      *row = &ke(i, 0);
                for (unsigned int j = 0; j < 24; ++j)
                  row[j] += hi[0][j] * g0 + hi[1][j] * g1 + hi[2][j] * g2;
              }
          }
      }

      void
      Assembler::assemble_joints(const bool with_matrix, const double time_step)
      {
        System               &system  = parts.system;
        const auto           &faces   = parts.joints.faces;
        const unsigned int    n_quad  = InterfaceElement::n_points;
        const System::Vector &ghosted = system.ghosted;
        // whether the bricks left the matrix the initial one: only then do
        // the joints' states decide it
        const bool                      bricks_initial = is_initial;
        const std::vector<unsigned int> items          = active_faces(parts);
        const auto                      worker =
          [&](const std::vector<unsigned int>::const_iterator &it,
              JointScratch                                    &s,
              LocalContribution                               &copy) {
            const unsigned int  n      = *it;
            const auto         &face   = faces[n];
            const InterfaceLaw &law    = parts.law_of(n);
            PointStates        &states = parts.states_of(n);
            copy.active                = true;
            copy.index                 = n;
            copy.initial               = true;
            InterfacePoint point;
            point.time_step       = time_step;
            point.strength_factor = parts.specimen.face_factor[n];
            for (unsigned int i = 0; i < 24; ++i)
              s.ue[i] = ghosted[face.dofs[i]];
            interface_element.jumps(face.axis, s.ue, s.jumps);
            bool elastic = true;
            for (unsigned int q = 0; q < n_quad && elastic; ++q)
              elastic = parts.integrator.joint_is_elastic(
                law, s.jumps[q], states, n_quad * n + q, point);
            if (elastic)
              {
                // intact and below the onset: the cached elastic matrix
                // gives the exact response, the law is not evaluated
                copy.cached = matrix_of_interface[n];
                copy.cached->vmult(copy.f, s.ue);
                copy.non_finite = all_finite(copy.f) ? 0u : 2u;
                for (unsigned int q = 0; q < n_quad; ++q)
                  parts.integrator.keep_elastic_joint(states, n_quad * n + q);
                return;
              }
            copy.cached = nullptr;
            for (unsigned int q = 0; q < n_quad; ++q)
              parts.integrator.joint_response(law,
                                              s.jumps[q],
                                              states,
                                              n_quad * n + q,
                                              point,
                                              s.tractions[q],
                                              s.tangents[q]);
            interface_element.local(face.axis,
                                    face.area,
                                    s.tractions,
                                    s.tangents,
                                    copy.f,
                                    with_matrix ? &copy.k : nullptr);
            // the matrix stays the initial one (its factorisation is kept)
            // only while no point is damaged and every tangent is the
            // elastic one: a law without damage (plastic slip) changes the
            // tangent too
            if (bricks_initial)
              for (unsigned int q = 0; q < n_quad; ++q)
                {
                  s.damages.resize(law.damage_names().size());
                  law.damages(parts.integrator.step_state(states,
                                                          n_quad * n + q),
                              s.damages);
                  for (const double d : s.damages)
                    if (d > 0)
                      copy.initial = false;
                  if (s.tangents[q] != law.elastic_tangent())
                    copy.initial = false;
                }
            copy.non_finite = all_finite(copy.f) ? 0u : 2u;
          };
        const auto copier = [&](const LocalContribution &copy) {
          const auto &dofs = faces[copy.index].dofs;
          non_finite_bits |= copy.non_finite;
          system.f_int.add(dofs, copy.f);
          if (copy.cached)
            {
              if (with_matrix)
                adder.add(CrsAdder::joint, copy.index, *copy.cached, dofs);
              ++statistics.n_elastic_interfaces;
              return;
            }
          ++statistics.n_law_interfaces;
          if (!copy.initial)
            is_initial = false;
          if (with_matrix)
            adder.add(CrsAdder::joint, copy.index, copy.k, dofs);
        };
        run_guarded(items.cbegin(),
                    items.cend(),
                    worker,
                    copier,
                    JointScratch(),
                    LocalContribution());
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
