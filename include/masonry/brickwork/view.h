/**
 * @file
 * The read-only view of a wallette model that postprocessors get (ASPECT's
 * SimulatorAccess): the settings, the output directory, the laws, the curve
 * and the point states. This header is public and light: the parts of the
 * model (mesh, DoFs, joints, ...) are only declared here; the built-in
 * postprocessors include their private headers, a postprocessor in a shared
 * library uses the functions below.
 */
#ifndef masonry_brickwork_view_h
#define masonry_brickwork_view_h

#include <masonry/brickwork/curve.h>
#include <masonry/brickwork/state.h>
#include <masonry/core/run_context.h>

#include <vector>

namespace masonry
{
  namespace brickwork
  {
    class BrickMaterial;
    class InterfaceLaw;
    class Protocol;
    struct WalletteSettings;
    namespace model
    {
      struct Geometry;
      class System;
      struct Joints;
      struct Specimen;
      class InterfaceElement;
      class PointStates;
      class StepController;
    } // namespace model

    /** What a postprocessor may read of a wallette run. */
    struct ModelView
    {
      /** The settings of the run (`subsection Wallette'). */
      const WalletteSettings &settings;
      /** The output directory, the MPI communicator, summary.json. */
      RunContext &context;
      /** The laws of the bricks and of the joints. */
      const BrickMaterial &material;
      const InterfaceLaw  &law;
      /** One point per converged step so far (the initial state first). */
      const std::vector<CurvePoint> &curve;

      /** @name The parts of the model (private headers in
       * source/brickwork/specimen, assembly and solution) */
      /** @{ */
      const model::Geometry         &geometry;
      const model::System           &system;
      const model::Joints           &joints;
      const model::Specimen         &specimen;
      const model::InterfaceElement &element;
      /** Brick points (8 c + q) and joint points (4 n + q). */
      const model::PointStates &bricks;
      const model::PointStates &joint_points;
      /** The law of the splitting interfaces through the units (nullptr:
       * none) and their points (4 per face pair, as the joints). */
      const InterfaceLaw          *splitting_law;
      const model::PointStates    &splitting_points;
      const Protocol              &protocol;
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
       * 8 c + q) and their converged states, in the layout of the brick
       * material's state_variables() (empty for a linear material). Only
       * the points of the cells this process owns are current.
       */
      unsigned int
      n_brick_points() const;
      ConstStateView
      brick_state(const unsigned int point) const;

      /**
       * Number of joint points (4 per face pair n: 4 n + q) and their
       * converged states, in the layout of the interface law's
       * state_variables(). Only the points of the face pairs this process
       * owns are current.
       */
      unsigned int
      n_joint_points() const;
      ConstStateView
      joint_state(const unsigned int point) const;
    };
  } // namespace brickwork
} // namespace masonry

#endif
