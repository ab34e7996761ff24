/**
 * @file
 * Postprocessor `crack map`: crack_map.csv and crack_map.png, the cracks on
 * the developed intrados.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch.h>
#include <masonry/rigid_blocks/postprocess/crack_map.h>

#include <fstream>
#include <iomanip>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /**
       * The crack map: every joint, support and patch edge drawn on the
       * developed intrados (DevelopedSurface), the joints that open or
       * slide coloured by their opening and drawn by their type. The table
       * crack_map.csv holds what the picture crack_map.png (the installed
       * crack_map.py, with `Write picture = true') draws, so that a
       * surveyor's crack record can be compared with it in any tool.
       */
      class CrackMap : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        std::vector<std::string>
        required_plugins() const override
        {
          return {"cracks"};
        }

        void
        execute(const Result &result, RunContext &context) override
        {
          if (!result.is_root())
            return;
          const BlockModel      &model = result.model();
          const DevelopedSurface map(model);
          const std::string      csv = context.output.file("crack_map.csv");
          {
            OutputFile out(csv);
            write_table(result, map, out);
            out.close();
          }
          if (!result.options().write_picture)
            return;
          OutputDirectory &dir = context.output;
          RunContext      *c   = &context;
          result.render({"crack_map.py",
                         {csv,
                          "{output}",
                          context.summary.at("analysis").get<std::string>(),
                          "--tolerance",
                          number(result.tolerance())},
                         dir.path() + "crack_map.png"},
                        [&dir, c](const std::string &why) {
                          if (why.empty())
                            dir.file("crack_map.png");
                          else
                            c->pcout << "Note: crack_map.png not written ("
                                     << why << ")\n";
                        });
        }

      private:
        static std::string
        number(const double x)
        {
          std::ostringstream s;
          s << std::setprecision(10) << x;
          return s.str();
        }

        /** One row per joint, support and patch edge. */
        static void
        write_table(const Result           &result,
                    const DevelopedSurface &map,
                    std::ostream           &out)
        {
          const BlockModel &model   = result.model();
          const auto       &patches = model.geometry().patches();
          out << "kind,patch,label,first_block,second_block,type,opens_at,"
                 "max_opening,intrados_opening,extrados_opening,max_jump,"
                 "support_motion,s0,t0,s1,t1,s2,t2\n"
              << std::setprecision(10);
          const auto write_points =
            [&](const std::vector<dealii::Point<2>> &p) {
              for (const unsigned int k : {0u, 1u, 2u})
                {
                  const auto &x = p[k * (p.size() - 1) / 2];
                  out << "," << x[0] << "," << x[1];
                }
              out << "\n";
            };
          for (const auto &i : model.interfaces())
            {
              const bool support = i.second == rigid_blocks::Interface::support;
              const InterfaceState s   = interface_state(result, i);
              const double         tol = result.tolerance();
              const char          *opens =
                s.intrados_opening > tol ?
                           (s.extrados_opening > tol ? "both" : "intrados") :
                           (s.extrados_opening > tol ? "extrados" : "none");
              const double motion =
                support ?
                  result.support_motion(i.centre, i.support_label).norm() :
                  0.;
              out << (support ? "support" : "joint") << "," << i.patch << ","
                  << (support ? i.support_label : "") << "," << i.first << ","
                  << (support ? std::string() : std::to_string(i.second)) << ","
                  << s.type << "," << opens << "," << s.max_opening << ","
                  << s.intrados_opening << "," << s.extrados_opening << ","
                  << s.max_jump << "," << motion;
              write_points(map.segment(i.patch, i.edge[0], i.edge[1], 2));
            }
          for (unsigned int p = 0; p < patches.size(); ++p)
            for (unsigned int side = 0; side < 4; ++side)
              {
                const double           c = side % 2;
                const dealii::Point<2> a =
                  side < 2 ? dealii::Point<2>(c, 0) : dealii::Point<2>(0, c);
                const dealii::Point<2> b =
                  side < 2 ? dealii::Point<2>(c, 1) : dealii::Point<2>(1, c);
                out << "edge," << p << "," << patches[p].edge_labels()[side]
                    << ",,,,,0,0,0,0,0";
                write_points(map.segment(p, a, b, 2));
              }
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::CrackMap,
  "crack map",
  "crack_map.csv and (with the analysis' `Write picture = true'; needs "
  "/usr/bin/python3 with matplotlib) crack_map.png: the cracks on the "
  "developed intrados, where a surveyor's crack record is compared. Each "
  "patch is unrolled by the arc lengths of its intrados (s along u, t "
  "along v, m; exact for barrel vaults and arches, whose halves are laid "
  "side by side from one springing to the other). One row per joint "
  "(`joint'), support joint (`support') and patch edge (`edge'): patch, "
  "edge label, blocks, type (`closed', `hinge', `separation', `slip' as "
  "in the crack list), the face that opens (`intrados', `extrados', "
  "`both', `none'), the largest opening of all its points, of the "
  "intrados and of the extrados points and the largest jump (m), the "
  "support's prescribed motion at its centre (m), and the start, middle "
  "and end of the joint on the map (s0, t0, s1, t1, s2, t2 in m). The "
  "picture draws the cracks coloured by opening (mm): solid where the "
  "intrados opens (visible from below), dashed where only the extrados "
  "opens, dotted for slip; settling supports in orange. Runs `cracks'.")
