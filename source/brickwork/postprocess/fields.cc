/**
 * @file
 * The brick fields: displacement (m), cell-averaged stress (Pa), the
 * quantities the brick material reports, MPI subdomain and deleted cells, as
 * a VTU/PVTU time series (solution.pvd) or HDF5 + XDMF (solution.xdmf).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/one_thread.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_out.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      using namespace dealii;

      namespace
      {
        /** solution.pvd / solution.xdmf and their files. */
        class Fields : public Postprocessor
        {
        public:
          static void
          declare_parameters(dealii::ParameterHandler &)
          {}

          void
          output(const ModelView   &view,
                 const unsigned int step,
                 const double       time) override;

          /** The lists of output steps, so that solution.pvd and
           * solution.xdmf of a resumed run list the whole run. */
          std::string
          save() const override
          {
            std::ostringstream out;
            {
              boost::archive::text_oarchive ar(out);
              ar << pvd << xdmf;
            }
            return out.str();
          }

          void
          load(const std::string &data) override
          {
            std::istringstream            in(data);
            boost::archive::text_iarchive ar(in);
            ar >> pvd >> xdmf;
          }

        private:
          /** Cell fields from the converged states, added to @p data_out
           * (the vectors must live until the patches are built). */
          void
          cell_fields(const ModelView                     &view,
                      const TrilinosWrappers::MPI::Vector &ghosted,
                      std::vector<Vector<float>>          &fields,
                      std::vector<std::string>            &names) const;

          void
          write_hdf5(const ModelView   &view,
                     DataOut<3>        &data_out,
                     const unsigned int step,
                     const double       time);

          void
          write_vtu(const ModelView   &view,
                    DataOut<3>        &data_out,
                    const unsigned int step,
                    const double       time);

          /** The steps written: (time, file). */
          std::vector<std::pair<double, std::string>> pvd;
          /** The steps of solution.xdmf (`Output format = hdf5'). */
          std::vector<XDMFEntry> xdmf;
        };

        void
        Fields::cell_fields(const ModelView                     &view,
                            const TrilinosWrappers::MPI::Vector &ghosted,
                            std::vector<Vector<float>>          &fields,
                            std::vector<std::string>            &names) const
        {
          const LawSet      &laws    = view.laws;
          const unsigned int n_cells = view.triangulation().n_active_cells();
          names                      = {"stress_xx",
                                        "stress_yy",
                                        "stress_zz",
                                        "stress_xy",
                                        "stress_yz",
                                        "stress_xz",
                                        "subdomain"};
          // the quantities each region's law reports, with the region's
          // prefix (0 in the cells of the other regions)
          std::vector<unsigned int> first_reported, n_reported;
          for (unsigned int r = 0; r < laws.n_regions(); ++r)
            {
              first_reported.push_back(names.size());
              const BrickMaterial &law = laws.brick_law(r);
              if (!law.is_linear())
                for (const auto &name : law.reported_quantities())
                  names.push_back(laws.region(r).prefix + name);
              n_reported.push_back(names.size() - first_reported.back());
            }
          const bool fading = view.fades_cells();
          if (fading)
            names.emplace_back("fade");
          if (view.deletes_cells())
            names.emplace_back("deleted");
          // the detailed model: 0 unit, 1 mortar
          const bool regions = view.has_regions();
          if (regions)
            names.emplace_back("region");
          fields.assign(names.size(), Vector<float>(n_cells));
          // the strains as the assembly and the deletion compute them
          // (FEValues' reuse of translated cells' values): the fields do not
          // change with `Assembly threads'
          const OneThread one_thread;
          QGauss<3>       quadrature(2);
          FEValues<3>     fe_values(view.dof_handler().get_fe(),
                                quadrature,
                                update_gradients);
          std::vector<SymmetricTensor<2, 3>> eps(8);
          const FEValuesExtractors::Vector   displacement(0);
          std::vector<double>                values;
          for (const auto &cell : view.dof_handler().active_cell_iterators())
            if (cell->is_locally_owned())
              {
                const unsigned int c = cell->active_cell_index();
                fields[6][c]         = cell->subdomain_id();
                if (regions)
                  fields.back()[c] = view.cell_region(c);
                if (view.deletes_cells())
                  fields[names.size() - 1 - regions][c] = view.cell_deleted(c);
                if (fading)
                  fields[names.size() - 2 - regions][c] =
                    view.cell_deleted(c) ? 0. : view.cell_fade(c);
                if (view.cell_deleted(c))
                  continue;
                fe_values.reinit(cell);
                fe_values[displacement].get_function_symmetric_gradients(
                  ghosted, eps);
                const unsigned int   r     = view.cell_region(c);
                const BrickMaterial &law   = laws.brick_law(r);
                const unsigned int   first = first_reported[r];
                values.resize(n_reported[r]);
                SymmetricTensor<2, 3> mean;
                for (unsigned int q = 0; q < 8; ++q)
                  {
                    // the stress the step left (the deletion reads the
                    // same)
                    mean +=
                      view.cell_fade(c) * view.brick_stress(c, q, eps[q]) / 8;
                    if (!law.is_linear())
                      {
                        law.report(view.brick_state(8 * c + q), values);
                        for (unsigned int k = 0; k < values.size(); ++k)
                          fields[first + k][c] += values[k] / 8;
                      }
                  }
                const unsigned int ij[6][2] = {
                  {0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
                for (unsigned int k = 0; k < 6; ++k)
                  fields[k][c] = mean[ij[k][0]][ij[k][1]];
              }
        }

        void
        Fields::output(const ModelView   &view,
                       const unsigned int step,
                       const double       time)
        {
          const TrilinosWrappers::MPI::Vector ghosted = view.solution();
          DataOut<3>                          data_out;
          data_out.attach_dof_handler(view.dof_handler());
          std::vector<std::string> names(3, "displacement");
          std::vector<DataComponentInterpretation::DataComponentInterpretation>
            interpretation(
              3, DataComponentInterpretation::component_is_part_of_vector);
          data_out.add_data_vector(ghosted,
                                   names,
                                   DataOut<3>::type_dof_data,
                                   interpretation);
          // stress (Pa) and the reported quantities averaged over the
          // cell's quadrature points, from the converged states
          std::vector<Vector<float>> fields;
          std::vector<std::string>   field_names;
          cell_fields(view, ghosted, fields, field_names);
          for (unsigned int k = 0; k < fields.size(); ++k)
            data_out.add_data_vector(fields[k], field_names[k]);
          data_out.build_patches();
          if (view.output_settings().hdf5)
            write_hdf5(view, data_out, step, time);
          else
            write_vtu(view, data_out, step, time);
        }

        void
        Fields::write_hdf5(const ModelView   &view,
                           DataOut<3>        &data_out,
                           const unsigned int step,
                           const double       time)
        {
          // mesh and fields of this step in one HDF5 file, written by all
          // ranks; solution.xdmf lists the steps with their times
          const MPI_Comm             comm = view.context.mpi_communicator;
          const std::string          dir  = view.context.output.path();
          DataOutBase::DataOutFilter filter(
            DataOutBase::DataOutFilterFlags(false, true));
          data_out.write_filtered_data(filter);
          const std::string h5 =
            "solution_" + Utilities::int_to_string(step, 4) + ".h5";
          // written by all ranks under one temporary name (rank 0's),
          // renamed by rank 0 once every rank has returned
          const std::string temporary =
            Utilities::MPI::broadcast(comm, temporary_file_name(dir + h5), 0);
          std::string error;
          try
            {
              data_out.write_hdf5_parallel(filter, temporary, comm);
            }
          catch (const std::exception &)
            {
              error = write_error(dir + h5,
                                  likely_write_reason(dir,
                                                      "the HDF5 library "
                                                      "failed"));
            }
          if (!error.empty() && Utilities::MPI::this_mpi_process(comm) == 0)
            std::remove(temporary.c_str());
          throw_if_any_rank_failed(error, comm);
          if (Utilities::MPI::this_mpi_process(comm) == 0 &&
              std::rename(temporary.c_str(), (dir + h5).c_str()) != 0)
            error = write_error(dir + h5, std::strerror(errno));
          throw_if_any_rank_failed(error, comm);
          const XDMFEntry entry =
            data_out.create_xdmf_entry(filter, h5, time, comm);
          if (!pvd.empty() && pvd.back().second == h5)
            xdmf.back() = entry;
          else
            {
              xdmf.push_back(entry);
              pvd.emplace_back(time, h5);
            }
          // solution.xdmf (rank 0 writes it) is replaced whole
          const std::string xdmf_name = dir + "solution.xdmf";
          const std::string xdmf_temporary =
            Utilities::MPI::broadcast(comm, temporary_file_name(xdmf_name), 0);
          error.clear();
          try
            {
              data_out.write_xdmf_file(xdmf, xdmf_temporary, comm);
              if (Utilities::MPI::this_mpi_process(comm) == 0 &&
                  std::rename(xdmf_temporary.c_str(), xdmf_name.c_str()) != 0)
                error = write_error(xdmf_name, std::strerror(errno));
            }
          catch (const std::exception &)
            {
              error = write_error(xdmf_name,
                                  likely_write_reason(dir, "an I/O error"));
              std::remove(xdmf_temporary.c_str());
            }
          throw_if_any_rank_failed(error, comm);
          view.context.output.file(h5);
          view.context.output.file("solution.xdmf");
        }

        void
        Fields::write_vtu(const ModelView   &view,
                          DataOut<3>        &data_out,
                          const unsigned int step,
                          const double       time)
        {
          const MPI_Comm    comm = view.context.mpi_communicator;
          const std::string dir  = view.context.output.path();
          // each rank its piece, rank 0 the record; every file under a
          // temporary name until it is whole (as write_vtu_with_pvtu_record
          // names them)
          const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
          const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
          const std::string  stem =
            "solution_" + Utilities::int_to_string(step, 4);
          const auto piece = [&](const unsigned int r) {
            return stem + "." +
                   Utilities::int_to_string(r,
                                            Utilities::needed_digits(n_ranks -
                                                                     1)) +
                   ".vtu";
          };
          const std::string pvtu = stem + ".pvtu";
          std::string       error;
          try
            {
              OutputFile out(dir + piece(rank));
              data_out.write_vtu(out);
              out.close();
              if (rank == 0)
                {
                  std::vector<std::string> pieces;
                  for (unsigned int r = 0; r < n_ranks; ++r)
                    pieces.push_back(piece(r));
                  OutputFile record(dir + pvtu);
                  data_out.write_pvtu_record(record, pieces);
                  record.close();
                }
            }
          catch (const std::exception &exc)
            {
              error = one_line_message(exc);
            }
          throw_if_any_rank_failed(error, comm);
          // the last state of a stopped run may repeat the last output step
          if (pvd.empty() || pvd.back().second != pvtu)
            pvd.emplace_back(time, pvtu);
          // record the files written
          view.context.output.file(pvtu);
          for (unsigned int r = 0; r < n_ranks; ++r)
            view.context.output.file(piece(r));
          if (rank == 0)
            {
              OutputFile out(view.context.output.file("solution.pvd"));
              DataOutBase::write_pvd_record(out, pvd);
              out.close();
            }
        }
      } // namespace

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  masonry::brickwork::postprocess::Fields,
  "fields",
  "The brick fields every `Output interval' steps: displacement (m), cell stresses (Pa), MPI subdomain, the cell averages of the quantities the brick material reports and the deleted cells, as solution.pvd with solution_NNNN.pvtu/.vtu, or with `Output format = hdf5' as solution.xdmf with solution_NNNN.h5. A resumed run lists the steps of the whole run.")
