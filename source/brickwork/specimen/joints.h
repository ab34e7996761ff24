/**
 * @file
 * The joints of a wallette: pairs of coincident cell faces of two bricks.
 */
#ifndef masonry_brickwork_model_joints_h
#define masonry_brickwork_model_joints_h

#include <masonry/brickwork/joint_faces.h>

#include <deal.II/dofs/dof_handler.h>


namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /**
       * The coincident boundary faces of different cells of
       * @p dof_handler (those on z = 0 and z = @p height are the platens').
       */
      Joints
      find_joints(const dealii::DoFHandler<3> &dof_handler,
                  const double                 height);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
