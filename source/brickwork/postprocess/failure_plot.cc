/**
 * @file
 * failure.png: the wallette at the end of the run, deformed (magnified
 * displacements), with the cells coloured by their damage, the deleted cells
 * marked and the open joints drawn, in two views: the front face (x-z) and a
 * vertical section across the thickness (y-z), where the collar joints of
 * double and triple walls show. The model's data go into failure.json; the
 * installed script contrib/plot/wallette_failure.py (matplotlib, run with
 * /usr/bin/python3) draws the picture from it.
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/scripts.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/patterns.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      using namespace dealii;

      namespace
      {
        /** Values per cell in the gathered list: deleted, damage, then
         * per vertex x, y, z, u_x, u_y, u_z. */
        constexpr unsigned int cell_size = 2 + 8 * 6;
        /** Values per open joint face: type, axis, opening, then per
         * vertex x, y, z and the mean displacement of its two sides. */
        constexpr unsigned int face_size = 3 + 4 * 6;

        class FailurePlot : public Postprocessor
        {
        public:
          static void
          declare_parameters(ParameterHandler &prm)
          {
            prm.declare_entry(
              "Displacement magnification",
              "0",
              Patterns::Double(0),
              "Factor on the displacements of the deformed wallette "
              "(dimensionless, >= 0); 0: automatic, the factor that makes "
              "the largest displacement a tenth of the wallette's height. "
              "The factor used is written on the picture and into "
              "summary.json (failure_plot).");
            prm.declare_entry(
              "Opening threshold",
              "1e-4",
              Patterns::Double(0),
              "A joint face (bed, head, collar or splitting interface) is "
              "drawn as open when the normal opening at its centre (the "
              "`normal_opening' of interfaces.pvd) exceeds this, m.");
            prm.declare_entry("Width",
                              "1600",
                              Patterns::Integer(200, 8000),
                              "Width of failure.png, pixels.");
            prm.declare_entry("Height",
                              "800",
                              Patterns::Integer(200, 8000),
                              "Height of failure.png, pixels.");
          }

          void
          parse_parameters(ParameterHandler &prm) override
          {
            magnification = prm.get_double("Displacement magnification");
            threshold     = prm.get_double("Opening threshold");
            width         = prm.get_integer("Width");
            height        = prm.get_integer("Height");
          }

          void
          finish(const ModelView &view, Json &summary) override;

        private:
          /**
           * The cells (cell_size values each) and the open joint faces
           * (face_size values each) of every rank, gathered on the root;
           * false on the other ranks, which have nothing more to do.
           */
          bool
          gather(const ModelView     &view,
                 std::vector<double> &cells,
                 std::vector<double> &faces) const;

          /** failure.json: the picture's data, for wallette_failure.py and
           * the user; @p factor: the displacement magnification used. */
          void
          write_data(const ModelView           &view,
                     const std::vector<double> &cells,
                     const std::vector<double> &faces,
                     const double               factor) const;

          double       magnification = 0;
          double       threshold     = 1e-4;
          unsigned int width = 1600, height = 800;
        };

        bool
        FailurePlot::gather(const ModelView     &view,
                            std::vector<double> &cells,
                            std::vector<double> &faces) const
        {
          const TrilinosWrappers::MPI::Vector u = view.solution();
          const MPI_Comm comm                   = view.context.mpi_communicator;
          // this rank's cells and open faces
          std::vector<double> damage;
          for (const auto &cell : view.dof_handler().active_cell_iterators())
            if (cell->is_locally_owned())
              {
                const unsigned int   c        = cell->active_cell_index();
                const BrickMaterial &material = view.brick_law_of(c);
                damage.resize(
                  material.is_linear() ? 0 : material.damage_names().size());
                cells.push_back(view.cell_deleted(c));
                // mean over the cell's points of the largest damage of the
                // law of its region
                double d = 0;
                if (!damage.empty())
                  for (unsigned int q = 0; q < 8; ++q)
                    {
                      material.damages(view.brick_state(8 * c + q), damage);
                      d += *std::max_element(damage.begin(), damage.end()) / 8;
                    }
                cells.push_back(d);
                for (const unsigned int v : cell->vertex_indices())
                  {
                    for (unsigned int k = 0; k < 3; ++k)
                      cells.push_back(cell->vertex(v)[k]);
                    for (unsigned int k = 0; k < 3; ++k)
                      cells.push_back(u[cell->vertex_dof_index(v, k)]);
                  }
              }
          const auto &all = view.joints.faces;
          for (unsigned int i = 0; i < all.size(); ++i)
            if (all[i].owned && !view.joint_face_deleted(i))
              {
                const auto  &face = all[i];
                Tensor<1, 3> jump;
                for (unsigned int v = 0; v < 4; ++v)
                  for (unsigned int k = 0; k < 3; ++k)
                    jump[k] += 0.25 * (u[face.dofs[12 + 3 * v + k]] -
                                       u[face.dofs[3 * v + k]]);
                if (!(jump[face.axis] > threshold))
                  continue;
                faces.insert(faces.end(),
                             {double(face.type),
                              double(face.axis),
                              jump[face.axis]});
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    for (unsigned int k = 0; k < 3; ++k)
                      faces.push_back(face.vertices[v][k]);
                    for (unsigned int k = 0; k < 3; ++k)
                      faces.push_back(0.5 * (u[face.dofs[3 * v + k]] +
                                             u[face.dofs[12 + 3 * v + k]]));
                  }
              }
          const auto all_cells = Utilities::MPI::gather(comm, cells, 0);
          const auto all_faces = Utilities::MPI::gather(comm, faces, 0);
          if (Utilities::MPI::this_mpi_process(comm) != 0)
            return false;
          cells.clear();
          faces.clear();
          for (const auto &c : all_cells)
            cells.insert(cells.end(), c.begin(), c.end());
          for (const auto &f : all_faces)
            faces.insert(faces.end(), f.begin(), f.end());
          return true;
        }

        void
        FailurePlot::write_data(const ModelView           &view,
                                const std::vector<double> &cells,
                                const std::vector<double> &faces,
                                const double               factor) const
        {
          const std::vector<std::string> names =
            view.laws.bricks_linear() ? std::vector<std::string>() :
                                        view.laws.brick_damage_names();
          const unsigned int n_damage = names.size();
          const unsigned int n_cells  = cells.size() / cell_size;
          const unsigned int n_open   = faces.size() / face_size;
          const CurvePoint  &last     = view.curve.back();
          // the picture's data, for wallette_failure.py and the user
          Json data                 = Json::object();
          data["width"]             = width;
          data["height"]            = height;
          data["magnification"]     = factor;
          data["opening_threshold"] = threshold;
          data["strain"]            = last.strain;
          data["stress"]            = last.stress;
          std::string damage        = n_damage > 0 ? "largest of " : "none";
          for (unsigned int k = 0; k < n_damage; ++k)
            damage += (k ? ", " : "") + names[k];
          data["damage"] = damage;
          Json rows      = Json::array();
          for (unsigned int c = 0; c < n_cells; ++c)
            rows.push_back(
              std::vector<double>(cells.begin() + c * cell_size,
                                  cells.begin() + (c + 1) * cell_size));
          data["cells"] = std::move(rows);
          rows          = Json::array();
          for (unsigned int f = 0; f < n_open; ++f)
            rows.push_back(
              std::vector<double>(faces.begin() + f * face_size,
                                  faces.begin() + (f + 1) * face_size));
          data["joints"] = std::move(rows);
          OutputFile out(view.context.output.file("failure.json"));
          out << data.dump(1) << "\n";
          out.close();
        }

        void
        FailurePlot::finish(const ModelView &view, Json &summary)
        {
          std::vector<double> cells, faces;
          if (!gather(view, cells, faces))
            return;

          // automatic factor: the largest displacement of a remaining cell
          // becomes a tenth of the height
          double largest = 0;
          for (std::size_t c = 0; c < cells.size(); c += cell_size)
            if (cells[c] == 0)
              for (unsigned int v = 0; v < 8; ++v)
                {
                  const double *x = &cells[c + 2 + 6 * v];
                  largest         = std::max(largest,
                                     std::sqrt(x[3] * x[3] + x[4] * x[4] +
                                               x[5] * x[5]));
                }
          const double       factor    = magnification > 0 ? magnification :
                                         largest > 0 ? 0.1 * view.height() / largest :
                                                       1.0;
          const unsigned int n_open    = faces.size() / face_size;
          unsigned int       n_deleted = 0, n_damaged = 0;
          for (std::size_t c = 0; c < cells.size(); c += cell_size)
            {
              n_deleted += cells[c] != 0;
              n_damaged += cells[c] == 0 && cells[c + 1] > 0.5;
            }
          std::array<unsigned int, 4> open_of_type{{0, 0, 0, 0}};
          for (std::size_t f = 0; f < faces.size(); f += face_size)
            ++open_of_type[std::min<unsigned int>(faces[f], 3)];

          write_data(view, cells, faces, factor);

          Json &s                         = summary["failure_plot"];
          s["displacement_magnification"] = factor;
          s["opening_threshold"]          = threshold;
          s["open_joints"]                = double(n_open);
          for (unsigned int t = 0; t < 4; ++t)
            s["open_joints_" + std::string(model::joint_type_name[t])] =
              double(open_of_type[t]);
          s["deleted_cells"]          = double(n_deleted);
          s["cells_damage_over_half"] = double(n_damaged);

          const std::string why =
            run_script("wallette_failure.py",
                       {view.context.output.path()},
                       {view.context.output.path() + "failure.png"});
          if (why.empty()) // named as a file of the run only once drawn
            view.context.output.file("failure.png");
          else
            {
              std::filesystem::remove(view.context.output.path() +
                                      "failure.png");
              view.context.pcout << "Warning: failure.png could not be drawn ("
                                 << why << "); its data are in failure.json\n";
            }
        }
      } // namespace

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  masonry::brickwork::postprocess::FailurePlot,
  "failure plot",
  "failure.png at the end of the run: the deformed wallette (displacements times `Displacement magnification'), cells coloured by their damage (the mean over the cell's points of the largest damage variable of the brick material), deleted cells marked with a cross, and the joint faces whose normal opening exceeds `Opening threshold' drawn by type, in two views: the front face (x-z) and a vertical section across the thickness at 45 % of the length (y-z), where collar joints show. Its data are in failure.json; the counts (open joints by type, deleted cells, cells with damage over 0.5) and the factor go into summary.json (failure_plot). Drawn by the installed script wallette_failure.py with /usr/bin/python3 and matplotlib. Not in the default list: add it to `List of postprocessors'.")
