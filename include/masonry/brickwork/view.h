/**
 * @file
 * The read-only view of a wallette model that postprocessors get (ASPECT's
 * SimulatorAccess): the settings, the output directory, the laws, the curve,
 * the mesh, the DoF handler and the solution, the joints, the cells'
 * regions and deletions, and the point states by name. This header is
 * public and light: the deal.II objects are only declared here (include
 * their deal.II headers where you use them) and the model's own parts
 * (System, Specimen, ...) stay private: every output uses the functions
 * below. The built-in outputs (source/brickwork/postprocess/) include only
 * installed headers, so each is a template for one of your own;
 * contrib/examples/wallette_field is one built out of tree that writes a
 * cell field.
 */
#ifndef masonry_brickwork_view_h
#define masonry_brickwork_view_h

#include <masonry/brickwork/curve.h>
#include <masonry/brickwork/joint_faces.h>
#include <masonry/brickwork/law_set.h>
#include <masonry/brickwork/state.h>
#include <masonry/core/run_context.h>

#include <string>
#include <vector>

// the deal.II 9.4 declarations of these classes (a deal.II with C++20
// constraints on them needs its own headers here instead)
namespace dealii
{
  template <int rank, int dim, typename Number>
  class SymmetricTensor;
  template <int dim, int spacedim>
  class Triangulation;
  template <int dim, int spacedim>
  class DoFHandler;
  namespace TrilinosWrappers
  {
    namespace MPI
    {
      class Vector;
    } // namespace MPI
  }   // namespace TrilinosWrappers
} // namespace dealii

namespace masonry
{
  namespace brickwork
  {
    class BrickMaterial;
    class InterfaceLaw;
    class Protocol;
    struct Platen;
    struct OutputSettings;
    struct WalletteSettings;
    namespace model
    {
      struct Geometry;
      class System;
      struct Joints;
      struct Specimen;
      class InterfaceElement;
      struct LawStates;
      class StepController;
    } // namespace model

    /** What a postprocessor may read of a wallette run. */
    struct ModelView
    {
      /** The settings of the run (`subsection Wallette'; a private type:
       * an output reads them through output_settings(), deletes_cells(),
       * fades_cells(), has_regions() and top_platen()). */
      const WalletteSettings &settings;
      /** The output directory, the MPI communicator, summary.json. */
      RunContext &context;
      /** The laws: one per cell region (units; the mortar of the detailed
       * model) and one per joint type (bed, head and collar share one; the
       * splitting interfaces through the units have their own). */
      const LawSet &laws;
      /** The loading protocol (include <masonry/brickwork/protocol.h>). */
      const Protocol &protocol;
      /** One point per converged step so far (the initial state first). */
      const std::vector<CurvePoint> &curve;

      /** The joints and splitting interfaces: one InterfaceFace per pair of
       * coincident cell faces (type, normal axis, vertices, area, cells);
       * the joint points of face pair n are 4 n + q. */
      const model::Joints &joints;

      /** @name The parts of the model (private headers in
       * source/brickwork/specimen, assembly and solution: for the model's
       * own report and for tests; an output uses the functions below) */
      /** @{ */
      const model::Geometry         &geometry;
      const model::System           &system;
      const model::Specimen         &specimen;
      const model::InterfaceElement &element;
      /** The states of the laws' points (brick points 8 c + q by region,
       * joint points 4 n + q by the law of their type). */
      const model::LawStates      &states;
      const model::StepController &controller;
      /** @} */

      /** Whether this is the process that writes the serial files. */
      bool
      is_root() const;

      /** Converged steps so far. */
      unsigned int
      step() const;

      /** Height (m) and gross area (m^2, length x thickness) of the
       * wallette: strain = displacement / height, stress = force / area. */
      double
      height() const;
      double
      gross_area() const;

      /**
       * Number of brick points (8 per cell, the Gauss points of cell c are
       * 8 c + q) and their converged states, in the layout of the
       * state_variables() of the law of the cell's region,
       * brick_law_of(c) (empty for a linear law). Only the points of the
       * cells this process owns are current.
       */
      unsigned int
      n_brick_points() const;
      ConstStateView
      brick_state(const unsigned int point) const;
      /** The law of cell @p c (that of its region). */
      const BrickMaterial &
      brick_law_of(const unsigned int c) const;

      /**
       * Number of joint points (4 per face pair n: 4 n + q, splitting
       * interfaces included) and their converged states, in the layout of
       * the state_variables() of the law of the face's type,
       * joint_law_of(n). Only the points of the face pairs this process
       * owns are current.
       */
      unsigned int
      n_joint_points() const;
      ConstStateView
      joint_state(const unsigned int point) const;
      /** The law of face pair @p n (that of its type). */
      const InterfaceLaw &
      joint_law_of(const unsigned int n) const;

      /** The output entries of the run (`Output format', ...). */
      const OutputSettings &
      output_settings() const;

      /**
       * @name The mesh and the solution, as deal.II objects (include
       * <deal.II/distributed/shared_tria.h>, <deal.II/dofs/dof_handler.h>
       * and <deal.II/lac/trilinos_vector.h> to use them)
       */
      /** @{ */
      /** The hexahedra of the units (and of the mortar in the detailed
       * model), shared by every rank; cell c is active_cell_index() c. */
      const dealii::Triangulation<3, 3> &
      triangulation() const;
      /** The displacement DoFs (FESystem of three Q1 components, m). */
      const dealii::DoFHandler<3, 3> &
      dof_handler() const;
      /** The converged displacements (m) of the present step, with every
       * entry this rank's cells need (a ghosted copy: DataOut, FEValues'
       * get_function_values and similar read it directly). Collective:
       * call it on every rank. */
      dealii::TrilinosWrappers::MPI::Vector
      solution() const;
      /** @} */

      /**
       * @name The cells (by active_cell_index()) and the point states by
       * name
       */
      /** @{ */
      /** The region of cell @p c: 0 unit, 1 mortar (detailed model). */
      unsigned int
      cell_region(const unsigned int c) const;
      /** Whether cell @p c has been deleted (it carries nothing). */
      bool
      cell_deleted(const unsigned int c) const;
      /** The factor (0..1) on the stress of cell @p c while it fades out
       * before its deletion; 1 without fading. */
      double
      cell_fade(const unsigned int c) const;
      /** Whether cells may be deleted in this run (`Deletion strain' > 0). */
      bool
      deletes_cells() const;
      /** Whether cells fade out before their deletion (`Deletion fade
       * opening' or `Deletion crushing length' > 0 with deletion on). */
      bool
      fades_cells() const;
      /** Whether the cells have regions (the detailed model: units and
       * mortar). */
      bool
      has_regions() const;
      /** The cells deleted so far, in the order they went. */
      const std::vector<DeletedCell> &
      deletions() const;
      /** Whether the joint face pair @p n (joints.faces[n]) has been
       * deleted with a cell on either side. */
      bool
      joint_face_deleted(const unsigned int n) const;
      /** The top platen as the protocol holds it: its nodes, their DoFs,
       * its direction and whether it holds the face laterally (include
       * <masonry/brickwork/protocol.h> to use it). */
      const Platen &
      top_platen() const;

      /**
       * The stress (Pa) of brick point @p q of cell @p c at the strain
       * @p eps from its converged state, with the cell's strength factor,
       * crack-band length and region: the stress the step left, without the
       * cell's fade (what solution_NNNN.vtu averages and the deletion
       * reads). Call it with deal.II limited to one thread (OneThread,
       * <masonry/brickwork/one_thread.h>) if the strains come from FEValues,
       * so that the values do not depend on `Assembly threads'.
       */
      dealii::SymmetricTensor<2, 3, double>
      brick_stress(const unsigned int                           c,
                   const unsigned int                           q,
                   const dealii::SymmetricTensor<2, 3, double> &eps) const;

      /**
       * The position of the state variable @p name in the state of the law
       * of cell region @p region (its state_variables()): its first double
       * in brick_state(p) of the cells of that region. Throws an error
       * naming @p name and the variables there are if the law has no such
       * variable.
       */
      unsigned int
      brick_state_index(const std::string &name,
                        const unsigned int region = unit_region) const;
      /** The same for the law of joint type @p type (InterfaceFace::type;
       * joint_state(p) of the faces of that type). */
      unsigned int
      joint_state_index(const std::string &name,
                        const unsigned int type = 0) const;
      /** @} */
    };
  } // namespace brickwork
} // namespace masonry

#endif
