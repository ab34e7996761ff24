/**
 * @file
 * The linear-algebra system of the wallette: DoFs, the platen conditions
 * (the bottom platen's here, the top platen's from the protocol, and the
 * nodes left without a cell by deletions), the sparse matrix, the solution
 * and internal-force vectors, the platen reaction and the gauge.
 */
#ifndef masonry_brickwork_model_system_h
#define masonry_brickwork_model_system_h

#include <masonry/brickwork/protocol.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include "../specimen/joints.h"
#include "../specimen/mesh.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The platens and the gauge (`Platen lateral restraint', `Platen
       * direction', `Gauge length'). */
      struct PlatenSettings
      {
        /** Platens hold the wall faces laterally (true) or let them slide. */
        bool lateral_fixed = false;
        /** Unit direction of the top platen's motion. */
        std::array<double, 3> direction = {{0, 0, -1}};
        /**
         * Length of a virtual LVDT on the front face (y = 0) at mid-length,
         * centred at mid-height (m); 0: no gauge.
         */
        double gauge_length = 0;

        /** Declare the entries in the present subsection. */
        static void
        declare_parameters(dealii::ParameterHandler &prm);
        /** Read them; errors name the entry. */
        void
        parse_parameters(dealii::ParameterHandler &prm);
      };

      /** DoFs, constraints, matrix and vectors of one wallette. */
      class System
      {
      public:
        using Vector = dealii::TrilinosWrappers::MPI::Vector;

        System(const dealii::parallel::shared::Triangulation<3> &tria,
               MPI_Comm                                          comm);

        /** Number the DoFs (before the joints are found). */
        void
        distribute_dofs();

        /**
         * Platen conditions (the top platen held and moved by
         * @p protocol), the gauge, the sparsity of bricks and @p joints, the
         * matrix and vectors. @p gauss: the joints' integration points;
         * with Lobatto points (the nodes) a joint couples each node only
         * with the node facing it, so only those pairs are in the sparsity.
         */
        void
        setup(const Joints         &joints,
              const Geometry       &geometry,
              const PlatenSettings &platen,
              const bool            gauss,
              const Protocol       &protocol);

        /** The constraints of the increments: the platens' and @p orphans
         * (the DOFs in no remaining cell). */
        void
        make_constraints();

        /** The residual @p r with the constraints applied (constrained
         * entries zeroed; a slave's entry added to its masters first). */
        void
        condense(Vector &r) const;

        /** The increment @p du made to satisfy the constraints. */
        void
        distribute(Vector &du) const;

        /** A copy of the solution with every relevant entry on this rank
         * (for readers of a const System: the postprocessors). */
        Vector
        ghosted_copy() const
        {
          Vector v(owned, relevant, comm);
          v = u;
          return v;
        }

        /** The platen displacement @p disp (m, along the direction) into
         * the top platen's entries of @p v (Protocol::move_platen()). */
        void
        set_platen(Vector &v, const double disp) const;

        /** The platen force along the direction from @p f_int, N. */
        double
        reaction() const;

        /** Strain of the gauge (0 without one) at the solution u. */
        double
        gauge_strain();

        /** Copy u into the ghosted vector (every entry on every rank). */
        const Vector &
        ghosted_solution();

        MPI_Comm                                          comm;
        const dealii::parallel::shared::Triangulation<3> &triangulation;
        dealii::FESystem<3>                               fe;
        dealii::DoFHandler<3>                             dof_handler;
        dealii::IndexSet                                  owned, relevant;
        dealii::AffineConstraints<double>                 zero_constraints;
        dealii::TrilinosWrappers::SparseMatrix            matrix;
        /** Owned vectors; `ghosted` holds every entry on every rank. */
        Vector u, f_int, ghosted;
        /** Displacement increment of the last converged step (the
         * extrapolated predictor; zero after a reversal or a deletion). */
        Vector last_increment;
        /** DOFs held by the bottom platen; DOFs in no remaining cell. */
        std::vector<dealii::types::global_dof_index> platen_lines, orphans;
        /** Top platen DOFs with their components: (dof, component). */
        std::vector<std::pair<dealii::types::global_dof_index, unsigned int>>
          top_dofs;
        /** The top platen and its conditions (from the protocol). */
        Platen                            top;
        dealii::AffineConstraints<double> top_constraints;
        /** The protocol that holds and moves the top platen. */
        const Protocol *protocol = nullptr;
        /** Whether every constraint is a fixed DoF (no slaves). */
        bool only_fixed = true;
        /** DOFs of the two gauge points and their distance (0: none). */
        std::array<std::array<dealii::types::global_dof_index, 3>, 2>
               gauge_dofs;
        double gauge_span = 0;
        /** Direction of the platen's motion. */
        std::array<double, 3> direction{{0, 0, -1}};
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
