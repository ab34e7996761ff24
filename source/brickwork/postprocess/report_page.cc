/**
 * @file
 * report.html of a wallette run: the page of the installed script
 * contrib/plot/wallette_report.py (plotly.js inside, opens offline), drawn
 * from the run's files and its summary when everything else is written.
 */
#include <masonry/brickwork/postprocessor.h>
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/scripts.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <string>
#include <unistd.h>

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      namespace
      {
        /** Runs the page script once the run's summary is complete. */
        class ReportPage : public Postprocessor
        {
        public:
          static void
          declare_parameters(dealii::ParameterHandler &)
          {}

          void
          after_summary(const ModelView &view, const Json &summary) override
          {
            if (!view.is_root())
              return;
            auto             &output = view.context.output;
            const std::string page   = output.path() + "report.html";
            // summary.json itself is written by the driver after the
            // analysis: the script reads this run's summary from a file of
            // its own, removed when the page is drawn
            const std::string given = output.path() + ".report-summary." +
                                      std::to_string(::getpid()) + ".json";
            {
              // the files as summary.json will list them: those written
              // so far and the page
              Json copy  = summary;
              Json files = Json::array();
              for (const auto &f : output.files())
                if (f != "report.html")
                  files.push_back(f);
              files.push_back("report.html");
              copy["files"] = files;
              // what the driver sets after the analysis (the run's time
              // and whether every result was written) is not known yet:
              // the page leaves it out rather than show the values of the
              // run's start
              for (const char *key :
                   {"complete", "wall_seconds", "cpu_seconds"})
                copy.erase(key);
              OutputFile out(given);
              out << copy.dump() << "\n";
              out.close();
            }
            std::string why;
            try
              {
                why = run_script("wallette_report.py",
                                 {output.path(), "--summary", given},
                                 {page});
              }
            catch (...)
              {
                std::remove(given.c_str());
                throw;
              }
            std::remove(given.c_str());
            if (why.empty())
              output.file("report.html");
            else
              view.context.pcout << "Note: report.html was not written (" << why
                                 << ")\n";
          }
        };
      } // namespace
    }   // namespace postprocess
  }     // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  masonry::brickwork::postprocess::ReportPage,
  "report",
  "report.html at the end of the run, one self-contained page that opens offline in any browser: the wallette in 3D at a chosen output step (a slider; cells coloured by damage, deleted cells hidden, open joints drawn by their opening), the stress-strain curve with its cycles, the cycle and envelope tables and the key numbers of the summary. Drawn by the installed script wallette_report.py with /usr/bin/python3 and numpy from the run's files (the 3D view needs `fields' and `joint fields'); plotly.js comes from Debian's python3-plotly at build time. The same script draws the page of an earlier run: wallette_report.py OUTPUT_DIRECTORY.");
