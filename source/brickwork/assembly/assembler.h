/**
 * @file
 * Assembly of the internal forces and the tangent: bricks (8-point Gauss
 * hexahedra) and joints (interface elements), with the elastic caches that
 * skip the laws where nothing can change.
 */
#ifndef masonry_brickwork_model_assembler_h
#define masonry_brickwork_model_assembler_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/law_set.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <map>
#include <string>

#include "../specimen/joints.h"
#include "../specimen/specimen.h"
#include "crs_adder.h"
#include "integrator.h"
#include "interface_element.h"
#include "nonlocal.h"
#include "point_states.h"
#include "system.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The threads of the assemblies (`Assembly threads'). */
      struct AssemblySettings
      {
        /** Threads per MPI rank that evaluate the laws of the cells and
         * interfaces in an assembly (0: deal.II's default, the cores
         * divided among the ranks). */
        unsigned int threads = 1;

        /** Declare the entry in the present subsection. */
        static void
        declare_parameters(dealii::ParameterHandler &prm);
        /** Read it. */
        void
        parse_parameters(dealii::ParameterHandler &prm);
      };

      /** Work counters of the assemblies (summary.json). */
      struct AssemblyStatistics
      {
        /** Cells evaluated by the material / by their elastic matrix
         * (work skipped where nothing can change). */
        unsigned long n_material_cells = 0, n_elastic_cells = 0;
        /** The same for the interfaces. */
        unsigned long n_law_interfaces = 0, n_elastic_interfaces = 0;
        /** Tangent matrices assembled. */
        unsigned int n_matrix_assemblies = 0;
        /** Wall time in assemblies, s. */
        double seconds = 0;
      };

      /** The parts an assembly reads and the states it writes. */
      struct AssemblyParts
      {
        System           &system;
        const Joints     &joints;
        const Specimen   &specimen;
        const LawSet     &laws;
        const Integrator &integrator;
        /** The states of the laws' points: brick points 8 c + q, joint
         * points 4 n + q (LawStates). */
        LawStates &states;

        /** The region of cell @p c. */
        unsigned int
        region_of(const unsigned int c) const
        {
          return specimen.cell_region[c];
        }
        /** The law of cell @p c. */
        const BrickMaterial &
        brick_law(const unsigned int c) const
        {
          return laws.brick_law(region_of(c));
        }
        /** The point states of cell @p c. */
        PointStates &
        brick_states(const unsigned int c) const
        {
          return states.bricks[region_of(c)];
        }
        /** The law of face @p n. */
        const InterfaceLaw &
        law_of(const unsigned int n) const
        {
          return laws.joint_law(joints.faces[n].type);
        }
        /** The point states of face @p n. */
        PointStates &
        states_of(const unsigned int n) const
        {
          return states.joints[laws.slot_of_type(joints.faces[n].type)];
        }
      };

      /** The interfaces this rank assembles: owned and not deleted. */
      std::vector<unsigned int>
      active_faces(const AssemblyParts &parts);

      /** Assembles forces and tangents; keeps the elastic caches. */
      class Assembler
      {
      public:
        /** Interface points from @p gauss; @p spacing: the mesh spacing
         * along x, m (scale of the diagonal of orphan DOFs). */
        Assembler(const AssemblyParts &parts,
                  const bool           gauss,
                  const double         spacing);

        /** The elastic matrices of the cells (one per cell shape) and the
         * interfaces (one per normal axis and area). */
        void
        make_elastic_caches();

        /**
         * Internal forces at the solution into system.f_int; the tangent
         * into system.matrix when @p need_matrix (a linear model keeps the
         * one it assembled first). Brick and joint laws are evaluated at
         * the pseudo-time increment @p time_step, s.
         */
        void
        assemble(const bool need_matrix, const double time_step);

        /**
         * The implicit update of every point at the solution (after a step,
         * when the integrator asks for it: Integrator::updates_after_step());
         * the largest difference between the updated and the extrapolated
         * damages of the laws (Integrator::extrapolated()), NaN where a
         * number is not finite (non_finite() says where).
         */
        double
        update_states(const double time_step);

        /** The units' nonlocal factors of the last update_states() (per
         * brick point: tensile, compressive; empty: local). */
        const std::array<std::vector<double>, 2> &
        nonlocal_factors() const
        {
          return rho;
        }

        /** Cells were deleted: the kept matrices are no longer valid. */
        void
        invalidate();

        /** Whether the last assembly gave the initial (elastic) tangent. */
        bool
        initial_tangent() const
        {
          return is_initial;
        }

        /**
         * Where the last assemble() or update_states() met a number that is
         * not finite (the same on every rank): "" when nowhere, else "the
         * stresses of the bricks", "the tractions of the joints", "the
         * damages of the bricks" or "the damages of the joints".
         */
        std::string
        non_finite() const;

        /** The interface element (jumps and local matrices). */
        const InterfaceElement &
        element() const
        {
          return interface_element;
        }

        AssemblyStatistics statistics;

      private:
        void
        assemble_bricks(const bool   with_matrix,
                        const bool   bricks_assembled,
                        const double time_step);
        /**
         * What a cell's assembly needs of the finite element at its 8 Gauss
         * points: the gradient of the nonzero component of each shape
         * function and JxW. The mesh does not move, so it is computed once
         * (make_elastic_caches()), one copy for the cells whose values are
         * the same bit for bit.
         */
        struct CellGeometry
        {
          std::array<std::array<dealii::Tensor<1, 3>, 24>, 8> grad;
          std::array<double, 8>                               JxW;
        };
        /** The strains at the Gauss points of a cell from its DoF values
         * @p ue, summed as deal.II sums symmetric gradients (the same
         * numbers bit for bit). */
        void
        cell_strains(
          const CellGeometry                           &geometry,
          const dealii::Vector<double>                 &ue,
          std::array<dealii::SymmetricTensor<2, 3>, 8> &strain) const;
        /** One brick cell's force and tangent from its point responses. */
        void
        brick_cell(const CellGeometry                                 &geometry,
                   const std::array<dealii::SymmetricTensor<2, 3>, 8> &strain,
                   const unsigned int                                  c,
                   const BrickPoint                                   &point,
                   const bool                  with_matrix,
                   dealii::Vector<double>     &fe_local,
                   dealii::FullMatrix<double> &ke);
        void
        assemble_joints(const bool with_matrix, const double time_step);
        /** The per-cell BrickPoint of cell @p c. */
        BrickPoint
        brick_point(const unsigned int c, const double time_step) const;

        /** The units' factors of the nonlocal average at system.ghosted
         * into rho (`Nonlocal length' > 0; the average is built at the
         * first call). */
        void
        update_nonlocal_factors();
        /** The brick points' new states at system.ghosted (@p time_step:
         * the pseudo-time step); returns the largest change of a damage
         * against its extrapolation (non-finite changes are flagged in
         * non_finite_bits instead). */
        double
        update_brick_states(const double time_step);
        /** The same for the points of the joints. */
        double
        update_joint_states(const double time_step);

        /** Combines the ranks' non_finite_bits (collective). */
        void
        gather_non_finite();

        AssemblyParts    parts;
        InterfaceElement interface_element;
        /** The units' nonlocal average (`Nonlocal length' > 0; built at
         * the first update_states()). */
        std::unique_ptr<NonlocalAverage> nonlocal;
        /** Its factors at the last update_states(). */
        std::array<std::vector<double>, 2> rho;
        /** Non-finite numbers met in the last assembly or update, bits:
         * bricks' stresses, joints' tractions, bricks' damages, joints'
         * damages. */
        unsigned int non_finite_bits = 0;
        double       spacing;
        bool         is_initial = false;
        /** A linear model's matrix is assembled once (until deletions). */
        bool matrix_valid = false;
        /** Elastic bricks with nonlinear joints: the bricks' part of the
         * matrix, assembled once (until deletions). */
        dealii::TrilinosWrappers::SparseMatrix brick_matrix;
        bool                                   brick_matrix_valid = false;
        /** Cell matrices of the elastic bricks, by cell shape. */
        std::map<std::vector<long>, dealii::FullMatrix<double>> cell_matrices;
        std::vector<const dealii::FullMatrix<double> *>         matrix_of_cell;
        /** The geometries of the cells (index by active cell). */
        std::vector<CellGeometry> geometries;
        std::vector<unsigned int> geometry_of_cell;
        /** The nonzero component of each shape function. */
        std::array<unsigned int, 24> component;
        /** Elastic matrices of the interfaces, by (axis, area). */
        std::map<std::pair<unsigned int, long>, dealii::FullMatrix<double>>
                                                        interface_matrices;
        std::vector<const dealii::FullMatrix<double> *> matrix_of_interface;
        /** Sums the element matrices into the tangent. */
        CrsAdder adder;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
