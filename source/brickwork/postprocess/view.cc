/**
 * @file
 * The functions of the public model view.
 */
#include <deal.II/base/mpi.h>

#include "view.h"

namespace masonry
{
  namespace brickwork
  {
    bool
    ModelView::is_root() const
    {
      return dealii::Utilities::MPI::this_mpi_process(
               context.mpi_communicator) == 0;
    }

    unsigned int
    ModelView::step() const
    {
      return controller.n_steps();
    }

    double
    ModelView::height() const
    {
      return geometry.height;
    }

    double
    ModelView::gross_area() const
    {
      return geometry.gross_area;
    }

    unsigned int
    ModelView::n_brick_points() const
    {
      return bricks.n_points();
    }

    ConstStateView
    ModelView::brick_state(const unsigned int point) const
    {
      return bricks.old(point);
    }

    unsigned int
    ModelView::n_joint_points() const
    {
      return joint_points.n_points();
    }

    ConstStateView
    ModelView::joint_state(const unsigned int point) const
    {
      return joint_points.old(point);
    }
  } // namespace brickwork
} // namespace masonry
