/**
 * @file
 * The functions of the public model view.
 */
#include <deal.II/base/mpi.h>

#include "view.h"

#include <algorithm>

#include "../solution/deletion.h"

namespace masonry
{
  namespace brickwork
  {
    namespace
    {
      /** The first double of the state variable @p name among
       * @p variables; an error names @p name, @p whose law and the
       * variables there are. */
      unsigned int
      state_index(const std::vector<StateVariable> &variables,
                  const std::string                &name,
                  const std::string                &whose)
      {
        unsigned int index = 0;
        std::string  names;
        for (const StateVariable &v : variables)
          {
            if (v.name == name)
              return index;
            index += v.n_components;
            names += (names.empty() ? "" : ", ") + v.name;
          }
        AssertThrow(false,
                    dealii::ExcMessage(
                      "model view: the " + whose + " has no state variable `" +
                      name + "' (it has: " +
                      (names.empty() ? std::string("none") : names) + ")"));
        return 0;
      }
    } // namespace

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
      return 8 * system.triangulation.n_active_cells();
    }

    ConstStateView
    ModelView::brick_state(const unsigned int point) const
    {
      return states.bricks[cell_region(point / 8)].old(point);
    }

    const BrickMaterial &
    ModelView::brick_law_of(const unsigned int c) const
    {
      return laws.brick_law(cell_region(c));
    }

    unsigned int
    ModelView::n_joint_points() const
    {
      return model::joint_face_points * joints.faces.size();
    }

    ConstStateView
    ModelView::joint_state(const unsigned int point) const
    {
      const unsigned int n = point / model::joint_face_points;
      return states.joints[laws.slot_of_type(joints.faces[n].type)].old(point);
    }

    const InterfaceLaw &
    ModelView::joint_law_of(const unsigned int n) const
    {
      return laws.joint_law(joints.faces[n].type);
    }

    const dealii::Triangulation<3, 3> &
    ModelView::triangulation() const
    {
      return system.triangulation;
    }

    const dealii::DoFHandler<3, 3> &
    ModelView::dof_handler() const
    {
      return system.dof_handler;
    }

    dealii::TrilinosWrappers::MPI::Vector
    ModelView::solution() const
    {
      return system.ghosted_copy();
    }

    unsigned int
    ModelView::cell_region(const unsigned int c) const
    {
      return specimen.cell_region.empty() ? 0 : specimen.cell_region[c];
    }

    bool
    ModelView::cell_deleted(const unsigned int c) const
    {
      return specimen.deleted[c];
    }

    double
    ModelView::cell_fade(const unsigned int c) const
    {
      return specimen.fade[c];
    }

    bool
    ModelView::deletes_cells() const
    {
      return settings.deletion.deletion_strain > 0;
    }

    bool
    ModelView::fades_cells() const
    {
      return deletes_cells() &&
             (settings.deletion.deletion_fade_opening > 0 ||
              settings.deletion.deletion_crushing_length > 0);
    }

    bool
    ModelView::has_regions() const
    {
      return settings.mesh.detailed;
    }

    const OutputSettings &
    ModelView::output_settings() const
    {
      return settings.output;
    }

    dealii::SymmetricTensor<2, 3, double>
    ModelView::brick_stress(
      const unsigned int                           c,
      const unsigned int                           q,
      const dealii::SymmetricTensor<2, 3, double> &eps) const
    {
      return model::converged_stress(laws, eps, states, specimen, c, q);
    }

    const std::vector<DeletedCell> &
    ModelView::deletions() const
    {
      return specimen.deletions;
    }

    bool
    ModelView::joint_face_deleted(const unsigned int n) const
    {
      return specimen.face_deleted[n];
    }

    const Platen &
    ModelView::top_platen() const
    {
      return system.top;
    }

    unsigned int
    ModelView::brick_state_index(const std::string &name,
                                 const unsigned int region) const
    {
      AssertThrow(region < laws.n_regions(),
                  dealii::ExcMessage(
                    "model view: the wallette has no cell region " +
                    std::to_string(region) + " (it has " +
                    std::to_string(laws.n_regions()) +
                    ": 0 units, 1 mortar of the detailed model)"));
      return state_index(laws.brick_law(region).state_variables(),
                         name,
                         "law of `" + laws.region(region).entry + "'");
    }

    unsigned int
    ModelView::joint_state_index(const std::string &name,
                                 const unsigned int type) const
    {
      const auto &entry = laws.joint(laws.slot_of_type(type));
      return state_index(entry.law->state_variables(),
                         name,
                         "law of `" + entry.entry + "'");
    }
  } // namespace brickwork
} // namespace masonry
