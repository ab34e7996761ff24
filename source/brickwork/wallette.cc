/**
 * @file
 * The wallette model: generator, interface detection, assembly of bricks and
 * zero-thickness interfaces, Newton-Raphson with line search and adaptive
 * steps, results (CSV, PNG, VTU/PVTU/PVD, summary.json).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/wallette.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_out.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <random>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    using namespace dealii;

    std::array<double, 3>
    mesh_spacing(const WalletteSettings &s)
    {
      return {
        {s.size.length / s.n_l, s.size.width / s.n_w, s.size.height / s.n_h}};
    }

    namespace
    {
      const char *element_entry[3] = {"Elements along the length",
                                      "Elements along the width",
                                      "Elements along the height"};

      /** Cells of @p box along direction @p d; 0 if not a whole number. */
      unsigned int
      divisions(const Box &box, const unsigned int d, const double h)
      {
        const double extent = box.upper[d] - box.lower[d];
        const double n      = std::round(extent / h);
        if (n < 1 || std::abs(n * h - extent) > 1e-9 * extent)
          return 0;
        return static_cast<unsigned int>(n);
      }
    } // namespace

    void
    check_mesh(const std::vector<Box> &boxes, const WalletteSettings &s)
    {
      const auto h = mesh_spacing(s);
      for (const auto &b : boxes)
        for (unsigned int d = 0; d < 3; ++d)
          if (divisions(b, d, h[d]) == 0)
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

    namespace
    {
      using Clock = std::chrono::steady_clock;

      /** A joint between two bricks: a pair of coincident cell faces. */
      struct InterfaceFace
      {
        /** 0 bed (normal z), 1 head (normal x), 2 collar (normal y). */
        unsigned int type;
        /** Axis of the normal (from side A, lower coordinate, to B). */
        unsigned int axis;
        /** Whether this rank assembles it (owner of side A). */
        bool owned;
        /** Degrees of freedom: A vertices 0-3 then B, 3 components each. */
        std::vector<types::global_dof_index> dofs;
        /** Vertices of side A (face-lexicographic order). */
        std::array<Point<3>, 4> vertices;
        double                  area;
        /** Bricks on both sides. */
        unsigned int brick_a, brick_b;
        /** Active cell indices on both sides. */
        unsigned int cell_a, cell_b;
      };

      /** Summary of one converged step. */
      struct CurvePoint
      {
        double       displacement, strain, force, stress, max_damage;
        double       gauge_strain;
        unsigned int newton;
        /** Cycle (from 1; 0 for the initial state) and whether the platen
         * was unloading. */
        unsigned int cycle     = 0;
        bool         unloading = false;
        /** Cells deleted so far; largest brick damages (tension,
         * compression). */
        unsigned int deleted        = 0;
        double       brick_damage_t = 0, brick_damage_c = 0;

        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &displacement &strain &force &stress &max_damage &gauge_strain
            &newton &cycle &unloading &deleted &brick_damage_t &brick_damage_c;
        }
      };

      /** A leg of the displacement protocol. */
      struct Segment
      {
        /** Platen displacement to reach (loading) or the lowest allowed
         * (unloading), m along the direction. */
        double       target;
        bool         unloading;
        unsigned int cycle;
      };

      /** Results of one load-unload cycle. */
      struct Cycle
      {
        unsigned int cycle     = 0;
        double       amplitude = 0, peak_stress = 0, strain_at_peak = 0;
        double       residual_strain = 0, unloading_modulus = 0;
        double       dissipated_energy = 0;
        /** Curve indices: start of loading, turning point, end. */
        unsigned int first = 0, turn = 0, last = 0;
      };

      const char *type_name[3] = {"bed", "head", "collar"};

      /** The whole model, for one run. */
      class Model
      {
      public:
        Model(const std::vector<Box> &boxes,
              const BrickMaterial    &material,
              const InterfaceLaw     &law,
              const WalletteSettings &settings,
              RunContext             &context)
          : boxes(boxes)
          , material(material)
          , law(law)
          , settings(settings)
          , context(context)
          , comm(context.mpi_communicator)
          , pcout(context.pcout)
          , triangulation(comm,
                          Triangulation<3>::none,
                          false,
                          parallel::shared::Triangulation<3>::partition_metis)
          , fe(FE_Q<3>(1), 3)
          , dof_handler(triangulation)
        {}

        void
        run();

      private:
        void
        make_mesh();
        void
        find_interfaces();
        void
        setup_system();
        /** Internal forces; the tangent matrix when @p need_matrix (a
         * linear model keeps the one it assembled first). */
        void
        assemble(const bool need_matrix);
        /** Openings (local frame) at the interface points of @p face
         * from its 24 DOF values @p ue. */
        void
        interface_jumps(const InterfaceFace   &face,
                        const Vector<double>  &ue,
                        std::array<Local3, 4> &jumps) const;
        /** The four bilinear shape values of a face at its point q
         * (q = qx + 2 qy). */
        std::array<double, 4>
        face_shapes(const unsigned int q) const;
        /** Local force vector and (if @p ki) tangent of @p face from the
         * tractions and tangents at its points. */
        void
        interface_local(const InterfaceFace          &face,
                        const std::array<Local3, 4>  &tractions,
                        const std::array<Local33, 4> &tangents,
                        Vector<double>               &fi,
                        FullMatrix<double>           *ki) const;
        bool
        solve_step(const double displacement, unsigned int &iterations);
        void
        solve_linear(TrilinosWrappers::MPI::Vector       &du,
                     const TrilinosWrappers::MPI::Vector &rhs);
        void
        set_platen(TrilinosWrappers::MPI::Vector &u, const double disp);
        double
        reaction() const;
        double
        max_damage() const;
        void
        write_vtu(const unsigned int step, const double time);
        void
        write_curve(Json &summary);
        void
        write_calculix();
        /** Platen conditions and the DOFs of deleted cells. */
        void
        make_constraints();
        /** The converged step becomes the old state. */
        void
        accept_step();
        /** IMPL-EX: the implicit update of every point at the converged
         * displacements; the largest difference between the updated and
         * the extrapolated damage. */
        double
        implex_update();
        /** Delete cells over the strain threshold; how many. */
        unsigned int
        delete_cells();
        /** Largest brick damages (tension, compression) of the old state. */
        std::pair<double, double>
        max_brick_damage() const;
        /** The legs of the displacement protocol. */
        std::vector<Segment>
        make_protocol() const;
        /** Cycle results from the curve. */
        std::vector<Cycle>
        cycle_results() const;
        /** Append the last curve point to curve.csv. */
        void
        append_curve(const bool header);
        /** Write or read this rank's checkpoint file. */
        void
        save_checkpoint(const std::string &status) const;
        void
        load_checkpoint();

        /** The protocol's position, stored in checkpoints. */
        struct Progress
        {
          double       applied = 0, increment = 0, time = 0;
          unsigned int step = 0, easy_steps = 0, segment = 0;
          /** Platen displacement increment of the last converged step. */
          double last_increment = 0;
          template <class Archive>
          void
          serialize(Archive &ar, const unsigned int)
          {
            ar &applied &increment &time &step &easy_steps &segment
              &last_increment;
          }
        } progress;

        const std::vector<Box>            &boxes;
        const BrickMaterial               &material;
        const InterfaceLaw                &law;
        const WalletteSettings            &settings;
        RunContext                        &context;
        MPI_Comm                           comm;
        ConditionalOStream                &pcout;
        parallel::shared::Triangulation<3> triangulation;
        FESystem<3>                        fe;
        DoFHandler<3>                      dof_handler;
        IndexSet                           owned, relevant;
        AffineConstraints<double>          zero_constraints;
        TrilinosWrappers::SparseMatrix     matrix;
        /** Owned vectors; `ghosted` holds every entry on every rank. */
        TrilinosWrappers::MPI::Vector u, f_int, ghosted;
        std::vector<InterfaceFace>    interfaces;
        unsigned int                  n_quad = 4;
        std::array<double, 2>         q_points, q_weights;
        /** Joint states at the interface points, stored as deal.II
         * quadrature-point data of the cell on side A of each interface
         * (n_quad points for each interface of that cell): converged
         * (old), being computed (new) and one step further back (older,
         * IMPL-EX). */
        CellDataStorage<typename Triangulation<3>::cell_iterator,
                        InterfaceHistory>
          joints_old, joints_new, joints_older;
        /** Per interface this rank assembles: its point states in the
         * storages above (which keep them in place). */
        struct JointStates
        {
          std::array<InterfaceHistory *, 4> old{}, updated{}, older{};
        };
        std::vector<JointStates> joint;
        /** Platen DOFs with the component of each: (dof, component). */
        std::vector<std::pair<types::global_dof_index, unsigned int>> top_dofs;
        std::vector<std::pair<types::global_dof_index, unsigned int>>
          constrained_top;
        /** Cell matrices of the linear bricks, by cell shape. */
        std::map<std::vector<long>, FullMatrix<double>> cell_matrices;
        std::vector<const FullMatrix<double> *>         matrix_of_cell;
        double       height = 0, gross_area = 0, length = 0, thickness = 0;
        unsigned int n_bricks = 0;
        std::array<unsigned int, 3> n_faces_of_type{{0, 0, 0}},
          n_joints_of_type{{0, 0, 0}};
        std::vector<CurvePoint>                     curve;
        std::vector<std::pair<double, std::string>> pvd, pvd_interfaces;
        /** The steps of solution.xdmf (`Output format = hdf5'). */
        std::vector<XDMFEntry> xdmf;
        /** DOFs of the two gauge points and their distance. */
        std::array<std::array<types::global_dof_index, 3>, 2> gauge_dofs;
        double                                                gauge_span = 0;
        unsigned int total_newton = 0, total_cutbacks = 0;
        unsigned int n_solves         = 0;
        double       seconds_assembly = 0, seconds_solve = 0;
        /** Brick states at the quadrature points (nonlinear materials). */
        CellDataStorage<typename Triangulation<3>::cell_iterator, BrickState>
          states_old, states_new, states_older;
        /** IMPL-EX: pseudo-time ratio of this step to the last. */
        double implex_ratio = 0;
        /** IMPL-EX: largest damage error of a step over the run. */
        double implex_max_error = 0;
        /** IMPL-EX steps accepted at the minimum step with a damage error
         * above the tolerance. */
        unsigned int implex_over_tolerance = 0;
        /** IMPL-EX steps redone smaller (damage error over the tolerance). */
        unsigned int implex_rejected = 0;
        /** Krylov solves that did not converge and were done by MUMPS. */
        unsigned int n_direct_fallbacks = 0;
        /** A Krylov solve failed: the rest of the run uses MUMPS. */
        bool krylov_abandoned = false;
        /** Per active cell: characteristic length, strength factor,
         * deleted. */
        std::vector<double> cell_length, cell_factor;
        std::vector<char>   deleted;
        /** Per interface: strength factor, deleted. */
        std::vector<double> face_factor;
        std::vector<char>   face_deleted;
        /** DOFs held by the platens. */
        std::vector<types::global_dof_index> platen_lines;
        /** DOFs in no remaining cell (held in place). */
        std::vector<types::global_dof_index> orphans;
        /** Pseudo-time increment of the step being solved, s. */
        double       time_step = 0;
        unsigned int n_deleted = 0;
        /** Cells evaluated by the material / by their elastic matrix in
         * the assemblies (work skipped where nothing can change). */
        unsigned long n_material_cells = 0, n_elastic_cells = 0;
        /** The same for the interfaces: evaluated by the law / by their
         * cached elastic matrix. */
        unsigned long n_law_interfaces = 0, n_elastic_interfaces = 0;
        /** Elastic matrices of the interfaces, by (axis, area); per
         * interface a pointer into them (owned interfaces only). */
        std::map<std::pair<unsigned int, long>, FullMatrix<double>>
                                                interface_matrices;
        std::vector<const FullMatrix<double> *> matrix_of_interface;
        /** Whether the last assembly gave the initial (elastic) tangent,
         * whether the kept solver was set up for it, and the kept solvers. */
        bool initial_tangent = false, solver_is_initial = false;
        /** A linear model's matrix is assembled once (until deletions). */
        bool matrix_valid = false;
        /** Elastic bricks with nonlinear joints: the bricks' part of the
         * matrix, assembled once (until deletions). */
        TrilinosWrappers::SparseMatrix brick_matrix;
        bool                           brick_matrix_valid      = false;
        unsigned int                   n_factorisations_reused = 0;
        unsigned int                   n_matrix_assemblies     = 0;
        /** The direct solver: Amesos on the matrix, whose sparsity never
         * changes, so the symbolic analysis (ordering) is done once and
         * every new tangent only costs a numeric factorisation. */
        Epetra_LinearProblem               direct_problem;
        std::unique_ptr<Amesos_BaseSolver> direct;
        /** Sets up @p direct (name: Amesos_Mumps or Amesos_Klu). */
        void
        make_direct(const std::string &name);
        std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
      };

      void
      Model::make_mesh()
      {
        const auto               h = mesh_spacing(settings);
        std::vector<Point<3>>    vertices;
        std::vector<CellData<3>> cells;
        for (const Box &box : boxes)
          {
            height    = std::max(height, box.upper[2]);
            length    = std::max(length, box.upper[0]);
            thickness = std::max(thickness, box.upper[1]);
          }
        const double pi = numbers::PI, delta = settings.distortion;
        const double extent[3] = {length, thickness, height};
        // the distortion: waves of a few cells' length (so that the cells
        // are not parallelepipeds), times a factor that vanishes on the
        // faces of the brick (interfaces) or of the wallette (bonded)
        auto distort = [&](const Point<3> &p, const double(&xi)[3]) {
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
        };
        for (unsigned int b = 0; b < boxes.size(); ++b)
          {
            const Box   &box = boxes[b];
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
                      xi));
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
        n_bricks   = boxes.size();
        gross_area = length * thickness;
        if (settings.bonded)
          {
            SubCellData               sub;
            std::vector<unsigned int> considered;
            GridTools::delete_duplicated_vertices(
              vertices, cells, sub, considered, 1e-9 * height);
          }
        triangulation.create_triangulation(vertices, cells, SubCellData());
      }

      void
      Model::find_interfaces()
      {
        const auto h = mesh_spacing(settings);
        // face centres lie on a grid of half the mesh spacing: exact keys
        std::map<std::array<long, 3>,
                 std::pair<DoFHandler<3>::active_cell_iterator, unsigned int>>
                                                        open;
        std::set<std::pair<unsigned int, unsigned int>> joints[3];
        auto key = [&](const Point<3> &p) {
          std::array<long, 3> k;
          for (unsigned int d = 0; d < 3; ++d)
            k[d] = std::lround(p[d] / (h[d] / 2));
          return k;
        };
        const double tol = 1e-9 * height;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<3>     c    = cell->face(f)->center();
                const unsigned int axis = f / 2;
                if (axis == 2 &&
                    (std::abs(c[2]) < tol || std::abs(c[2] - height) < tol))
                  {
                    if (std::abs(c[2] - height) < tol)
                      for (unsigned int v = 0; v < 4; ++v)
                        for (unsigned int d = 0; d < 3; ++d)
                          top_dofs.emplace_back(
                            cell->face(f)->vertex_dof_index(v, d), d);
                    continue;
                  }
                const auto k  = key(c);
                const auto it = open.find(k);
                if (it == open.end())
                  {
                    open.emplace(k, std::make_pair(cell, f));
                    continue;
                  }
                auto         other = it->second;
                auto         a = other.first, b = cell;
                unsigned int fa = other.second, fb = f;
                if (a->center()[axis] > b->center()[axis])
                  {
                    std::swap(a, b);
                    std::swap(fa, fb);
                  }
                open.erase(it);
                InterfaceFace face;
                face.axis  = axis;
                face.type  = axis == 2 ? 0 : axis == 0 ? 1 : 2;
                face.owned = a->is_locally_owned();
                face.dofs.resize(24);
                face.brick_a = a->material_id();
                face.brick_b = b->material_id();
                face.cell_a  = a->active_cell_index();
                face.cell_b  = b->active_cell_index();
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    face.vertices[v] = a->face(fa)->vertex(v);
                    unsigned int w   = 4;
                    for (unsigned int x = 0; x < 4; ++x)
                      if (a->face(fa)->vertex(v).distance(
                            b->face(fb)->vertex(x)) < tol)
                        w = x;
                    AssertThrow(w < 4,
                                ExcMessage("internal error: a joint's faces "
                                           "do not coincide"));
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        face.dofs[3 * v + d] =
                          a->face(fa)->vertex_dof_index(v, d);
                        face.dofs[12 + 3 * v + d] =
                          b->face(fb)->vertex_dof_index(w, d);
                      }
                  }
                face.area =
                  cross_product_3d(face.vertices[1] - face.vertices[0],
                                   face.vertices[2] - face.vertices[0])
                    .norm();
                ++n_faces_of_type[face.type];
                joints[face.type].insert({face.brick_a, face.brick_b});
                interfaces.push_back(face);
              }
        for (unsigned int t = 0; t < 3; ++t)
          n_joints_of_type[t] = joints[t].size();
        // remove duplicates of the top DOFs (shared vertices within a brick)
        std::sort(top_dofs.begin(), top_dofs.end());
        top_dofs.erase(std::unique(top_dofs.begin(), top_dofs.end()),
                       top_dofs.end());

        if (settings.gauss)
          {
            q_points = {{0.5 - 0.5 / std::sqrt(3.), 0.5 + 0.5 / std::sqrt(3.)}};
            q_weights = {{0.5, 0.5}};
          }
        else
          {
            q_points  = {{0., 1.}};
            q_weights = {{0.5, 0.5}};
          }
        // the joint states live with the cell on side A: n_quad points
        // for each of its interfaces
        std::vector<typename Triangulation<3>::active_cell_iterator> cells(
          triangulation.n_active_cells());
        for (const auto &cell : triangulation.active_cell_iterators())
          cells[cell->active_cell_index()] = cell;
        std::vector<unsigned int> n_of_cell(cells.size(), 0),
          slot(interfaces.size(), 0);
        for (unsigned int n = 0; n < interfaces.size(); ++n)
          if (interfaces[n].owned)
            slot[n] = n_of_cell[interfaces[n].cell_a]++;
        for (unsigned int c = 0; c < cells.size(); ++c)
          if (n_of_cell[c] > 0)
            for (auto *storage : {&joints_old, &joints_new, &joints_older})
              storage->initialize(cells[c], n_quad * n_of_cell[c]);
        joint.assign(interfaces.size(), JointStates());
        for (unsigned int n = 0; n < interfaces.size(); ++n)
          if (interfaces[n].owned)
            {
              const auto &cell    = cells[interfaces[n].cell_a];
              const auto  old     = joints_old.get_data(cell);
              const auto  updated = joints_new.get_data(cell);
              const auto  older   = joints_older.get_data(cell);
              for (unsigned int q = 0; q < n_quad; ++q)
                {
                  const unsigned int k = slot[n] * n_quad + q;
                  joint[n].old[q]      = old[k].get();
                  joint[n].updated[q]  = updated[k].get();
                  joint[n].older[q]    = older[k].get();
                }
            }
      }

      void
      Model::setup_system()
      {
        dof_handler.distribute_dofs(fe);
        owned    = dof_handler.locally_owned_dofs();
        relevant = complete_index_set(dof_handler.n_dofs());

        find_interfaces();

        // Dirichlet conditions of the platens; increments are zero there
        const double tol      = 1e-9 * height;
        const bool   vertical = std::abs(settings.direction[0]) < 1e-12 &&
                              std::abs(settings.direction[1]) < 1e-12;
        AssertThrow(settings.lateral_fixed || vertical,
                    ExcMessage("the platens must be laterally fixed "
                               "('Platen lateral restraint = fixed') when "
                               "the platen moves sideways"));
        std::set<std::pair<types::global_dof_index, unsigned int>> pins;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() && f / 2 == 2)
              {
                const double z = cell->face(f)->center()[2];
                if (std::abs(z) > tol && std::abs(z - height) > tol)
                  continue;
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    const Point<3> p = cell->face(f)->vertex(v);
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        const auto i   = cell->face(f)->vertex_dof_index(v, d);
                        bool       fix = settings.lateral_fixed || d == 2;
                        // free platens: pin the rigid motions in the plane
                        if (!fix && std::abs(z) < tol && std::abs(p[1]) < tol &&
                            (std::abs(p[0]) < tol ||
                             (d == 1 && std::abs(p[0] - length) < tol)))
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
        make_constraints();
        for (const auto &td : top_dofs)
          if (zero_constraints.is_constrained(td.first))
            constrained_top.push_back(td);

        if (settings.gauge_length > 0)
          {
            // the mesh vertices nearest to the ends of the gauge
            const Point<3> ends[2] = {
              Point<3>(length / 2, 0, (height - settings.gauge_length) / 2),
              Point<3>(length / 2, 0, (height + settings.gauge_length) / 2)};
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
                          gauge_dofs[e][d] = cell->vertex_dof_index(v, d);
                      }
            gauge_span = where[1][2] - where[0][2];
            AssertThrow(gauge_span > 0,
                        ExcMessage("the gauge length is shorter than an "
                                   "element: no two mesh points along it"));
          }

        DynamicSparsityPattern dsp(relevant);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        zero_constraints,
                                        false,
                                        Utilities::MPI::this_mpi_process(comm));
        for (const auto &face : interfaces)
          if (face.owned)
            zero_constraints.add_entries_local_to_global(face.dofs, dsp, false);
        SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
        matrix.reinit(owned, owned, dsp, comm);

        u.reinit(owned, comm);
        f_int.reinit(owned, comm);
        ghosted.reinit(owned, relevant, comm);

        // per cell: characteristic length, strength factor of its brick;
        // per joint (brick pair): strength factor
        const unsigned int n_cells = triangulation.n_active_cells();
        cell_length.assign(n_cells, 0);
        cell_factor.assign(n_cells, 1);
        deleted.assign(n_cells, 0);
        face_factor.assign(interfaces.size(), 1);
        face_deleted.assign(interfaces.size(), 0);
        {
          std::mt19937                     random(settings.seed);
          std::normal_distribution<double> normal(0., 1.);
          auto                             draw = [&]() {
            const double x = normal(random);
            return std::clamp(1 + settings.strength_scatter * x, 0.2, 1.8);
          };
          std::vector<double> brick_factor(n_bricks, 1);
          for (auto &f : brick_factor)
            f = settings.strength_scatter > 0 ? draw() : 1.;
          std::map<std::pair<unsigned int, unsigned int>, double> joint_factor;
          for (const auto &face : interfaces)
            joint_factor[{face.brick_a, face.brick_b}] = 1;
          for (auto &j : joint_factor)
            j.second = settings.strength_scatter > 0 ? draw() : 1.;
          for (unsigned int i = 0; i < interfaces.size(); ++i)
            face_factor[i] =
              joint_factor[{interfaces[i].brick_a, interfaces[i].brick_b}];
          for (const auto &cell : triangulation.active_cell_iterators())
            {
              cell_length[cell->active_cell_index()] =
                std::cbrt(cell->measure());
              cell_factor[cell->active_cell_index()] =
                brick_factor[cell->material_id()];
            }
        }
        if (!material.is_linear())
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                BrickPoint point;
                point.characteristic_length =
                  cell_length[cell->active_cell_index()];
                point.strength_factor = cell_factor[cell->active_cell_index()];
                material.check_point(point);
                states_old.initialize(cell, 8);
                states_new.initialize(cell, 8);
                states_older.initialize(cell, 8);
              }

        // the elastic matrix of every cell, one per cell shape: all cells
        // of a linear material, the cells of a nonlinear one while they
        // stay elastic
        const double E      = material.youngs_modulus(),
                     nu     = material.poissons_ratio();
        const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                     mu     = E / (2 * (1 + nu));
        QGauss<3>   quadrature(2);
        FEValues<3> fe_values(fe,
                              quadrature,
                              update_gradients | update_JxW_values);
        matrix_of_cell.assign(triangulation.n_active_cells(), nullptr);
        const FEValuesExtractors::Vector displacement(0);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              std::vector<long> shape;
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
                    for (unsigned int i = 0; i < 24; ++i)
                      {
                        const auto eps_i =
                          fe_values[displacement].symmetric_gradient(i, q);
                        const double div_i =
                          fe_values[displacement].divergence(i, q);
                        for (unsigned int j = 0; j < 24; ++j)
                          {
                            const auto eps_j =
                              fe_values[displacement].symmetric_gradient(j, q);
                            const double div_j =
                              fe_values[displacement].divergence(j, q);
                            m(i, j) += (lambda * div_i * div_j +
                                        2 * mu * scalar_product(eps_i, eps_j)) *
                                       fe_values.JxW(q);
                          }
                      }
                }
              matrix_of_cell[cell->active_cell_index()] = &m;
            }

        // the elastic matrix of every interface this rank assembles, one
        // per (normal axis, area): used while the interface stays intact
        // and below the damage onset
        matrix_of_interface.assign(interfaces.size(), nullptr);
        std::array<Local3, 4>  no_traction{};
        std::array<Local33, 4> elastic{};
        for (auto &D : elastic)
          {
            D[0][0] = law.normal_stiffness;
            D[1][1] = D[2][2] = law.shear_stiffness;
          }
        Vector<double> f(24);
        for (unsigned int n = 0; n < interfaces.size(); ++n)
          if (interfaces[n].owned)
            {
              const auto &face = interfaces[n];
              auto       &m    = interface_matrices[std::make_pair(
                face.axis, std::lround(face.area * 1e12))];
              if (m.m() == 0)
                {
                  m.reinit(24, 24);
                  interface_local(face, no_traction, elastic, f, &m);
                }
              matrix_of_interface[n] = &m;
            }
      }

      void
      Model::assemble(const bool need_matrix)
      {
        const auto start        = Clock::now();
        ghosted                 = u;
        f_int                   = 0;
        const bool linear_model = material.is_linear() && law.is_linear();
        bool       with_matrix = need_matrix && !(linear_model && matrix_valid);
        initial_tangent        = true;
        const bool linear      = material.is_linear();
        // elastic bricks and nonlinear joints: the bricks' part of the
        // matrix never changes (until cells are deleted), so it is kept
        // and copied instead of summed cell by cell every iteration
        const bool keep_bricks      = linear && !linear_model && with_matrix;
        bool       bricks_assembled = false;
        if (with_matrix)
          {
            if (keep_bricks && brick_matrix_valid)
              {
                matrix.copy_from(brick_matrix);
                bricks_assembled = true;
              }
            else
              matrix = 0;
            ++n_matrix_assemblies;
          }
        std::vector<types::global_dof_index> dofs(24);
        Vector<double>                       ue(24), fe_local(24);
        FullMatrix<double>                   ke(24, 24);
        QGauss<3>                            quadrature(2);
        FEValues<3>                          fe_values(fe,
                              quadrature,
                              update_gradients | update_JxW_values);
        const FEValuesExtractors::Vector     displacement(0);
        std::array<SymmetricTensor<2, 3>, 8> strain;
        std::array<Tensor<1, 3>, 24>         grad;
        std::array<unsigned int, 24>         component;
        for (unsigned int i = 0; i < 24; ++i)
          component[i] = fe.system_to_component_index(i).first;
        SymmetricTensor<2, 3> stress;
        SymmetricTensor<4, 3> C;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && !deleted[cell->active_cell_index()])
            {
              const unsigned int c = cell->active_cell_index();
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < 24; ++i)
                ue[i] = ghosted[dofs[i]];
              bool                                     elastic = linear;
              std::vector<std::shared_ptr<BrickState>> old, updated, older;
              BrickPoint                               point;
              if (!linear)
                {
                  point.characteristic_length = cell_length[c];
                  point.strength_factor       = cell_factor[c];
                  point.time_step             = time_step;
                  old                         = states_old.get_data(cell);
                  updated                     = states_new.get_data(cell);
                  if (settings.implex)
                    older = states_older.get_data(cell);
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
                          (!material.is_elastic(strain[q], *old[q], point) ||
                           (settings.implex &&
                            !material.is_elastic(strain[q], *older[q], point))))
                        elastic = false;
                    }
                }
              if (elastic)
                {
                  // the response cannot differ from the cached elastic one
                  const FullMatrix<double> &k = *matrix_of_cell[c];
                  k.vmult(fe_local, ue);
                  f_int.add(dofs, fe_local);
                  if (with_matrix && !bricks_assembled)
                    zero_constraints.distribute_local_to_global(k,
                                                                dofs,
                                                                matrix);
                  if (!linear)
                    {
                      for (unsigned int q = 0; q < 8; ++q)
                        *updated[q] = *old[q];
                      ++n_elastic_cells;
                    }
                  continue;
                }
              ++n_material_cells;
              initial_tangent = false;
              fe_local        = 0;
              if (with_matrix)
                ke = 0;
              for (unsigned int q = 0; q < 8; ++q)
                {
                  // a residual assembly (line search) needs no tangent
                  if (settings.implex && with_matrix)
                    material.evaluate_extrapolated(strain[q],
                                                   *old[q],
                                                   *older[q],
                                                   implex_ratio,
                                                   point,
                                                   stress,
                                                   C);
                  else if (settings.implex)
                    material.extrapolated_stress(strain[q],
                                                 *old[q],
                                                 *older[q],
                                                 implex_ratio,
                                                 point,
                                                 stress);
                  else if (with_matrix)
                    material.evaluate(
                      strain[q], *old[q], point, *updated[q], stress, C);
                  else
                    material.update_state(
                      strain[q], *old[q], point, *updated[q], stress);
                  // every shape function has one nonzero component c_i
                  // with gradient g_i, so stress : B_i = sigma[c_i] . g_i
                  // and B_i : C : B_j = g_i . C[c_i][.][c_j][.] g_j (C has
                  // the minor symmetries)
                  const double JxW = fe_values.JxW(q);
                  for (unsigned int i = 0; i < 24; ++i)
                    {
                      grad[i] =
                        fe_values.shape_grad_component(i, q, component[i]);
                      for (unsigned int b = 0; b < 3; ++b)
                        fe_local[i] +=
                          stress[component[i]][b] * grad[i][b] * JxW;
                    }
                  if (with_matrix)
                    {
                      double Cf[3][3][3][3];
                      for (unsigned int a = 0; a < 3; ++a)
                        for (unsigned int b = 0; b < 3; ++b)
                          for (unsigned int c = 0; c < 3; ++c)
                            for (unsigned int e = 0; e < 3; ++e)
                              Cf[a][b][c][e] = C[a][b][c][e] * JxW;
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
                              ke(i, j) += hi[0] * grad[i][0] +
                                          hi[1] * grad[i][1] +
                                          hi[2] * grad[i][2];
                            }
                        }
                    }
                }
              for (unsigned int i = 0; i < 24; ++i)
                AssertThrow(std::isfinite(fe_local[i]),
                            ExcMessage("the brick material returned a "
                                       "stress that is not a number"));
              f_int.add(dofs, fe_local);
              if (with_matrix)
                zero_constraints.distribute_local_to_global(ke, dofs, matrix);
            }

        if (keep_bricks && !bricks_assembled)
          {
            matrix.compress(VectorOperation::add);
            brick_matrix.copy_from(matrix);
            brick_matrix_valid = true;
          }

        FullMatrix<double> ki(24, 24);
        Vector<double>     fi(24);
        InterfacePoint     point;
        point.time_step = time_step;
        std::array<Local3, 4>  jumps, tractions;
        std::array<Local33, 4> tangents;
        for (unsigned int n = 0; n < interfaces.size(); ++n)
          {
            const auto &face = interfaces[n];
            if (!face.owned || face_deleted[n])
              continue;
            point.strength_factor = face_factor[n];
            for (unsigned int i = 0; i < 24; ++i)
              ue[i] = ghosted[face.dofs[i]];
            interface_jumps(face, ue, jumps);
            const JointStates &h       = joint[n];
            bool               elastic = true;
            for (unsigned int q = 0; q < n_quad && elastic; ++q)
              elastic = law.is_elastic(jumps[q], *h.old[q], point) &&
                        (!settings.implex ||
                         law.is_elastic(jumps[q], *h.older[q], point));
            if (elastic)
              {
                // intact and below the onset: the cached elastic matrix
                // gives the exact response, the law is not evaluated
                const FullMatrix<double> &k = *matrix_of_interface[n];
                k.vmult(fi, ue);
                f_int.add(face.dofs, fi);
                if (with_matrix)
                  zero_constraints.distribute_local_to_global(k,
                                                              face.dofs,
                                                              matrix);
                if (!settings.implex)
                  for (unsigned int q = 0; q < n_quad; ++q)
                    *h.updated[q] = *h.old[q];
                ++n_elastic_interfaces;
                continue;
              }
            ++n_law_interfaces;
            for (unsigned int q = 0; q < n_quad; ++q)
              if (settings.implex)
                law.evaluate_extrapolated(jumps[q],
                                          *h.old[q],
                                          *h.older[q],
                                          implex_ratio,
                                          point,
                                          tractions[q],
                                          tangents[q]);
              else
                law.evaluate(jumps[q],
                             *h.old[q],
                             point,
                             *h.updated[q],
                             tractions[q],
                             tangents[q]);
            interface_local(
              face, tractions, tangents, fi, with_matrix ? &ki : nullptr);
            if (initial_tangent)
              for (unsigned int q = 0; q < n_quad; ++q)
                if ((settings.implex ? h.old : h.updated)[q]->damage > 0)
                  initial_tangent = false;
            f_int.add(face.dofs, fi);
            if (with_matrix)
              zero_constraints.distribute_local_to_global(ki,
                                                          face.dofs,
                                                          matrix);
          }
        f_int.compress(VectorOperation::add);
        initial_tangent = Utilities::MPI::min(int(initial_tangent), comm) == 1;
        if (with_matrix)
          {
            matrix_valid = true;
            matrix.compress(VectorOperation::add);
            // DOFs of deleted cells belong to no element: a unit diagonal
            // keeps the matrix regular (their increments are constrained)
            if (!orphans.empty())
              {
                const double scale =
                  material.youngs_modulus() * mesh_spacing(settings)[0];
                for (const auto i : orphans)
                  if (owned.is_element(i))
                    matrix.set(i, i, scale);
                matrix.compress(VectorOperation::insert);
              }
          }
        seconds_assembly +=
          std::chrono::duration<double>(Clock::now() - start).count();
      }

      void
      Model::interface_jumps(const InterfaceFace   &face,
                             const Vector<double>  &ue,
                             std::array<Local3, 4> &jumps) const
      {
        const unsigned int a = face.axis;
        for (unsigned int q = 0; q < 4; ++q)
          {
            const auto N    = face_shapes(q);
            Local3    &jump = jumps[q];
            jump            = {{0, 0, 0}};
            for (unsigned int v = 0; v < 4; ++v)
              for (unsigned int k = 0; k < 3; ++k)
                {
                  const unsigned int d = (a + k) % 3;
                  jump[k] += N[v] * (ue[12 + 3 * v + d] - ue[3 * v + d]);
                }
          }
      }

      std::array<double, 4>
      Model::face_shapes(const unsigned int q) const
      {
        const double xi = q_points[q % 2], eta = q_points[q / 2];
        return {
          {(1 - xi) * (1 - eta), xi * (1 - eta), (1 - xi) * eta, xi * eta}};
      }

      void
      Model::interface_local(const InterfaceFace          &face,
                             const std::array<Local3, 4>  &tractions,
                             const std::array<Local33, 4> &tangents,
                             Vector<double>               &fi,
                             FullMatrix<double>           *ki) const
      {
        fi = 0;
        if (ki)
          *ki = 0;
        const unsigned int a = face.axis;
        for (unsigned int qy = 0; qy < 2; ++qy)
          for (unsigned int qx = 0; qx < 2; ++qx)
            {
              const unsigned int q  = qx + 2 * qy;
              const auto         N  = face_shapes(q);
              const double       dA = face.area * q_weights[qx] * q_weights[qy];
              const Local3      &t  = tractions[q];
              const Local33     &D  = tangents[q];
              for (unsigned int v = 0; v < 8; ++v)
                {
                  const double sv = (v < 4 ? -1. : 1.) * N[v % 4];
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const unsigned int row = 3 * v + (a + k) % 3;
                      fi[row] += sv * t[k] * dA;
                      if (ki)
                        for (unsigned int w = 0; w < 8; ++w)
                          {
                            const double sw = (w < 4 ? -1. : 1.) * N[w % 4];
                            for (unsigned int l = 0; l < 3; ++l)
                              (*ki)(row, 3 * w + (a + l) % 3) +=
                                sv * sw * D[k][l] * dA;
                          }
                    }
                }
            }
      }

      void
      Model::solve_linear(TrilinosWrappers::MPI::Vector       &du,
                          const TrilinosWrappers::MPI::Vector &rhs)
      {
        const auto start = Clock::now();
        ++n_solves;
        const std::string &s = settings.linear_solver;
        // the factorisation (or AMG hierarchy) of the initial tangent is
        // kept while the tangent stays the initial one: every step of a
        // linear model, the elastic steps of a nonlinear one
        const bool reuse = initial_tangent && solver_is_initial;
        if (reuse)
          ++n_factorisations_reused;
        const auto direct_solve = [&](const bool factorise) {
          if (factorise)
            {
              AssertThrow(direct->NumericFactorization() == 0,
                          ExcMessage("the direct solver could not factorise "
                                     "the tangent (singular matrix?)"));
              solver_is_initial = initial_tangent;
            }
          direct_problem.SetLHS(&du.trilinos_vector());
          direct_problem.SetRHS(
            const_cast<Epetra_MultiVector *>(&rhs.trilinos_vector()));
          AssertThrow(direct->Solve() == 0,
                      ExcMessage("the direct solver failed"));
        };
        if (s == "direct" || s == "direct klu" || krylov_abandoned)
          {
            const bool fresh = !direct;
            if (fresh)
              make_direct(s == "direct klu" ? "Amesos_Klu" : "Amesos_Mumps");
            direct_solve(fresh || !reuse);
          }
        else
          {
            if (!reuse)
              amg.reset();
            if (!amg)
              {
                amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
                TrilinosWrappers::PreconditionAMG::AdditionalData data;
                std::vector<std::vector<bool>>                    modes;
                DoFTools::extract_constant_modes(dof_handler,
                                                 ComponentMask(3, true),
                                                 modes);
                data.constant_modes        = modes;
                data.elliptic              = true;
                data.higher_order_elements = false;
                data.smoother_sweeps       = 2;
                data.aggregation_threshold = 0.02;
                amg->initialize(matrix, data);
                solver_is_initial = initial_tangent;
              }
            // AMG-preconditioned Krylov needs tens of iterations on an
            // intact or moderately damaged tangent; a solve that needs more
            // than this is stalling
            SolverControl control(1000,
                                  settings.linear_tolerance * rhs.l2_norm());
            try
              {
                if (s == "cg amg")
                  {
                    TrilinosWrappers::SolverCG solver(control);
                    solver.solve(matrix, du, rhs, *amg);
                  }
                else
                  {
                    TrilinosWrappers::SolverGMRES solver(control);
                    solver.solve(matrix, du, rhs, *amg);
                  }
              }
            catch (const std::exception &)
              {
                // cracked and crushed regions can make the tangent so badly
                // conditioned that the Krylov solver stalls or AztecOO
                // reports a loss of precision. Damage does not heal, so the
                // tangents of the rest of the run are no better: this solve
                // and all later ones use MUMPS
                ++n_direct_fallbacks;
                krylov_abandoned = true;
                amg.reset();
                pcout << "  note: the Krylov solver failed on the damaged "
                         "tangent; MUMPS solves from here on\n";
                make_direct("Amesos_Mumps");
                du = 0;
                direct_solve(true);
              }
          }
        seconds_solve +=
          std::chrono::duration<double>(Clock::now() - start).count();
      }

      void
      Model::make_direct(const std::string &name)
      {
        direct_problem.SetOperator(
          const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
        Amesos factory;
        direct.reset(factory.Create(name.c_str(), direct_problem));
        AssertThrow(direct != nullptr,
                    ExcMessage(name + " is not available in this Trilinos"));
        AssertThrow(direct->SymbolicFactorization() == 0,
                    ExcMessage("the symbolic analysis of the direct solver "
                               "failed"));
      }

      void
      Model::set_platen(TrilinosWrappers::MPI::Vector &v, const double disp)
      {
        for (const auto &td : constrained_top)
          if (owned.is_element(td.first))
            v[td.first] = disp * settings.direction[td.second];
        v.compress(VectorOperation::insert);
      }

      double
      Model::reaction() const
      {
        double r = 0;
        for (const auto &td : top_dofs)
          if (owned.is_element(td.first))
            r += f_int[td.first] * settings.direction[td.second];
        return Utilities::MPI::sum(r, comm);
      }

      double
      Model::max_damage() const
      {
        double d = 0;
        for (unsigned int n = 0; n < interfaces.size(); ++n)
          if (interfaces[n].owned)
            for (unsigned int q = 0; q < n_quad; ++q)
              d = std::max(d, joint[n].old[q]->damage);
        return Utilities::MPI::max(d, comm);
      }

      bool
      Model::solve_step(const double displacement, unsigned int &iterations)
      {
        set_platen(u, displacement);
        TrilinosWrappers::MPI::Vector r(owned, comm), du(owned, comm),
          u_start(owned, comm);
        double norm0 = 0;
        // convergence: the residual (constrained entries zeroed) against the
        // platen reactions, or against the elastic force of the whole
        // applied displacement when nothing is loaded; @p all is the norm of
        // the internal forces with the reactions
        const auto converged = [&](const double norm, const double all) {
          const double scale =
            std::max(std::sqrt(std::max(all * all - norm * norm, 0.)),
                     1e-6 * material.youngs_modulus() * gross_area *
                       std::abs(settings.target_displacement) / height);
          return norm <= settings.newton_tolerance * scale;
        };
        // a material or solver failure inside the iteration counts as no
        // convergence: the caller cuts the step back
        try
          {
            for (iterations = 0; iterations <= settings.max_newton;
                 ++iterations)
              {
                assemble(true);
                r = f_int;
                r *= -1;
                zero_constraints.set_zero(r);
                const double norm = r.l2_norm();
                const double all  = f_int.l2_norm();
                if (!std::isfinite(norm) || !std::isfinite(all))
                  return false;
                if (converged(norm, all))
                  return true;
                if (iterations == settings.max_newton)
                  return false;
                norm0 = norm;
                du    = 0;
                try
                  {
                    solve_linear(du, r);
                  }
                catch (const std::exception &)
                  {
                    return false;
                  }
                zero_constraints.set_zero(du);
                u_start = u;
                u.add(1., du);
                if (settings.line_search)
                  {
                    // backtracking on the residual norm
                    double alpha = 1, best_alpha = 1, best = 0;
                    for (unsigned int k = 0; k < 6; ++k)
                      {
                        assemble(false);
                        r = f_int;
                        zero_constraints.set_zero(r);
                        const double n = r.l2_norm();
                        // converged at this point already: the states were
                        // just updated at it, so the tangent assembly of the
                        // next iteration would only repeat this residual
                        if (std::isfinite(n) &&
                            n < (1 - 1e-4 * alpha) * norm0 &&
                            converged(n, f_int.l2_norm()))
                          {
                            ++iterations;
                            return true;
                          }
                        if (k == 0 || (std::isfinite(n) && n < best))
                          {
                            best       = n;
                            best_alpha = alpha;
                          }
                        if (std::isfinite(n) && n < (1 - 1e-4 * alpha) * norm0)
                          break;
                        alpha /= 2;
                        u = u_start;
                        u.add(alpha, du);
                      }
                    if (alpha != best_alpha)
                      {
                        u = u_start;
                        u.add(best_alpha, du);
                      }
                  }
              }
          }
        catch (const std::exception &)
          {
            return false;
          }
        return false;
      }

      void
      Model::write_vtu(const unsigned int step, const double time)
      {
        if (!settings.write_vtu)
          return;
        ghosted = u;
        DataOut<3> data_out;
        data_out.attach_dof_handler(dof_handler);
        std::vector<std::string> names(3, "displacement");
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
          interpretation(
            3, DataComponentInterpretation::component_is_part_of_vector);
        data_out.add_data_vector(ghosted,
                                 names,
                                 DataOut<3>::type_dof_data,
                                 interpretation);
        // stress (Pa), damage and plastic strain averaged over the cell's
        // quadrature points, from the converged states
        const unsigned int         n_cells = triangulation.n_active_cells();
        std::vector<Vector<float>> stress(6, Vector<float>(n_cells));
        Vector<float> subdomain(n_cells), damage_t(n_cells), damage_c(n_cells),
          plastic(n_cells), removed(n_cells);
        QGauss<3>   quadrature(2);
        FEValues<3> fe_values(fe, quadrature, update_gradients);
        std::vector<SymmetricTensor<2, 3>> eps(8);
        const FEValuesExtractors::Vector   displacement(0);
        const bool                         linear = material.is_linear();
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const unsigned int c = cell->active_cell_index();
              subdomain[c]         = cell->subdomain_id();
              removed[c]           = deleted[c];
              if (deleted[c])
                continue;
              fe_values.reinit(cell);
              fe_values[displacement].get_function_symmetric_gradients(ghosted,
                                                                       eps);
              BrickPoint point;
              point.characteristic_length = cell_length[c];
              point.strength_factor       = cell_factor[c];
              SymmetricTensor<2, 3> sigma, mean;
              SymmetricTensor<4, 3> C;
              BrickState            scratch;
              for (unsigned int q = 0; q < 8; ++q)
                {
                  if (linear)
                    material.evaluate(
                      eps[q], BrickState(), point, scratch, sigma, C);
                  else
                    {
                      // from the converged state at the converged strain:
                      // no further loading, the stress of the step
                      const auto old = states_old.get_data(cell);
                      material.evaluate(
                        eps[q], *old[q], point, scratch, sigma, C);
                      damage_t[c] += old[q]->damage_t / 8;
                      damage_c[c] += old[q]->damage_c / 8;
                      plastic[c] += old[q]->plastic_strain.norm() / 8;
                    }
                  mean += sigma / 8;
                }
              const unsigned int ij[6][2] = {
                {0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
              for (unsigned int k = 0; k < 6; ++k)
                stress[k][c] = mean[ij[k][0]][ij[k][1]];
            }
        const char *stress_names[6] = {"stress_xx",
                                       "stress_yy",
                                       "stress_zz",
                                       "stress_xy",
                                       "stress_yz",
                                       "stress_xz"};
        for (unsigned int k = 0; k < 6; ++k)
          data_out.add_data_vector(stress[k], stress_names[k]);
        data_out.add_data_vector(subdomain, "subdomain");
        if (!linear)
          {
            data_out.add_data_vector(damage_t, "damage_tension");
            data_out.add_data_vector(damage_c, "damage_compression");
            data_out.add_data_vector(plastic, "plastic_strain_norm");
          }
        if (settings.deletion_strain > 0)
          data_out.add_data_vector(removed, "deleted");
        data_out.build_patches();
        const std::string dir = context.output.path();
        if (settings.hdf5)
          {
            // mesh and fields of this step in one HDF5 file, written by all
            // ranks; solution.xdmf lists the steps with their times
            DataOutBase::DataOutFilter filter(
              DataOutBase::DataOutFilterFlags(false, true));
            data_out.write_filtered_data(filter);
            const std::string h5 =
              "solution_" + Utilities::int_to_string(step, 4) + ".h5";
            data_out.write_hdf5_parallel(filter, dir + h5, comm);
            xdmf.push_back(data_out.create_xdmf_entry(filter, h5, time, comm));
            data_out.write_xdmf_file(xdmf, dir + "solution.xdmf", comm);
            context.output.file(h5);
            context.output.file("solution.xdmf");
          }
        else
          {
            const std::string pvtu = data_out.write_vtu_with_pvtu_record(
              dir, "solution", step, comm, 4);
            pvd.emplace_back(time, pvtu);
            // record the files written by DataOut
            context.output.file(pvtu);
            const std::string stem =
              "solution_" + Utilities::int_to_string(step, 4);
            const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
            for (unsigned int r = 0; r < n_ranks; ++r)
              context.output.file(stem + "." +
                                  Utilities::int_to_string(
                                    r, Utilities::needed_digits(n_ranks - 1)) +
                                  ".vtu");
          }

        // interfaces: one quadrilateral per face pair, cell data averaged
        // over the integration points
        const unsigned int  n = interfaces.size();
        std::vector<double> damage(n, 0), opening(n, 0), slip(n, 0);
        for (unsigned int i = 0; i < n; ++i)
          if (interfaces[i].owned)
            {
              const auto        &face = interfaces[i];
              const unsigned int a    = face.axis;
              for (unsigned int q = 0; q < n_quad; ++q)
                damage[i] += joint[i].old[q]->damage / n_quad;
              // opening at the centre of the face
              Tensor<1, 3> jump;
              for (unsigned int v = 0; v < 4; ++v)
                for (unsigned int d = 0; d < 3; ++d)
                  jump[d] += 0.25 * (ghosted[face.dofs[12 + 3 * v + d]] -
                                     ghosted[face.dofs[3 * v + d]]);
              opening[i] = jump[a];
              slip[i]    = std::hypot(jump[(a + 1) % 3], jump[(a + 2) % 3]);
            }
        MPI_Allreduce(
          MPI_IN_PLACE, damage.data(), n, MPI_DOUBLE, MPI_SUM, comm);
        MPI_Allreduce(
          MPI_IN_PLACE, opening.data(), n, MPI_DOUBLE, MPI_SUM, comm);
        MPI_Allreduce(MPI_IN_PLACE, slip.data(), n, MPI_DOUBLE, MPI_SUM, comm);
        std::ostringstream name;
        name << "interfaces_" << std::setw(4) << std::setfill('0') << step
             << ".vtu";
        const std::string file = context.output.file(name.str());
        pvd_interfaces.emplace_back(time, name.str());
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            std::ofstream out(file);
            out << std::setprecision(10);
            out
              << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
                 "version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "<UnstructuredGrid>\n<Piece NumberOfPoints=\""
              << 4 * n << "\" NumberOfCells=\"" << n << "\">\n"
              << "<Points>\n<DataArray type=\"Float64\" "
                 "NumberOfComponents=\"3\" format=\"ascii\">\n";
            const unsigned int order[4] = {0, 1, 3, 2};
            for (const auto &face : interfaces)
              for (unsigned int v = 0; v < 4; ++v)
                out << face.vertices[order[v]] << "\n";
            out << "</DataArray>\n</Points>\n<Cells>\n<DataArray "
                   "type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
            for (unsigned int i = 0; i < 4 * n; ++i)
              out << i << (i % 4 == 3 ? "\n" : " ");
            out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
                   "format=\"ascii\">\n";
            for (unsigned int i = 0; i < n; ++i)
              out << 4 * (i + 1) << "\n";
            out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
                   "format=\"ascii\">\n";
            for (unsigned int i = 0; i < n; ++i)
              out << "9\n";
            out << "</DataArray>\n</Cells>\n<CellData>\n";
            auto array = [&](const char                *title,
                             const std::vector<double> &values) {
              out << "<DataArray type=\"Float64\" Name=\"" << title
                  << "\" format=\"ascii\">\n";
              for (const double x : values)
                out << x << "\n";
              out << "</DataArray>\n";
            };
            array("damage", damage);
            array("normal_opening", opening);
            array("slip", slip);
            std::vector<double> type(n);
            for (unsigned int i = 0; i < n; ++i)
              type[i] = interfaces[i].type;
            array("joint_type_bed0_head1_collar2", type);
            out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
          }
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            if (!settings.hdf5)
              {
                std::ofstream pvd_out(context.output.file("solution.pvd"));
                DataOutBase::write_pvd_record(pvd_out, pvd);
              }
            std::ofstream pvd_i(context.output.file("interfaces.pvd"));
            DataOutBase::write_pvd_record(pvd_i, pvd_interfaces);
          }
      }

      void
      Model::write_curve(Json &summary)
      {
        // curve.csv was written step by step (append_curve)
        context.output.file("curve.csv");
        const std::vector<Cycle> cycles = cycle_results();
        const bool               cyclic = !settings.cycle_amplitudes.empty();
        const double      modulus = curve.size() > 1 && curve[1].strain != 0 ?
                                      curve[1].stress / curve[1].strain :
                                      0.;
        const std::string cycles_csv = context.output.path() + "/cycles.csv";
        if (cyclic)
          {
            context.output.file("cycles.csv");
            if (Utilities::MPI::this_mpi_process(comm) == 0)
              {
                std::ofstream out(cycles_csv);
                out << std::setprecision(12);
                out << "cycle,amplitude_strain,peak_stress_Pa,strain_at_peak,"
                       "residual_strain,unloading_modulus_Pa,"
                       "stiffness_ratio,dissipated_energy_J_per_m3\n";
                for (const auto &c : cycles)
                  out << c.cycle << "," << c.amplitude << "," << c.peak_stress
                      << "," << c.strain_at_peak << "," << c.residual_strain
                      << "," << c.unloading_modulus << ","
                      << (modulus > 0 ? c.unloading_modulus / modulus : 0.)
                      << "," << c.dissipated_energy << "\n";
              }
            // envelope (first cycle at each amplitude), stability point
            // (last cycle) and common point (where the reloading of the
            // next cycle at the same amplitude meets the unloading of the
            // previous one)
            const unsigned int n_rep    = settings.cycles_per_amplitude;
            Json               envelope = Json::array();
            if (Utilities::MPI::this_mpi_process(comm) == 0)
              {
                std::ofstream out(context.output.path() + "/envelope.csv");
                out << std::setprecision(12)
                    << "amplitude_strain,envelope_strain,envelope_stress_Pa,"
                       "common_point_stress_Pa,stability_point_stress_Pa\n";
                for (unsigned int k = 0; k * n_rep < cycles.size(); ++k)
                  {
                    const Cycle &first = cycles[k * n_rep];
                    const Cycle &lastc =
                      cycles[std::min<std::size_t>((k + 1) * n_rep,
                                                   cycles.size()) -
                             1];
                    // empty in the CSV where there is no second cycle
                    double common = std::numeric_limits<double>::quiet_NaN();
                    if (n_rep > 1 && k * n_rep + 1 < cycles.size())
                      {
                        // reloading branch of the 2nd cycle against the
                        // unloading branch of the 1st, both as stress over
                        // strain: the highest stress where the reloading
                        // line reaches the unloading line
                        const Cycle &second       = cycles[k * n_rep + 1];
                        auto         on_unloading = [&](const double e) {
                          for (unsigned int i = first.turn + 1; i <= first.last;
                               ++i)
                            {
                              const auto &a = curve[i - 1], &b = curve[i];
                              if ((e - a.strain) * (e - b.strain) <= 0 &&
                                  a.strain != b.strain)
                                return a.stress + (b.stress - a.stress) *
                                                    (e - a.strain) /
                                                    (b.strain - a.strain);
                            }
                          return std::numeric_limits<double>::quiet_NaN();
                        };
                        // from the top of the reloading down to the first
                        // point on or under the unloading line
                        for (unsigned int i = second.turn; i > second.first;
                             --i)
                          {
                            const double g = on_unloading(curve[i].strain);
                            if (std::isfinite(g) &&
                                curve[i].stress <=
                                  g + 1e-9 * std::abs(first.peak_stress))
                              {
                                common = curve[i].stress;
                                break;
                              }
                          }
                      }
                    out << first.amplitude << "," << first.strain_at_peak << ","
                        << first.peak_stress << ",";
                    if (std::isfinite(common))
                      out << common;
                    out << "," << lastc.peak_stress << "\n";
                  }
              }
            context.output.file("envelope.csv");
            Json list = Json::array();
            for (const auto &c : cycles)
              {
                Json j;
                j["cycle"]             = c.cycle;
                j["amplitude_strain"]  = c.amplitude;
                j["peak_stress"]       = c.peak_stress;
                j["residual_strain"]   = c.residual_strain;
                j["unloading_modulus"] = c.unloading_modulus;
                j["dissipated_energy"] = c.dissipated_energy;
                list.push_back(j);
              }
            summary["cycles"] = list;
          }
        if (settings.write_plot)
          {
            const std::string png = context.output.file("curve.png");
            if (cyclic)
              context.output.file("degradation.png");
            if (Utilities::MPI::this_mpi_process(comm) == 0)
              {
                const std::string script =
                  context.output.path() + "/.curve_plot.py";
                std::ofstream py(script);
                py << "import matplotlib\nmatplotlib.use('Agg')\n"
                      "import matplotlib.pyplot as plt\nimport csv, os\n"
                      "d = '"
                   << context.output.path()
                   << "'\n"
                      "rows = list(csv.DictReader(open(d + '/curve.csv')))\n"
                      "e = [1e3*float(r['strain']) for r in rows]\n"
                      "s = [1e-6*float(r['stress_Pa']) for r in rows]\n"
                      "plt.figure(figsize=(6,4.5))\n"
                      "plt.plot(e, s, '-', lw=1, marker='o' if len(e) < 80 "
                      "else None, ms=3)\n"
                      "if os.path.exists(d + '/cycles.csv'):\n"
                      "    c = list(csv.DictReader(open(d + '/cycles.csv')))\n"
                      "    plt.plot([1e3*float(r['strain_at_peak']) for r in "
                      "c], [1e-6*float(r['peak_stress_Pa']) for r in c], "
                      "'k^', ms=4, label='cycle peaks')\n"
                      "    plt.legend()\n"
                      "plt.xlabel('strain along the platen motion (1e-3)')\n"
                      "plt.ylabel('stress = force / gross area (MPa)')\n"
                      "plt.grid(alpha=0.3)\nplt.tight_layout()\n"
                      "plt.savefig('"
                   << png
                   << "', dpi=120)\n"
                      "if os.path.exists(d + '/cycles.csv'):\n"
                      "    plt.figure(figsize=(6,4.5))\n"
                      "    plt.plot([1e3*float(r['strain_at_peak']) for r in "
                      "c], [float(r['stiffness_ratio']) for r in c], 'o-')\n"
                      "    plt.xlabel('strain at the cycle peak (1e-3)')\n"
                      "    plt.ylabel('unloading modulus / initial modulus')\n"
                      "    plt.ylim(0, 1.05)\n    plt.grid(alpha=0.3)\n"
                      "    plt.tight_layout()\n"
                      "    plt.savefig(d + '/degradation.png', dpi=120)\n";
                py.close();
                const int rc = std::system(
                  ("/usr/bin/python3 " + script + " >/dev/null 2>&1").c_str());
                std::filesystem::remove(script);
                if (rc != 0)
                  pcout << "Warning: the plots could not be drawn "
                           "(needs /usr/bin/python3 with matplotlib)\n";
              }
          }
        double peak = -1e300, strain_at_peak = 0;
        for (const auto &p : curve)
          if (p.stress > peak)
            {
              peak           = p.stress;
              strain_at_peak = p.strain;
            }
        double work = 0;
        for (unsigned int i = 1; i < curve.size(); ++i)
          work += 0.5 * (curve[i].force + curve[i - 1].force) *
                  (curve[i].displacement - curve[i - 1].displacement);
        summary["peak_stress"]     = curve.size() > 1 ? peak : 0.;
        summary["strain_at_peak"]  = strain_at_peak;
        summary["initial_modulus"] = modulus;
        if (gauge_span > 0)
          {
            summary["gauge_length"] = gauge_span;
            for (const auto &p : curve)
              if (p.stress == peak)
                summary["gauge_strain_at_peak"] = p.gauge_strain;
            summary["initial_modulus_gauge"] =
              curve.size() > 1 && curve[1].gauge_strain != 0 ?
                curve[1].stress / curve[1].gauge_strain :
                0.;
          }
        summary["final_stress"]  = curve.back().stress;
        summary["final_strain"]  = curve.back().strain;
        summary["external_work"] = work;
        summary["max_damage"]    = curve.back().max_damage;
        if (!material.is_linear())
          {
            summary["max_brick_damage_tension"] = curve.back().brick_damage_t;
            summary["max_brick_damage_compression"] =
              curve.back().brick_damage_c;
          }
      }

      void
      Model::write_calculix()
      {
        // the nodes used by the cells, numbered from 1 in vertex order
        ghosted                       = u;
        const auto               &all = triangulation.get_vertices();
        std::vector<unsigned int> node(all.size(), 0);
        std::vector<std::array<types::global_dof_index, 3>> dofs(all.size());
        for (const auto &cell : dof_handler.active_cell_iterators())
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
        const std::string inp = context.output.file("calculix.inp");
        const std::string csv = context.output.file("nodal_displacements.csv");
        if (Utilities::MPI::this_mpi_process(comm) != 0)
          return;
        const double  tol = 1e-9 * height;
        std::ofstream out(inp);
        // CalculiX reads fields of at most 20 characters
        out << std::setprecision(15);
        out << "** masonry wallette: " << triangulation.n_active_cells()
            << " C3D8 elements, bottom fixed, top moved by "
            << settings.target_displacement << " m along ("
            << settings.direction[0] << ", " << settings.direction[1] << ", "
            << settings.direction[2] << ")\n*NODE, NSET=NALL\n";
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
            << material.youngs_modulus() << ", " << material.poissons_ratio()
            << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=BRICK\n"
            << "*STEP\n*STATIC\n*BOUNDARY\n";
        for (unsigned int d = 0; d < 3; ++d)
          if (settings.lateral_fixed || d == 2)
            out << "BOTTOM, " << d + 1 << ", " << d + 1 << "\n";
        for (unsigned int d = 0; d < 3; ++d)
          if (settings.lateral_fixed || d == 2)
            out << "TOP, " << d + 1 << ", " << d + 1 << ", " << std::scientific
                << std::setprecision(12)
                << settings.target_displacement * settings.direction[d]
                << std::defaultfloat << std::setprecision(15) << "\n";
        out << "*NODE PRINT, NSET=NALL\nU\n*NODE PRINT, NSET=TOP, "
               "TOTALS=ONLY\nRF\n*END STEP\n";
        std::ofstream d(csv);
        d << std::setprecision(17) << "node,x,y,z,u_x,u_y,u_z\n";
        for (unsigned int v = 0; v < all.size(); ++v)
          if (node[v])
            d << node[v] << "," << all[v][0] << "," << all[v][1] << ","
              << all[v][2] << "," << ghosted[dofs[v][0]] << ","
              << ghosted[dofs[v][1]] << "," << ghosted[dofs[v][2]] << "\n";
      }

      void
      Model::make_constraints()
      {
        zero_constraints.clear();
        zero_constraints.reinit(relevant);
        for (const auto i : platen_lines)
          zero_constraints.add_line(i);
        for (const auto i : orphans)
          if (!zero_constraints.is_constrained(i))
            zero_constraints.add_line(i);
        zero_constraints.close();
      }

      void
      Model::accept_step()
      {
        for (unsigned int n = 0; n < interfaces.size(); ++n)
          if (interfaces[n].owned)
            for (unsigned int q = 0; q < n_quad; ++q)
              {
                if (settings.implex)
                  *joint[n].older[q] = *joint[n].old[q];
                *joint[n].old[q] = *joint[n].updated[q];
              }
        if (!material.is_linear())
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && !deleted[cell->active_cell_index()])
              {
                const auto old     = states_old.get_data(cell);
                const auto updated = states_new.get_data(cell);
                const auto older   = states_older.get_data(cell);
                for (unsigned int q = 0; q < 8; ++q)
                  {
                    if (settings.implex)
                      *older[q] = *old[q];
                    *old[q] = *updated[q];
                  }
              }
      }

      double
      Model::implex_update()
      {
        ghosted             = u;
        double error        = 0;
        auto   extrapolated = [&](const double d, const double d_older) {
          return std::clamp(d + implex_ratio * (d - d_older), d, 1.);
        };
        if (!material.is_linear())
          {
            QGauss<3>   quadrature(2);
            FEValues<3> fe_values(fe, quadrature, update_gradients);
            std::vector<SymmetricTensor<2, 3>> eps(8);
            const FEValuesExtractors::Vector   displacement(0);
            SymmetricTensor<2, 3>              stress;
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (cell->is_locally_owned() &&
                  !deleted[cell->active_cell_index()])
                {
                  const unsigned int c = cell->active_cell_index();
                  fe_values.reinit(cell);
                  fe_values[displacement].get_function_symmetric_gradients(
                    ghosted, eps);
                  BrickPoint point;
                  point.characteristic_length = cell_length[c];
                  point.strength_factor       = cell_factor[c];
                  point.time_step             = time_step;
                  const auto old              = states_old.get_data(cell);
                  const auto older            = states_older.get_data(cell);
                  const auto updated          = states_new.get_data(cell);
                  for (unsigned int q = 0; q < 8; ++q)
                    {
                      material.update_state(
                        eps[q], *old[q], point, *updated[q], stress);
                      error =
                        std::max({error,
                                  std::abs(updated[q]->damage_t -
                                           extrapolated(old[q]->damage_t,
                                                        older[q]->damage_t)),
                                  std::abs(updated[q]->damage_c -
                                           extrapolated(old[q]->damage_c,
                                                        older[q]->damage_c))});
                    }
                }
          }
        InterfacePoint point;
        point.time_step = time_step;
        Local3                t;
        Local33               D;
        Vector<double>        ue(24);
        std::array<Local3, 4> jumps;
        for (unsigned int n = 0; n < interfaces.size(); ++n)
          {
            const auto &face = interfaces[n];
            if (!face.owned || face_deleted[n])
              continue;
            point.strength_factor = face_factor[n];
            for (unsigned int i = 0; i < 24; ++i)
              ue[i] = ghosted[face.dofs[i]];
            interface_jumps(face, ue, jumps);
            const JointStates &h = joint[n];
            for (unsigned int q = 0; q < n_quad; ++q)
              {
                law.evaluate(jumps[q], *h.old[q], point, *h.updated[q], t, D);
                error = std::max(error,
                                 std::abs(h.updated[q]->damage -
                                          extrapolated(h.old[q]->damage,
                                                       h.older[q]->damage)));
              }
          }
        return Utilities::MPI::max(error, comm);
      }

      std::pair<double, double>
      Model::max_brick_damage() const
      {
        double dt = 0, dc = 0;
        if (!material.is_linear())
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && !deleted[cell->active_cell_index()])
              for (const auto &state : states_old.get_data(cell))
                {
                  dt = std::max(dt, state->damage_t);
                  dc = std::max(dc, state->damage_c);
                }
        return {Utilities::MPI::max(dt, comm), Utilities::MPI::max(dc, comm)};
      }

      unsigned int
      Model::delete_cells()
      {
        if (settings.deletion_strain <= 0)
          return 0;
        // maximum principal strain of the cell-averaged strain
        ghosted = u;
        QGauss<3>                                    quadrature(2);
        FEValues<3>                                  fe_values(fe,
                              quadrature,
                              update_gradients | update_JxW_values);
        std::vector<SymmetricTensor<2, 3>>           eps(8);
        const FEValuesExtractors::Vector             displacement(0);
        std::vector<std::pair<double, unsigned int>> candidates;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && !deleted[cell->active_cell_index()])
            {
              fe_values.reinit(cell);
              fe_values[displacement].get_function_symmetric_gradients(ghosted,
                                                                       eps);
              SymmetricTensor<2, 3> mean;
              double                volume = 0;
              for (unsigned int q = 0; q < 8; ++q)
                {
                  mean += eps[q] * fe_values.JxW(q);
                  volume += fe_values.JxW(q);
                }
              mean /= volume;
              const double e1 = eigenvalues(mean)[0];
              if (e1 > settings.deletion_strain)
                candidates.emplace_back(e1, cell->active_cell_index());
            }
        // the same decision on every rank: largest strains first, capped
        std::vector<std::pair<double, unsigned int>> all;
        for (const auto &part : Utilities::MPI::all_gather(comm, candidates))
          all.insert(all.end(), part.begin(), part.end());
        std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
          return a.first > b.first ||
                 (a.first == b.first && a.second < b.second);
        });
        if (all.size() > settings.max_deletions)
          all.resize(settings.max_deletions);
        if (all.empty())
          return 0;
        for (const auto &c : all)
          deleted[c.second] = 1;
        n_deleted += all.size();
        // joints at a deleted cell go with it
        for (unsigned int i = 0; i < interfaces.size(); ++i)
          if (deleted[interfaces[i].cell_a] || deleted[interfaces[i].cell_b])
            face_deleted[i] = 1;
        // DOFs that no remaining cell holds stay where they are
        std::vector<char>                    used(dof_handler.n_dofs(), 0);
        std::vector<types::global_dof_index> dofs(24);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!deleted[cell->active_cell_index()])
            {
              cell->get_dof_indices(dofs);
              for (const auto i : dofs)
                used[i] = 1;
            }
        orphans.clear();
        for (types::global_dof_index i = 0; i < used.size(); ++i)
          if (!used[i])
            orphans.push_back(i);
        make_constraints();
        matrix_valid = solver_is_initial = brick_matrix_valid = false;
        return all.size();
      }

      std::vector<Segment>
      Model::make_protocol() const
      {
        std::vector<Segment> legs;
        if (settings.cycle_amplitudes.empty())
          legs.push_back({settings.target_displacement, false, 1});
        else
          {
            unsigned int cycle = 0;
            for (const double a : settings.cycle_amplitudes)
              for (unsigned int r = 0; r < settings.cycles_per_amplitude; ++r)
                {
                  ++cycle;
                  legs.push_back({a, false, cycle});
                  legs.push_back({0., true, cycle});
                }
          }
        return legs;
      }

      std::vector<Cycle>
      Model::cycle_results() const
      {
        std::vector<Cycle> cycles;
        for (unsigned int i = 1; i < curve.size(); ++i)
          {
            const CurvePoint &p = curve[i];
            if (cycles.empty() || cycles.back().cycle != p.cycle)
              {
                Cycle c;
                c.cycle = p.cycle;
                c.first = c.turn = i - 1;
                c.amplitude =
                  settings.cycle_amplitudes.empty() ?
                    settings.target_displacement / height :
                    settings.cycle_amplitudes[(p.cycle - 1) /
                                              settings.cycles_per_amplitude] /
                      height;
                cycles.push_back(c);
              }
            Cycle &c = cycles.back();
            c.last   = i;
            if (!p.unloading)
              c.turn = i;
            if (p.stress > c.peak_stress || c.first + 1 == i)
              {
                c.peak_stress    = p.stress;
                c.strain_at_peak = p.strain;
              }
          }
        for (auto &c : cycles)
          {
            const CurvePoint &turn = curve[c.turn], &end = curve[c.last];
            c.residual_strain = end.strain;
            c.unloading_modulus =
              c.last > c.turn && turn.strain != end.strain ?
                (turn.stress - end.stress) / (turn.strain - end.strain) :
                0.;
            // the loop's area: work per unit volume done on the wallette
            // from the start of the cycle to its end
            for (unsigned int i = c.first + 1; i <= c.last; ++i)
              c.dissipated_energy += 0.5 *
                                     (curve[i].stress + curve[i - 1].stress) *
                                     (curve[i].strain - curve[i - 1].strain);
          }
        return cycles;
      }

      void
      Model::append_curve(const bool header)
      {
        if (Utilities::MPI::this_mpi_process(comm) != 0)
          return;
        std::ofstream out(context.output.path() + "/curve.csv",
                          header ? std::ios::trunc : std::ios::app);
        out << std::setprecision(12);
        if (header)
          out << "step,displacement_m,strain,force_N,stress_Pa,"
                 "newton_iterations,max_damage,gauge_strain,cycle,unloading,"
                 "deleted_cells,brick_damage_tension,"
                 "brick_damage_compression\n";
        const unsigned int i = curve.size() - 1;
        const CurvePoint  &p = curve[i];
        out << i << "," << p.displacement << "," << p.strain << "," << p.force
            << "," << p.stress << "," << p.newton << "," << p.max_damage << ","
            << p.gauge_strain << "," << p.cycle << "," << p.unloading << ","
            << p.deleted << "," << p.brick_damage_t << "," << p.brick_damage_c
            << "\n";
      }

      void
      Model::save_checkpoint(const std::string &status) const
      {
        const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
        const std::string  name =
          context.output.path() + "/checkpoint." + std::to_string(rank);
        {
          std::ofstream                   out(name + ".tmp", std::ios::binary);
          boost::archive::binary_oarchive ar(out);
          const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
          const types::global_dof_index n_dofs = dof_handler.n_dofs();
          ar &n_ranks                  &n_dofs;
          // the joint states of the interfaces this rank assembles
          std::vector<InterfaceHistory> joint_old, joint_older;
          for (unsigned int n = 0; n < interfaces.size(); ++n)
            if (interfaces[n].owned)
              for (unsigned int q = 0; q < n_quad; ++q)
                {
                  joint_old.push_back(*joint[n].old[q]);
                  joint_older.push_back(*joint[n].older[q]);
                }
          ar &progress &curve &total_newton &total_cutbacks &n_solves &n_deleted
            &deleted &face_deleted &orphans &joint_old &joint_older;
          ar &implex_max_error &implex_over_tolerance &n_direct_fallbacks
            &krylov_abandoned &implex_rejected;
          std::vector<std::pair<types::global_dof_index, double>> values;
          for (const auto i : owned)
            values.emplace_back(i, u[i]);
          ar                     &values;
          std::vector<BrickState> states;
          if (!material.is_linear())
            for (const auto &cell : triangulation.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  for (const auto &state : states_old.get_data(cell))
                    states.push_back(*state);
                  for (const auto &state : states_older.get_data(cell))
                    states.push_back(*state);
                }
          ar         &states;
          std::string s = status;
          ar         &s;
        }
        // replace the old checkpoint only once the new one is complete
        std::filesystem::rename(name + ".tmp", name);
        context.output.file("checkpoint." + std::to_string(rank));
      }

      void
      Model::load_checkpoint()
      {
        const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
        const std::string  name =
          context.output.path() + "/checkpoint." + std::to_string(rank);
        std::ifstream in(name, std::ios::binary);
        AssertThrow(in,
                    ExcParameter("Resume",
                                 "no checkpoint " + name +
                                   " (run with `Checkpoint interval' or "
                                   "`Maximum steps' first, with the same "
                                   "output directory and number of ranks)"));
        try
          {
            boost::archive::binary_iarchive ar(in);
            unsigned int                    n_ranks;
            types::global_dof_index         n_dofs;
            ar &n_ranks                    &n_dofs;
            AssertThrow(n_ranks == Utilities::MPI::n_mpi_processes(comm) &&
                          n_dofs == dof_handler.n_dofs(),
                        ExcParameter("Resume",
                                     "the checkpoint was written by a run "
                                     "with " +
                                       std::to_string(n_ranks) + " ranks and " +
                                       std::to_string(n_dofs) +
                                       " DOFs; resume with the same "
                                       "parameters and number of ranks"));
            std::vector<InterfaceHistory> joint_old, joint_older;
            ar &progress &curve &total_newton &total_cutbacks &n_solves &
              n_deleted &deleted &face_deleted &orphans &joint_old &joint_older;
            ar &implex_max_error &implex_over_tolerance &n_direct_fallbacks
              &krylov_abandoned &implex_rejected;
            std::size_t          j = 0;
            for (unsigned int n = 0; n < interfaces.size(); ++n)
              if (interfaces[n].owned)
                for (unsigned int q = 0; q < n_quad; ++q, ++j)
                  {
                    AssertThrow(j < joint_old.size() && j < joint_older.size(),
                                ExcInternalError());
                    *joint[n].old[q] = *joint[n].updated[q] = joint_old[j];
                    *joint[n].older[q]                      = joint_older[j];
                  }
            std::vector<std::pair<types::global_dof_index, double>> values;
            ar                                                     &values;
            for (const auto &v : values)
              u[v.first] = v.second;
            u.compress(VectorOperation::insert);
            std::vector<BrickState> states;
            ar                     &states;
            unsigned int            k = 0;
            if (!material.is_linear())
              for (const auto &cell : triangulation.active_cell_iterators())
                if (cell->is_locally_owned())
                  {
                    const auto old   = states_old.get_data(cell);
                    const auto upd   = states_new.get_data(cell);
                    const auto older = states_older.get_data(cell);
                    AssertThrow(k + 16 <= states.size(), ExcInternalError());
                    for (unsigned int q = 0; q < 8; ++q)
                      *old[q] = *upd[q] = states[k++];
                    for (unsigned int q = 0; q < 8; ++q)
                      *older[q] = states[k++];
                  }
          }
        catch (const boost::archive::archive_exception &e)
          {
            AssertThrow(false,
                        ExcParameter("Resume",
                                     "the checkpoint " + name +
                                       " cannot be read (" + e.what() + ")"));
          }
        make_constraints();
      }

      void
      Model::run()
      {
        const auto start = Clock::now();
        make_mesh();
        setup_system();
        Json &summary         = context.summary;
        summary["n_bricks"]   = n_bricks;
        summary["n_cells"]    = triangulation.n_active_cells();
        summary["n_dofs"]     = dof_handler.n_dofs();
        summary["height"]     = height;
        summary["length"]     = length;
        summary["thickness"]  = thickness;
        summary["gross_area"] = gross_area;
        for (unsigned int t = 0; t < 3; ++t)
          {
            summary[std::string("n_") + type_name[t] + "_joints"] =
              n_joints_of_type[t];
            summary[std::string("n_") + type_name[t] + "_interface_faces"] =
              n_faces_of_type[t];
          }
        pcout << "Wallette: " << length << " x " << thickness << " x " << height
              << " m, " << n_bricks << " enlarged bricks, "
              << triangulation.n_active_cells() << " cells, "
              << dof_handler.n_dofs() << " DOFs\n"
              << "Joints (brick pairs / face pairs): bed "
              << n_joints_of_type[0] << " / " << n_faces_of_type[0] << ", head "
              << n_joints_of_type[1] << " / " << n_faces_of_type[1]
              << ", collar " << n_joints_of_type[2] << " / "
              << n_faces_of_type[2] << "\n";

        const std::vector<Segment> legs = make_protocol();
        const double               nominal =
          std::abs(settings.target_displacement / settings.n_steps);
        progress.increment = nominal;
        // IMPL-EX step control: the smallest step it asks for, and a step
        // shrunk in proportion to the damage error (to no less than a fifth)
        const double implex_floor = settings.implex_minimum_step * nominal;
        const auto   shrunk       = [&](const double step, const double error) {
          return step * std::max(0.2, 0.9 * settings.implex_tolerance / error);
        };
        if (settings.resume)
          {
            load_checkpoint();
            pcout << "Resumed from the checkpoint at step " << progress.step
                  << " (platen displacement " << progress.applied << " m)\n";
            // curve.csv anew, up to the checkpoint
            const std::vector<CurvePoint> all = curve;
            curve.clear();
            for (const auto &p : all)
              {
                curve.push_back(p);
                append_curve(curve.size() == 1);
              }
          }
        else
          {
            curve.push_back({0, 0, 0, 0, 0, 0, 0});
            append_curve(true);
            write_vtu(0, 0);
          }
        if (!legs.empty() && legs.size() > 1)
          pcout << "Protocol: " << legs.size() / 2
                << " load-unload cycles, unloading to "
                << settings.unloading_stress * 1e-6 << " MPa\n";

        unsigned int consecutive_cutbacks = 0, steps_this_run = 0;
        std::string  status = "completed", message;
        TrilinosWrappers::MPI::Vector u_converged(u);
        // along the direction: positive displacement is the loading sense
        while (progress.segment < legs.size())
          {
            const Segment &leg       = legs[progress.segment];
            double        &applied   = progress.applied;
            double        &increment = progress.increment;
            // the next platen position of this leg, or the end of the leg
            double next;
            if (!leg.unloading)
              {
                if (applied >= leg.target * (1 - 1e-12))
                  {
                    ++progress.segment;
                    continue;
                  }
                next = applied + increment;
                if (next > leg.target * (1 - 1e-9))
                  next = leg.target;
              }
            else
              {
                const CurvePoint &last = curve.back();
                // (the aimed last step may land a round-off above)
                if (last.stress <= settings.unloading_stress +
                                     1e-6 * std::abs(curve[1].stress) ||
                    applied <= leg.target + 1e-9 * nominal)
                  {
                    ++progress.segment;
                    increment = nominal;
                    continue;
                  }
                next = applied - increment;
                // aim at the unloading stress with the slope of the last
                // unloading step (elastic unloading is linear)
                const CurvePoint &before = curve[curve.size() - 2];
                if (last.unloading && last.displacement < before.displacement)
                  {
                    const double slope =
                      (before.stress - last.stress) /
                      (before.displacement - last.displacement);
                    if (slope > 0)
                      {
                        const double aim =
                          applied -
                          (last.stress - settings.unloading_stress) / slope;
                        if (aim > next - 1e-12 * nominal)
                          next = aim;
                      }
                  }
                next = std::max(next, leg.target);
                if (applied - next < 1e-9 * nominal)
                  {
                    ++progress.segment;
                    increment = nominal;
                    continue;
                  }
              }
            time_step = std::abs(next - applied) / settings.platen_speed;
            // IMPL-EX: no extrapolation across a reversal of the platen
            implex_ratio =
              progress.last_increment > 0 && curve.size() > 1 &&
                  curve.back().unloading == leg.unloading &&
                  curve.back().cycle == leg.cycle ?
                std::abs(next - applied) / progress.last_increment :
                0.;
            unsigned int its = 0;
            const bool   ok  = solve_step(next, its);
            total_newton += its;
            if (!ok)
              {
                u = u_converged;
                ++total_cutbacks;
                ++consecutive_cutbacks;
                if (consecutive_cutbacks > settings.max_cutbacks)
                  {
                    std::ostringstream m;
                    m << "no convergence at platen displacement " << next
                      << " m after " << settings.max_cutbacks
                      << " halvings of the step (last converged: " << applied
                      << " m); results up to there are written";
                    status  = "not converged";
                    message = m.str();
                    pcout << "Stopped: " << message << "\n";
                    break;
                  }
                increment /= 2;
                progress.easy_steps = 0;
                if (settings.progress)
                  pcout << "  cut-back: step halved to " << increment << " m\n";
                continue;
              }
            consecutive_cutbacks = 0;
            double implex_error  = 0;
            if (settings.implex)
              {
                implex_error = implex_update();
                // a step whose damage error is over the tolerance is redone
                // smaller, down to the floor: otherwise the first step that
                // re-enters the envelope (elastic, nothing to extrapolate
                // from) overshoots the cycle peak by up to E0 x the step
                const double taken = std::abs(next - applied);
                if (implex_error > settings.implex_tolerance &&
                    taken > implex_floor * (1 + 1e-12))
                  {
                    u = u_converged;
                    ++implex_rejected;
                    increment =
                      std::max(shrunk(taken, implex_error), implex_floor);
                    if (settings.progress)
                      pcout << "  IMPL-EX: step redone (damage error "
                            << implex_error << "), step " << increment
                            << " m\n";
                    continue;
                  }
                implex_max_error = std::max(implex_max_error, implex_error);
              }
            accept_step();
            progress.last_increment = std::abs(next - applied);
            u_converged             = u;
            progress.time += time_step;
            applied = next;
            ++progress.step;
            ++steps_this_run;
            const unsigned int removed = delete_cells();
            const double       force   = reaction();
            CurvePoint         p;
            p.displacement                               = applied;
            p.strain                                     = applied / height;
            p.force                                      = force;
            p.stress                                     = force / gross_area;
            p.newton                                     = its;
            p.max_damage                                 = max_damage();
            p.gauge_strain                               = 0;
            p.cycle                                      = leg.cycle;
            p.unloading                                  = leg.unloading;
            p.deleted                                    = n_deleted;
            std::tie(p.brick_damage_t, p.brick_damage_c) = max_brick_damage();
            if (gauge_span > 0)
              {
                ghosted = u;
                for (unsigned int d = 0; d < 3; ++d)
                  p.gauge_strain +=
                    (ghosted[gauge_dofs[1][d]] - ghosted[gauge_dofs[0][d]]) *
                    settings.direction[d] / gauge_span;
              }
            curve.push_back(p);
            append_curve(false);
            if (settings.progress)
              {
                pcout << "Step " << progress.step;
                if (legs.size() > 1)
                  pcout << " (cycle " << leg.cycle
                        << (leg.unloading ? ", unloading" : "") << ")";
                pcout << ": strain " << std::setprecision(4) << p.strain
                      << ", stress " << p.stress * 1e-6 << " MPa, max damage "
                      << p.max_damage;
                if (!material.is_linear())
                  pcout << ", bricks " << p.brick_damage_t << " / "
                        << p.brick_damage_c;
                pcout << ", " << its << " Newton iterations";
                if (removed > 0)
                  pcout << ", " << removed << " cells deleted";
                pcout << std::setprecision(6) << "\n";
              }
            const bool last = progress.segment + 1 == legs.size() &&
                              !leg.unloading &&
                              applied >= leg.target * (1 - 1e-12);
            if ((settings.vtu_interval > 0 &&
                 progress.step % settings.vtu_interval == 0) ||
                last)
              write_vtu(progress.step, p.strain);
            if (settings.implex)
              {
                // IMPL-EX step control on the damage error of the step
                if (implex_error > settings.implex_tolerance)
                  {
                    // accepted only at (or below) the floor: shrink, but
                    // not below the floor (and never raise a step that a
                    // cut-back made smaller still)
                    ++implex_over_tolerance;
                    increment = std::max(shrunk(increment, implex_error),
                                         std::min(increment, implex_floor));
                  }
                else if (implex_error < 0.5 * settings.implex_tolerance)
                  increment = std::min(increment * settings.growth, nominal);
              }
            else
              {
                // grow after two consecutive easy steps
                progress.easy_steps =
                  its <= std::max(2u, settings.max_newton / 3) ?
                    progress.easy_steps + 1 :
                    0;
                if (progress.easy_steps >= 2)
                  {
                    increment = std::min(increment * settings.growth, nominal);
                    progress.easy_steps = 0;
                  }
              }
            if (settings.checkpoint_interval > 0 &&
                progress.step % settings.checkpoint_interval == 0)
              save_checkpoint("running");
            if (settings.max_steps > 0 &&
                steps_this_run >= settings.max_steps &&
                progress.segment < legs.size())
              {
                // the run's last leg may just have ended
                const bool done =
                  progress.segment + 1 == legs.size() &&
                  (leg.unloading ? p.stress <= settings.unloading_stress :
                                   applied >= leg.target * (1 - 1e-12));
                if (!done)
                  {
                    status  = "interrupted";
                    message = "stopped after `Maximum steps' = " +
                              std::to_string(settings.max_steps) +
                              " steps; `set Resume = true' continues from "
                              "the checkpoint";
                    pcout << "Stopped: " << message << "\n";
                    break;
                  }
              }
          }
        if (status != "completed")
          {
            u = u_converged;
            save_checkpoint(status);
            if (settings.write_vtu)
              write_vtu(progress.step, curve.back().strain);
          }
        write_curve(summary);
        if (settings.write_calculix)
          write_calculix();
        const double seconds =
          std::chrono::duration<double>(Clock::now() - start).count();
        summary["status"] = status;
        if (!message.empty())
          summary["message"] = message;
        summary["steps"]                   = progress.step;
        summary["newton_iterations"]       = total_newton;
        summary["cut_backs"]               = total_cutbacks;
        summary["linear_solves"]           = n_solves;
        summary["matrix_assemblies"]       = n_matrix_assemblies;
        summary["factorisations_reused"]   = n_factorisations_reused;
        summary["deleted_cells"]           = n_deleted;
        summary["direct_solver_fallbacks"] = n_direct_fallbacks;
        if (settings.implex)
          {
            summary["implex_max_damage_error"]     = implex_max_error;
            summary["implex_steps_over_tolerance"] = implex_over_tolerance;
            summary["implex_steps_redone"]         = implex_rejected;
          }
        // share of the evaluations skipped by the elastic check, over all
        // ranks (work skipped where nothing can change)
        const auto elastic_fraction = [&](const unsigned long elastic,
                                          const unsigned long evaluated) {
          const double e   = Utilities::MPI::sum(double(elastic), comm),
                       all = e + Utilities::MPI::sum(double(evaluated), comm);
          return all > 0 ? e / all : 0.;
        };
        if (!material.is_linear())
          summary["cell_evaluations_elastic_fraction"] =
            elastic_fraction(n_elastic_cells, n_material_cells);
        if (!law.is_linear())
          summary["interface_evaluations_elastic_fraction"] =
            elastic_fraction(n_elastic_interfaces, n_law_interfaces);
        summary["seconds"]          = seconds;
        summary["seconds_assembly"] = seconds_assembly;
        summary["seconds_solve"]    = seconds_solve;
        pcout << "Result: peak stress " << std::setprecision(6)
              << summary["peak_stress"].as_number() * 1e-6 << " MPa at strain "
              << summary["strain_at_peak"].as_number() << ", initial modulus "
              << summary["initial_modulus"].as_number() * 1e-9 << " GPa; "
              << progress.step << " steps, " << total_newton
              << " Newton iterations, " << total_cutbacks << " cut-backs";
        if (n_deleted > 0)
          pcout << ", " << n_deleted << " cells deleted";
        pcout << "\n";
      }
    } // namespace

    void
    run_wallette(const std::vector<Box> &boxes,
                 const BrickMaterial    &material,
                 const InterfaceLaw     &law,
                 const WalletteSettings &settings,
                 RunContext             &context)
    {
      check_mesh(boxes, settings);
      Model model(boxes, material, law, settings, context);
      model.run();
    }
  } // namespace brickwork
} // namespace masonry
