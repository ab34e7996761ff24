/**
 * @file
 * Postprocessor `report`: report.html, the page of a rigid-block run.
 */
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/report_page.h>
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch.h>
#include <masonry/rigid_blocks/postprocess/crack_map.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      namespace
      {
        /**
         * JSON text of the page's data, written directly: the arrays of
         * coordinates are large and need 7 significant digits, not the
         * 17 of summary.json.
         */
        class DataText
        {
        public:
          /** Start the member @p key of the open object. */
          DataText &
          key(const std::string &k)
          {
            separate();
            text << '"' << k << "\":";
            first = true;
            return *this;
          }

          /** A number (7 significant digits). */
          DataText &
          number(const double x)
          {
            separate();
            char buffer[32];
            std::snprintf(buffer,
                          sizeof buffer,
                          "%.7g",
                          std::isfinite(x) ? x : 0.);
            text << buffer;
            return *this;
          }

          /** A JSON value given as text (a string, true, ...). */
          DataText &
          raw(const std::string &json)
          {
            separate();
            text << json;
            return *this;
          }

          /** A string. */
          DataText &
          string(const std::string &s)
          {
            return raw(Json(s).dump(0));
          }

          /** Open an object or array. */
          DataText &
          open(const char bracket)
          {
            separate();
            text << bracket;
            first = true;
            return *this;
          }

          /** Close it. */
          DataText &
          close(const char bracket)
          {
            text << bracket;
            first = false;
            return *this;
          }

          /** A point's or a vector's coordinates (flat). */
          DataText &
          vector(const dealii::Tensor<1, 3> &v)
          {
            return number(v[0]).number(v[1]).number(v[2]);
          }

          /** The text. */
          std::string
          str() const
          {
            return text.str();
          }

        private:
          void
          separate()
          {
            if (!first)
              text << ',';
            first = false;
          }

          std::ostringstream text;
          bool               first = true;
        };


        /**
         * The blocks into @p d: intrados and extrados grids of
         * (k+1)^2 points per block (k = `subdivisions`), the triangles of
         * their faces and sides, the edges as polylines, and the
         * displacement (m) of every point.
         */
        void
        write_blocks(DataText &d, const Result &result)
        {
          const BlockModel &model  = result.model();
          const auto       &blocks = model.blocks();
          const auto       &motion = result.motion();
          // the blocks: intrados and extrados grids of (k+1)^2 points, the
          // sides between their boundaries; displacement per point
          const unsigned int k = result.options().subdivisions;
          const unsigned int n = k + 1;
          {
            std::vector<dealii::Point<3>>     points;
            std::vector<dealii::Tensor<1, 3>> u;
            std::vector<unsigned int>         triangles;
            // block edges: polylines (intrados and extrados outlines,
            // the four corner edges across the thickness)
            std::vector<std::vector<unsigned int>> edges;
            for (unsigned int b = 0; b < blocks.size(); ++b)
              {
                const unsigned int base = points.size();
                for (unsigned int z = 0; z < 2; ++z)
                  for (unsigned int j = 0; j <= k; ++j)
                    for (unsigned int i = 0; i <= k; ++i)
                      {
                        const dealii::Point<3> x =
                          model.solid_point(b,
                                            dealii::Point<2>(double(i) / k,
                                                             double(j) / k),
                                            z == 0 ? -0.5 : 0.5);
                        points.push_back(x);
                        u.push_back(motion.displacement(model, b, x));
                      }
                const auto id =
                  [&](unsigned int i, unsigned int j, unsigned int z) {
                    return base + z * n * n + j * n + i;
                  };
                const auto quad = [&](unsigned int a,
                                      unsigned int b2,
                                      unsigned int c,
                                      unsigned int e) {
                  triangles.insert(triangles.end(), {a, b2, c, a, c, e});
                };
                for (unsigned int z = 0; z < 2; ++z)
                  for (unsigned int j = 0; j < k; ++j)
                    for (unsigned int i = 0; i < k; ++i)
                      quad(id(i, j, z),
                           id(i + 1, j, z),
                           id(i + 1, j + 1, z),
                           id(i, j + 1, z));
                // the boundary of the cell, counter-clockwise
                std::vector<std::array<unsigned int, 2>> ring;
                for (unsigned int i = 0; i < k; ++i)
                  ring.push_back({{i, 0}});
                for (unsigned int j = 0; j < k; ++j)
                  ring.push_back({{k, j}});
                for (unsigned int i = k; i > 0; --i)
                  ring.push_back({{i, k}});
                for (unsigned int j = k; j > 0; --j)
                  ring.push_back({{0, j}});
                for (unsigned int r = 0; r < ring.size(); ++r)
                  {
                    const auto &p = ring[r];
                    const auto &q = ring[(r + 1) % ring.size()];
                    quad(id(p[0], p[1], 0),
                         id(q[0], q[1], 0),
                         id(q[0], q[1], 1),
                         id(p[0], p[1], 1));
                  }
                for (unsigned int z = 0; z < 2; ++z)
                  for (unsigned int side = 0; side < 4; ++side)
                    {
                      std::vector<unsigned int> line;
                      for (unsigned int r = side * k; r <= (side + 1) * k; ++r)
                        {
                          const auto &p = ring[r % ring.size()];
                          line.push_back(id(p[0], p[1], z));
                        }
                      edges.push_back(line);
                    }
                for (const auto &corner : {std::array<unsigned int, 2>{{0, 0}},
                                           std::array<unsigned int, 2>{{k, 0}},
                                           std::array<unsigned int, 2>{{k, k}},
                                           std::array<unsigned int, 2>{{0, k}}})
                  edges.push_back(
                    {id(corner[0], corner[1], 0), id(corner[0], corner[1], 1)});
              }
            d.key("blocks").open('{');
            d.key("n_per_block").number(2 * n * n);
            d.key("p").open('[');
            for (const auto &x : points)
              d.vector(x);
            d.close(']');
            d.key("u").open('[');
            for (const auto &v : u)
              d.vector(v);
            d.close(']');
            d.key("triangles").open('[');
            for (const auto t : triangles)
              d.number(t);
            d.close(']');
            d.key("edges").open('[');
            for (const auto &line : edges)
              {
                d.open('[');
                for (const auto v : line)
                  d.number(v);
                d.close(']');
              }
            d.close(']');
            d.close('}');
          }
        }

        /**
         * Every interface of @p result's model into @p d: its state, its
         * segment on the crack @p map, and for a crack or a support the
         * points, both sides' displacements (m) and the openings (m).
         */
        void
        write_interfaces(DataText               &d,
                         const Result           &result,
                         const DevelopedSurface &map)
        {
          const BlockModel &model  = result.model();
          const auto       &motion = result.motion();
          // every interface: its state and its place on the crack map; the
          // points and both sides' displacements of those that crack
          d.key("interfaces").open('[');
          for (unsigned int c = 0; c < model.interfaces().size(); ++c)
            {
              const auto &i      = model.interfaces()[c];
              const bool support = i.second == rigid_blocks::Interface::support;
              // without a solution nothing moves but the ground: no cracks
              const InterfaceState s = result.has_solution() ?
                                         interface_state(result, i) :
                                         InterfaceState();
              d.open('{');
              d.key("index").number(c);
              d.key("first").number(i.first);
              if (support)
                d.key("support").string(i.support_label);
              else
                d.key("second").number(i.second);
              d.key("type").string(s.type);
              d.key("max_opening").number(s.max_opening);
              d.key("intrados_opening").number(s.intrados_opening);
              d.key("extrados_opening").number(s.extrados_opening);
              d.key("max_jump").number(s.max_jump);
              d.key("map").open('[');
              for (const auto &x :
                   map.segment(i.patch, i.edge[0], i.edge[1], 4))
                d.number(x[0]).number(x[1]);
              d.close(']');
              if (s.is_crack() || support)
                {
                  // intrados, extrados at every station
                  d.key("p").open('[');
                  for (const auto &p : i.points)
                    d.vector(p.position);
                  d.close(']');
                  d.key("u1").open('[');
                  for (const auto &p : i.points)
                    d.vector(motion.displacement(model, i.first, p.position));
                  d.close(']');
                  d.key("u2").open('[');
                  for (const auto &p : i.points)
                    d.vector(
                      support ?
                        result.support_motion(p.position, i.support_label) :
                        motion.displacement(model, i.second, p.position));
                  d.close(']');
                  d.key("intrados").open('[');
                  for (const auto &p : i.points)
                    d.raw(p.intrados ? "1" : "0");
                  d.close(']');
                  d.key("opening").open('[');
                  for (const auto &p : i.points)
                    d.number(result.jump(i, p) * p.normal);
                  d.close(']');
                }
              d.close('}');
            }
          d.close(']');
        }

        /** The outlines and names of @p model's patches on @p map into @p d. */
        void
        write_patches(DataText               &d,
                      const BlockModel       &model,
                      const DevelopedSurface &map)
        {
          // the patches' outlines and names on the map
          const auto &patches = model.geometry().patches();
          d.key("patches").open('[');
          for (unsigned int p = 0; p < patches.size(); ++p)
            {
              d.open('{');
              d.key("name").string(patches[p].name());
              d.key("outline").open('[');
              for (const auto &corner : {dealii::Point<2>(0, 0),
                                         dealii::Point<2>(1, 0),
                                         dealii::Point<2>(1, 1),
                                         dealii::Point<2>(0, 1),
                                         dealii::Point<2>(0, 0)})
                {
                  const auto x = map.map(p, corner);
                  d.number(x[0]).number(x[1]);
                }
              d.close(']');
              d.close('}');
            }
          d.close(']');
        }

        /**
         * The rows of adaptation.csv (one per generation) into @p d, when
         * an optimiser adapted the mesh and wrote that file.
         */
        void
        write_generations(DataText &d, const RunContext &context)
        {
          // the convergence of an adaptation by an optimiser
          if (context.summary.contains("adaptation"))
            {
              const auto &files = context.output.files();
              if (std::find(files.begin(), files.end(), "adaptation.csv") !=
                  files.end())
                {
                  std::ifstream in(context.output.path() + "adaptation.csv");
                  std::string   line;
                  d.key("generations").open('[');
                  while (std::getline(in, line))
                    if (!line.empty() &&
                        std::isdigit(static_cast<unsigned char>(line[0])))
                      {
                        std::istringstream row(line);
                        std::string        cell;
                        d.open('[');
                        while (std::getline(row, cell, ','))
                          d.number(std::stod(cell));
                        d.close(']');
                      }
                  d.close(']');
                }
            }
        }
      } // namespace

      /**
       * report.html: one self-contained page of the run (write_report_page()):
       * the deformed blocks in 3D, coloured by displacement magnitude, with
       * an amplification slider; the cracks coloured by opening and the
       * hinges marked; the supports and the prescribed motion of the
       * settling ones; the crack map on the developed intrados; the
       * convergence of an adaptation; the key numbers, the crack list, the
       * support reactions and every entry of the summary as it is when
       * the report is written (the same numbers as summary.json). Written
       * also for a run without an optimum: the status, its explanation and
       * diagnostics on the blocks at rest.
       */
      class Report : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        std::vector<std::string>
        required_plugins() const override
        {
          return {"cracks", "support reactions"};
        }

        bool
        writes_without_solution() const override
        {
          return true;
        }

        void
        execute(const Result &result, RunContext &context) override
        {
          if (!result.is_root())
            return;
          const auto  start = std::chrono::steady_clock::now();
          std::string data;
          try
            {
              data = page_data(result, context);
            }
          catch (const std::exception &e)
            {
              context.pcout << "Note: report.html not written (" << e.what()
                            << ")\n";
              return;
            }
          const std::string title =
            "masonry: " + context.summary.at("analysis").get<std::string>() +
            " — " + context.summary.at("parameter_file").get<std::string>();
          const std::string path = context.output.path() + "report.html";
          const std::string why =
            write_report_page(path, title, "rigid_blocks", data);
          if (why.empty())
            context.output.file("report.html");
          else
            context.pcout << "Note: report.html not written (" << why << ")\n";
          context.summary["seconds_report"] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          start)
              .count();
        }

      private:
        /** The JSON the page's script draws. */
        static std::string
        page_data(const Result &result, RunContext &context)
        {
          const BlockModel &model = result.model();
          DataText          d;
          d.open('{');
          // the summary as it is now, without the entries the driver
          // completes after the outputs (times, file list, completeness)
          Json summary = context.summary;
          for (const char *later : {"complete",
                                    "wall_seconds",
                                    "cpu_seconds",
                                    "files",
                                    "seconds_output",
                                    "seconds_picture",
                                    "seconds_report"})
            summary.erase(later);
          d.key("summary").raw(summary.dump(0));
          d.key("has_solution").raw(result.has_solution() ? "true" : "false");
          d.key("amplification").number(result.amplification());
          d.key("tolerance").number(result.tolerance());
          d.key("length_scale").number(model.length_scale());
          const dealii::Tensor<1, 2> view = result.view_direction();
          d.key("view").open('[').number(view[0]).number(view[1]).close(']');

          write_blocks(d, result);

          const DevelopedSurface map(model);
          write_interfaces(d, result, map);

          write_patches(d, model, map);

          write_generations(d, context);
          d.close('}');
          return d.str();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::Report,
  "report",
  "report.html: one self-contained page of the run that opens offline in "
  "any browser (plotly.js from Debian's python3-plotly inside, "
  "gzip-compressed): the deformed blocks in 3D coloured by displacement "
  "magnitude (mm) with a slider for the amplification, the cracks "
  "coloured by opening and the hinges marked, the supports and the "
  "prescribed motion of the settling ones, the crack map on the developed "
  "intrados (as `crack map'), the convergence of an adaptation, the key "
  "numbers (status, work, dissipation, load multiplier or minimum "
  "thickness, LP size and time), the crack list, the support reactions and "
  "every entry of the summary as it is when the report is written. Also "
  "written for a run without an optimum (status, explanation and "
  "diagnostics on the blocks at rest). Summary entry `seconds_report'. "
  "Runs `cracks' and `support reactions'.")
