/**
 * @file
 * curve.png (stress-strain curve with the cycle peaks) and degradation.png
 * (unloading modulus over the initial modulus per cycle), drawn by
 * matplotlib from curve.csv and cycles.csv.
 */
#include <masonry/core/output_directory.h>

#include <filesystem>
#include <fstream>

#include "postprocessor.h"

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      namespace
      {
        /** Runs the plot script at the end of the run. */
        class CurvePlot : public Postprocessor
        {
        public:
          void
          finish(const ModelView &view, Json &) override
          {
            const std::string png = view.context.output.file("curve.png");
            if (!view.settings.protocol.cycle_amplitudes.empty())
              view.context.output.file("degradation.png");
            if (dealii::Utilities::MPI::this_mpi_process(view.system.comm) != 0)
              return;
            const std::string dir    = view.context.output.path();
            const std::string script = dir + "/.curve_plot.py";
            std::ofstream     py(script);
            py << "import matplotlib\nmatplotlib.use('Agg')\n"
                  "import matplotlib.pyplot as plt\nimport csv, os\n"
                  "d = '"
               << dir
               << "'\n"
                  "rows = list(csv.DictReader(open(d + '/curve.csv')))\n"
                  "e = [1e3*float(r['strain']) for r in rows]\n"
                  "s = [1e-6*float(r['stress_Pa']) for r in rows]\n"
                  "plt.figure(figsize=(6,4.5))\n"
                  "plt.plot(e, s, '-', lw=1, marker='o' if len(e) < 80 "
                  "else None, ms=3)\n"
                  "if os.path.exists(d + '/cycles.csv'):\n"
                  "    c = list(csv.DictReader(open(d + '/cycles.csv')))\n"
                  "    plt.plot([1e3*float(r['strain_at_peak']) for r in "
                  "c], [1e-6*float(r['peak_stress_Pa']) for r in c], "
                  "'k^', ms=4, label='cycle peaks')\n"
                  "    plt.legend()\n"
                  "plt.xlabel('strain along the platen motion (1e-3)')\n"
                  "plt.ylabel('stress = force / gross area (MPa)')\n"
                  "plt.grid(alpha=0.3)\nplt.tight_layout()\n"
                  "plt.savefig('"
               << png
               << "', dpi=120)\n"
                  "if os.path.exists(d + '/cycles.csv'):\n"
                  "    plt.figure(figsize=(6,4.5))\n"
                  "    plt.plot([1e3*float(r['strain_at_peak']) for r in "
                  "c], [float(r['stiffness_ratio']) for r in c], 'o-')\n"
                  "    plt.xlabel('strain at the cycle peak (1e-3)')\n"
                  "    plt.ylabel('unloading modulus / initial modulus')\n"
                  "    plt.ylim(0, 1.05)\n    plt.grid(alpha=0.3)\n"
                  "    plt.tight_layout()\n"
                  "    plt.savefig(d + '/degradation.png', dpi=120)\n";
            py.close();
            const int rc = std::system(
              ("/usr/bin/python3 " + script + " >/dev/null 2>&1").c_str());
            std::filesystem::remove(script);
            if (rc != 0)
              view.context.pcout
                << "Warning: the plots could not be drawn "
                   "(needs /usr/bin/python3 with matplotlib)\n";
          }
        };
      } // namespace

      std::unique_ptr<Postprocessor>
      create_curve_plot()
      {
        return std::make_unique<CurvePlot>();
      }
    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry
