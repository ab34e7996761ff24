/**
 * @file
 * Assembly of bricks and joints.
 */
#include <deal.II/base/quadrature_lib.h>

#include "assembler.h"

#include <chrono>
#include <cmath>
#include <limits>

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
      } // namespace

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
        // the elastic matrix of every cell, one per cell shape: all cells
        // of a linear material, the cells of a nonlinear one while they
        // stay elastic
        const System &system = parts.system;
        // the initial stiffness of each region (units, mortar)
        BrickPoint unit_point, mortar_point;
        mortar_point.region               = 1;
        const SymmetricTensor<4, 3> Cs[2] = {
          parts.material.elastic_stiffness_at(unit_point),
          parts.material.elastic_stiffness_at(mortar_point)};
        QGauss<3>   quadrature(2);
        FEValues<3> fe_values(system.fe,
                              quadrature,
                              update_gradients | update_JxW_values);
        matrix_of_cell.assign(system.triangulation.n_active_cells(), nullptr);
        const FEValuesExtractors::Vector displacement(0);
        for (const auto &cell : system.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const unsigned int region =
                parts.specimen.cell_region[cell->active_cell_index()];
              const SymmetricTensor<4, 3> &C = Cs[region];
              std::vector<long>            shape{long(region)};
              for (unsigned int v = 1; v < 8; ++v)
                for (unsigned int d = 0; d < 3; ++d)
                  shape.push_back(std::lround(
                    (cell->vertex(v)[d] - cell->vertex(0)[d]) * 1e12));
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
              // the splitting interfaces (axis 0 or 1) have their own law
              const unsigned int key =
                face.type == splitting_type ? 3 + face.axis : face.axis;
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
        point.region                = parts.specimen.cell_region[c];
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
          parts.material.is_linear() && parts.law.is_linear() &&
          (!parts.splitting_law || parts.splitting_law->is_linear());
        const bool with_matrix = need_matrix && !(linear_model && matrix_valid);
        is_initial             = true;
        // elastic bricks and nonlinear joints: the bricks' part of the
        // matrix never changes (until cells are deleted), so it is kept
        // and copied instead of summed cell by cell every iteration
        const bool keep_bricks =
          parts.material.is_linear() && !linear_model && with_matrix;
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
                const double scale = parts.material.youngs_modulus() * spacing;
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
        System                              &system   = parts.system;
        const BrickMaterial                 &material = parts.material;
        const bool                           linear   = material.is_linear();
        std::vector<types::global_dof_index> dofs(24);
        Vector<double>                       ue(24), fe_local(24);
        FullMatrix<double>                   ke(24, 24);
        QGauss<3>                            quadrature(2);
        FEValues<3>                          fe_values(system.fe,
                              quadrature,
                              update_gradients | update_JxW_values);
        const FEValuesExtractors::Vector     displacement(0);
        std::array<SymmetricTensor<2, 3>, 8> strain;
        for (const auto &cell : system.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() &&
              !parts.specimen.deleted[cell->active_cell_index()])
            {
              const unsigned int c = cell->active_cell_index();
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < 24; ++i)
                ue[i] = system.ghosted[dofs[i]];
              bool             elastic = linear;
              const BrickPoint point   = brick_point(c, time_step);
              if (!linear)
                {
                  fe_values.reinit(cell);
                  elastic = true;
                  for (unsigned int q = 0; q < 8; ++q)
                    {
                      strain[q] = 0;
                      for (unsigned int i = 0; i < 24; ++i)
                        strain[q] +=
                          ue[i] *
                          fe_values[displacement].symmetric_gradient(i, q);
                      if (elastic &&
                          !parts.integrator.brick_is_elastic(material,
                                                             strain[q],
                                                             parts.bricks,
                                                             8 * c + q,
                                                             point))
                        elastic = false;
                    }
                }
              // a cell fading out before its deletion
              const double fade = parts.specimen.fade[c];
              if (elastic)
                {
                  // the response cannot differ from the cached elastic one
                  const FullMatrix<double> &k = *matrix_of_cell[c];
                  k.vmult(fe_local, ue);
                  if (fade < 1)
                    fe_local *= fade;
                  if (!all_finite(fe_local))
                    non_finite_bits |= 1u;
                  system.f_int.add(dofs, fe_local);
                  if (with_matrix && !bricks_assembled && fade < 1)
                    {
                      ke = k;
                      ke *= fade;
                      system.zero_constraints.distribute_local_to_global(
                        ke, dofs, system.matrix);
                    }
                  else if (with_matrix && !bricks_assembled)
                    system.zero_constraints.distribute_local_to_global(
                      k, dofs, system.matrix);
                  if (!linear)
                    {
                      for (unsigned int q = 0; q < 8; ++q)
                        parts.bricks.keep(8 * c + q);
                      ++statistics.n_elastic_cells;
                    }
                  continue;
                }
              ++statistics.n_material_cells;
              is_initial = false;
              brick_cell(
                fe_values, strain, c, point, with_matrix, fe_local, ke);
              if (fade < 1)
                {
                  fe_local *= fade;
                  if (with_matrix)
                    ke *= fade;
                }
              if (!all_finite(fe_local))
                non_finite_bits |= 1u;
              system.f_int.add(dofs, fe_local);
              if (with_matrix)
                system.zero_constraints.distribute_local_to_global(
                  ke, dofs, system.matrix);
            }
      }

      void
      Assembler::brick_cell(const FEValues<3> &fe_values,
                            const std::array<SymmetricTensor<2, 3>, 8> &strain,
                            const unsigned int                          c,
                            const BrickPoint                           &point,
                            const bool          with_matrix,
                            Vector<double>     &fe_local,
                            FullMatrix<double> &ke)
      {
        std::array<Tensor<1, 3>, 24> grad;
        std::array<unsigned int, 24> component;
        for (unsigned int i = 0; i < 24; ++i)
          component[i] = parts.system.fe.system_to_component_index(i).first;
        SymmetricTensor<2, 3> stress;
        SymmetricTensor<4, 3> C;
        fe_local = 0;
        if (with_matrix)
          ke = 0;
        for (unsigned int q = 0; q < 8; ++q)
          {
            parts.integrator.brick_response(parts.material,
                                            strain[q],
                                            parts.bricks,
                                            8 * c + q,
                                            point,
                                            stress,
                                            with_matrix ? &C : nullptr);
            // every shape function has one nonzero component c_i with
            // gradient g_i, so stress : B_i = sigma[c_i] . g_i and
            // B_i : C : B_j = g_i . C[c_i][.][c_j][.] g_j (C has the minor
            // symmetries)
            const double JxW = fe_values.JxW(q);
            for (unsigned int i = 0; i < 24; ++i)
              {
                grad[i] = fe_values.shape_grad_component(i, q, component[i]);
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
            for (unsigned int j = 0; j < 24; ++j)
              {
                // h[a][b] = sum_e C[a][b][c_j][e] g_j[e] JxW
                double             h[3][3];
                const unsigned int cj = component[j];
                for (unsigned int a = 0; a < 3; ++a)
                  for (unsigned int b = 0; b < 3; ++b)
                    h[a][b] = Cf[a][b][cj][0] * grad[j][0] +
                              Cf[a][b][cj][1] * grad[j][1] +
                              Cf[a][b][cj][2] * grad[j][2];
                for (unsigned int i = 0; i < 24; ++i)
                  {
                    const double *hi = h[component[i]];
                    ke(i, j) += hi[0] * grad[i][0] + hi[1] * grad[i][1] +
                                hi[2] * grad[i][2];
                  }
              }
          }
      }

      void
      Assembler::assemble_joints(const bool with_matrix, const double time_step)
      {
        System            &system = parts.system;
        const auto        &faces  = parts.joints.faces;
        const unsigned int n_quad = InterfaceElement::n_points;
        FullMatrix<double> ki(24, 24);
        Vector<double>     fi(24), ue(24);
        InterfacePoint     point;
        point.time_step = time_step;
        std::array<Local3, 4>  jumps, tractions;
        std::array<Local33, 4> tangents;
        std::vector<double>    damages;
        for (unsigned int n = 0; n < faces.size(); ++n)
          {
            const auto &face = faces[n];
            if (!face.owned || parts.specimen.face_deleted[n])
              continue;
            const InterfaceLaw &law    = parts.law_of(n);
            PointStates        &states = parts.states_of(n);
            point.strength_factor      = parts.specimen.face_factor[n];
            for (unsigned int i = 0; i < 24; ++i)
              ue[i] = system.ghosted[face.dofs[i]];
            interface_element.jumps(face.axis, ue, jumps);
            bool elastic = true;
            for (unsigned int q = 0; q < n_quad && elastic; ++q)
              elastic = parts.integrator.joint_is_elastic(
                law, jumps[q], states, n_quad * n + q, point);
            if (elastic)
              {
                // intact and below the onset: the cached elastic matrix
                // gives the exact response, the law is not evaluated
                const FullMatrix<double> &k = *matrix_of_interface[n];
                k.vmult(fi, ue);
                if (!all_finite(fi))
                  non_finite_bits |= 2u;
                system.f_int.add(face.dofs, fi);
                if (with_matrix)
                  system.zero_constraints.distribute_local_to_global(
                    k, face.dofs, system.matrix);
                for (unsigned int q = 0; q < n_quad; ++q)
                  parts.integrator.keep_elastic_joint(states, n_quad * n + q);
                ++statistics.n_elastic_interfaces;
                continue;
              }
            ++statistics.n_law_interfaces;
            for (unsigned int q = 0; q < n_quad; ++q)
              parts.integrator.joint_response(law,
                                              jumps[q],
                                              states,
                                              n_quad * n + q,
                                              point,
                                              tractions[q],
                                              tangents[q]);
            interface_element.local(face.axis,
                                    face.area,
                                    tractions,
                                    tangents,
                                    fi,
                                    with_matrix ? &ki : nullptr);
            // the matrix stays the initial one (its factorisation is kept)
            // only while no point is damaged and every tangent is the
            // elastic one: a law without damage (plastic slip) changes the
            // tangent too
            if (is_initial)
              for (unsigned int q = 0; q < n_quad; ++q)
                {
                  damages.resize(law.damage_names().size());
                  law.damages(parts.integrator.step_state(states,
                                                          n_quad * n + q),
                              damages);
                  for (const double d : damages)
                    if (d > 0)
                      is_initial = false;
                  if (tangents[q] != law.elastic_tangent())
                    is_initial = false;
                }
            if (!all_finite(fi))
              non_finite_bits |= 2u;
            system.f_int.add(face.dofs, fi);
            if (with_matrix)
              system.zero_constraints.distribute_local_to_global(ki,
                                                                 face.dofs,
                                                                 system.matrix);
          }
      }

      double
      Assembler::update_states(const Integrator &integrator,
                               const double      time_step)
      {
        System &system  = parts.system;
        system.ghosted  = system.u;
        double error    = 0;
        non_finite_bits = 0;
        // the largest change of a damage against its extrapolation (a
        // non-finite one is flagged: std::max would drop a NaN)
        const auto damage_error = [&](const unsigned int   flag,
                                      const auto          &law,
                                      const PointStates   &states,
                                      const unsigned int   p,
                                      std::vector<double> &d,
                                      std::vector<double> &d_old,
                                      std::vector<double> &d_older) {
          law.damages(states.updated(p), d);
          law.damages(states.old(p), d_old);
          law.damages(states.older(p), d_older);
          for (unsigned int k = 0; k < d.size(); ++k)
            {
              const double e =
                std::abs(d[k] - integrator.extrapolated(d_old[k], d_older[k]));
              if (!std::isfinite(e))
                non_finite_bits |= 1u << flag;
              else
                error = std::max(error, e);
            }
        };
        const BrickMaterial &material = parts.material;
        if (!material.is_linear())
          {
            QGauss<3>   quadrature(2);
            FEValues<3> fe_values(system.fe, quadrature, update_gradients);
            std::vector<SymmetricTensor<2, 3>> eps(8);
            const FEValuesExtractors::Vector   displacement(0);
            SymmetricTensor<2, 3>              stress;
            const unsigned int  n_damages = material.damage_names().size();
            std::vector<double> d(n_damages), d_old(n_damages),
              d_older(n_damages);
            for (const auto &cell : system.dof_handler.active_cell_iterators())
              if (cell->is_locally_owned() &&
                  !parts.specimen.deleted[cell->active_cell_index()])
                {
                  const unsigned int c = cell->active_cell_index();
                  fe_values.reinit(cell);
                  fe_values[displacement].get_function_symmetric_gradients(
                    system.ghosted, eps);
                  const BrickPoint point = brick_point(c, time_step);
                  for (unsigned int q = 0; q < 8; ++q)
                    {
                      const unsigned int p = 8 * c + q;
                      material.update_state(eps[q],
                                            parts.bricks.old(p),
                                            point,
                                            parts.bricks.updated(p),
                                            stress);
                      damage_error(
                        2, material, parts.bricks, p, d, d_old, d_older);
                    }
                }
          }
        InterfacePoint point;
        point.time_step = time_step;
        Local3                t;
        Local33               D;
        Vector<double>        ue(24);
        std::array<Local3, 4> jumps;
        const auto           &faces = parts.joints.faces;
        for (unsigned int n = 0; n < faces.size(); ++n)
          {
            const auto &face = faces[n];
            if (!face.owned || parts.specimen.face_deleted[n])
              continue;
            const InterfaceLaw &law       = parts.law_of(n);
            PointStates        &states    = parts.states_of(n);
            const unsigned int  n_damages = law.damage_names().size();
            std::vector<double> d(n_damages), d_old(n_damages),
              d_older(n_damages);
            point.strength_factor = parts.specimen.face_factor[n];
            for (unsigned int i = 0; i < 24; ++i)
              ue[i] = system.ghosted[face.dofs[i]];
            interface_element.jumps(face.axis, ue, jumps);
            for (unsigned int q = 0; q < 4; ++q)
              {
                const unsigned int p = 4 * n + q;
                law.evaluate(
                  jumps[q], states.old(p), point, states.updated(p), t, D);
                damage_error(3, law, states, p, d, d_old, d_older);
              }
          }
        gather_non_finite();
        if (!non_finite().empty())
          return std::numeric_limits<double>::quiet_NaN();
        return Utilities::MPI::max(error, system.comm);
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
