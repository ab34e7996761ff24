/**
 * @file
 * The joint fields: one quadrilateral per face pair with the quantities the
 * interface law reports (averaged over the face's points), the normal
 * opening and the slip at its centre (m) and the joint type, as a VTU time
 * series (interfaces.pvd) or, with `Output format = hdf5', HDF5 + XDMF
 * (interfaces.xdmf).
 */
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/vtu_grid.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <iomanip>
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
        /** interfaces.pvd and interfaces_NNNN.vtu, or interfaces.xdmf and
         * interfaces_NNNN.h5. */
        class JointFields : public Postprocessor
        {
        public:
          static void
          declare_parameters(dealii::ParameterHandler &)
          {}

          void
          output(const ModelView   &view,
                 const unsigned int step,
                 const double       time) override;

          std::string
          save() const override
          {
            std::ostringstream out;
            out << std::setprecision(17);
            for (const auto &entry : steps)
              out << entry.first << " " << entry.second << "\n";
            return out.str();
          }

          void
          load(const std::string &data) override
          {
            steps.clear();
            std::istringstream in(data);
            double             time;
            std::string        file;
            while (in >> time >> file)
              steps.emplace_back(time, file);
          }

        private:
          /** Per face: the reported quantities, then opening, slip and
           * type, summed over the ranks. */
          std::vector<std::vector<double>>
          face_values(const ModelView          &view,
                      std::vector<std::string> &names) const;

          /** The steps written: (time, file). */
          std::vector<std::pair<double, std::string>> steps;
        };

        std::vector<std::vector<double>>
        JointFields::face_values(const ModelView          &view,
                                 std::vector<std::string> &names) const
        {
          const auto        &faces  = view.joints.faces;
          const unsigned int n      = faces.size();
          const unsigned int n_quad = model::joint_face_points;
          const LawSet      &laws   = view.laws;
          // the quantities of each joint law, with its prefix (zero on the
          // faces of the other laws)
          names.clear();
          std::vector<unsigned int> first_reported;
          for (unsigned int slot = 0; slot < laws.n_joint_laws(); ++slot)
            {
              first_reported.push_back(names.size());
              for (const auto &name :
                   laws.joint(slot).law->reported_quantities())
                names.push_back(laws.joint(slot).prefix + name);
            }
          const unsigned int n_reported = names.size();
          const bool         split = laws.has_joint_law(model::splitting_type);
          names.insert(names.end(),
                       {"normal_opening",
                        "slip",
                        split ? "joint_type_bed0_head1_collar2_splitting3" :
                                "joint_type_bed0_head1_collar2"});
          std::vector<std::vector<double>>    values(names.size(),
                                                  std::vector<double>(n, 0));
          const TrilinosWrappers::MPI::Vector ghosted = view.solution();
          std::vector<double>                 reported;
          for (unsigned int i = 0; i < n; ++i)
            if (faces[i].owned)
              {
                const auto         &face = faces[i];
                const unsigned int  a    = face.axis;
                const InterfaceLaw &law  = view.joint_law_of(i);
                const unsigned int  first =
                  first_reported[laws.slot_of_type(face.type)];
                reported.resize(law.reported_quantities().size());
                for (unsigned int q = 0; q < n_quad; ++q)
                  {
                    law.report(view.joint_state(n_quad * i + q), reported);
                    for (unsigned int k = 0; k < reported.size(); ++k)
                      values[first + k][i] += reported[k] / n_quad;
                  }
                // opening at the centre of the face
                Tensor<1, 3> jump;
                for (unsigned int v = 0; v < 4; ++v)
                  for (unsigned int d = 0; d < 3; ++d)
                    jump[d] += 0.25 * (ghosted[face.dofs[12 + 3 * v + d]] -
                                       ghosted[face.dofs[3 * v + d]]);
                values[n_reported][i] = jump[a];
                values[n_reported + 1][i] =
                  std::hypot(jump[(a + 1) % 3], jump[(a + 2) % 3]);
              }
          for (unsigned int k = 0; k < n_reported + 2; ++k)
            MPI_Allreduce(MPI_IN_PLACE,
                          values[k].data(),
                          n,
                          MPI_DOUBLE,
                          MPI_SUM,
                          view.context.mpi_communicator);
          for (unsigned int i = 0; i < n; ++i)
            values.back()[i] = faces[i].type;
          return values;
        }

        void
        JointFields::output(const ModelView   &view,
                            const unsigned int step,
                            const double       time)
        {
          std::vector<std::string>               names;
          const std::vector<std::vector<double>> values =
            face_values(view, names);
          const bool        hdf5 = view.output_settings().hdf5;
          const std::string name = "interfaces_" +
                                   Utilities::int_to_string(step, 4) +
                                   (hdf5 ? ".h5" : ".vtu");
          const std::string file = view.context.output.file(name);
          if (steps.empty() || steps.back().second != name)
            steps.emplace_back(time, name);
          if (Utilities::MPI::this_mpi_process(view.context.mpi_communicator) !=
              0)
            return;
          // one quadrilateral per face pair, the values as cell data
          const auto &faces = view.joints.faces;
          VtuGrid     grid;
          grid.nodes_per_cell         = 4;
          grid.cell_type              = 9;
          const unsigned int order[4] = {0, 1, 3, 2};
          for (const auto &face : faces)
            for (unsigned int v = 0; v < 4; ++v)
              {
                grid.connectivity.push_back(grid.points.size());
                grid.points.push_back(face.vertices[order[v]]);
              }
          for (unsigned int k = 0; k < names.size(); ++k)
            grid.cell_data.emplace_back(names[k], values[k]);
          if (hdf5)
            {
              grid.write_hdf5(file);
              // the joints and their quantities are the same every step,
              // so the grid describes the earlier steps' files too (a
              // resumed run lists the whole run)
              std::vector<std::string> grids;
              for (const auto &[t, h5] : steps)
                if (h5.size() > 3 && h5.substr(h5.size() - 3) == ".h5")
                  grids.push_back(grid.xdmf_grid(h5, t));
              OutputFile xdmf(view.context.output.file("interfaces.xdmf"));
              write_xdmf_series(xdmf, grids);
              xdmf.close();
              return;
            }
          OutputFile out(file);
          grid.write(out);
          out.close();
          std::vector<std::pair<double, std::string>> vtu;
          for (const auto &entry : steps)
            if (entry.second.size() > 4 &&
                entry.second.substr(entry.second.size() - 4) == ".vtu")
              vtu.push_back(entry);
          OutputFile pvd_out(view.context.output.file("interfaces.pvd"));
          DataOutBase::write_pvd_record(pvd_out, vtu);
          pvd_out.close();
        }
      } // namespace

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  masonry::brickwork::postprocess::JointFields,
  "joint fields",
  "The joints every `Output interval' steps: one quadrilateral per face pair with the quantities the interface law reports, the normal opening and the slip at its centre (m) and the joint type, as interfaces.pvd with interfaces_NNNN.vtu, or with `Output format = hdf5' as interfaces.xdmf with interfaces_NNNN.h5 (double precision). A resumed run lists the steps of the whole run.")
