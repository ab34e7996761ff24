/**
 * @file
 * A read-only view of a wallette model for the postprocessors: the
 * settings, the mesh, the solution, the point states, the laws and the
 * curve. Postprocessors get this instead of the step loop.
 */
#ifndef masonry_brickwork_model_view_h
#define masonry_brickwork_model_view_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/wallette.h>
#include <masonry/core/run_context.h>

#include "curve.h"
#include "interface_element.h"
#include "joints.h"
#include "mesh.h"
#include "point_states.h"
#include "specimen.h"
#include "step_control.h"
#include "system.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** What a postprocessor may read. */
      struct ModelView
      {
        const WalletteSettings &settings;
        RunContext             &context;
        const Geometry         &geometry;
        const System           &system;
        const Joints           &joints;
        const Specimen         &specimen;
        const BrickMaterial    &material;
        const InterfaceLaw     &law;
        const InterfaceElement &element;
        /** Brick points (8 c + q) and joint points (4 n + q). */
        const PointStates &bricks;
        const PointStates &joint_points;
        /** The splitting interfaces' law (nullptr: none) and points. */
        const InterfaceLaw            *splitting_law;
        const PointStates             &splitting_points;
        const Protocol                &protocol;
        const std::vector<CurvePoint> &curve;
        const Progress                &progress;

        /** The solution with every entry on every rank. */
        System::Vector
        ghosted_solution() const
        {
          System::Vector v(system.owned, system.relevant, system.comm);
          v = system.u;
          return v;
        }
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
