/**
 * @file
 * A field output added to masonry's wallette analysis from outside: the
 * postprocessor `cell strain` writes, at every output step, a VTU file set
 * (one piece per MPI rank and a .pvtu record) of the wallette's cells with the
 * strain averaged over each cell's eight Gauss points (three normal components,
 * -), the cell's region and whether it has been deleted, and optionally the
 * cell average of one state variable of the brick material, chosen by name. It
 * reads the run through the public model view only: the mesh, the DoF handler
 * and the solution as deal.II objects, the cells' regions and deletions, the
 * point states by name. Start a field output of your own from here.
 */
#include <masonry/brickwork/postprocessor.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <stdexcept>

namespace
{
  using namespace masonry::brickwork;

  class CellStrain : public postprocess::Postprocessor
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("File prefix",
                        "cell_strain",
                        dealii::Patterns::FileName(),
                        "The files, in the output directory: PREFIX_NNNN.pvtu "
                        "and its pieces PREFIX_NNNN.R.vtu (R the MPI rank), "
                        "NNNN the step.");
      prm.declare_entry(
        "State variable",
        "",
        dealii::Patterns::Anything(),
        "A state variable of the brick material (its first component) to "
        "average over each unit cell as well, by the name the material "
        "declares (e.g. damage_tension of the damage-plasticity law; 0 in "
        "the mortar cells of the detailed model, whose law is another); "
        "empty: none.");
    }

    void
    parse_parameters(dealii::ParameterHandler &prm) override
    {
      prefix   = prm.get("File prefix");
      variable = prm.get("State variable");
    }

    /** The state variable's name is checked before the first step. */
    void
    start(const ModelView &view) override
    {
      find_variable(view);
    }

    void
    resume(const ModelView &view) override
    {
      find_variable(view);
    }

    void
    output(const ModelView   &view,
           const unsigned int step,
           const double) override
    {
      using namespace dealii;
      const bool                          with_state = !variable.empty();
      const DoFHandler<3, 3>             &dofs       = view.dof_handler();
      const TrilinosWrappers::MPI::Vector u          = view.solution();
      const unsigned int n_cells = view.triangulation().n_active_cells();
      std::vector<Vector<float>> strain(3, Vector<float>(n_cells));
      Vector<float> region(n_cells), deleted(n_cells), state(n_cells);

      const QGauss<3> gauss(2);
      FEValues<3>     fe_values(dofs.get_fe(), gauss, update_gradients);
      const FEValuesExtractors::Vector   displacement(0);
      std::vector<SymmetricTensor<2, 3>> eps(gauss.size());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int c = cell->active_cell_index();
            region[c]            = view.cell_region(c);
            deleted[c]           = view.cell_deleted(c);
            fe_values.reinit(cell);
            fe_values[displacement].get_function_symmetric_gradients(u, eps);
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                for (unsigned int d = 0; d < 3; ++d)
                  strain[d][c] += eps[q][d][d] / gauss.size();
                // brick point 8 c + q holds the state of Gauss point q, in
                // the layout of the law of the cell's region
                if (with_state && region[c] == masonry::brickwork::unit_region)
                  state[c] += view.brick_state(8 * c + q)[index] / 8;
              }
          }

      DataOut<3> data_out;
      data_out.attach_triangulation(view.triangulation());
      const char *names[3] = {"strain_xx", "strain_yy", "strain_zz"};
      for (unsigned int d = 0; d < 3; ++d)
        data_out.add_data_vector(strain[d], names[d]);
      data_out.add_data_vector(region, "region");
      data_out.add_data_vector(deleted, "deleted");
      if (with_state)
        data_out.add_data_vector(state, variable);
      data_out.build_patches();
      // each rank writes its own cells (PREFIX_NNNN.R.vtu), rank 0 the
      // record PREFIX_NNNN.pvtu that ParaView opens; the files are named in
      // summary.json
      const MPI_Comm    comm = view.context.mpi_communicator;
      const std::string pvtu = data_out.write_vtu_with_pvtu_record(
        view.context.output.path(), prefix, step, comm, 4);
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      view.context.output.file(pvtu);
      for (unsigned int r = 0; r < n_ranks; ++r)
        view.context.output.file(
          prefix + "_" + Utilities::int_to_string(step, 4) + "." +
          Utilities::int_to_string(r, Utilities::needed_digits(n_ranks - 1)) +
          ".vtu");
    }

  private:
    std::string prefix, variable;
    /** The position of `State variable' in a brick point's state. */
    unsigned int index = 0;

    /** The point states by name: a name the material does not declare
     * stops the run with an error naming the entry and the variables the
     * material has. */
    void
    find_variable(const ModelView &view)
    {
      if (variable.empty())
        return;
      try
        {
          index = view.brick_state_index(variable);
        }
      catch (const std::exception &e)
        {
          throw std::runtime_error(
            "Postprocess/Wallette/Cell strain/State variable = " + variable +
            ": " + masonry::one_line_message(e));
        }
    }
  };
} // namespace

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  CellStrain,
  "cell strain",
  "PREFIX_NNNN.pvtu (`File prefix') at every output step: the cells' strain "
  "averaged over their Gauss points (xx, yy, zz, -), region (0 unit, 1 "
  "mortar), deleted (0/1) and, with `State variable', the cell average of "
  "that state variable of the brick material (units only).")
