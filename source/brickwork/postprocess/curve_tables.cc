/**
 * @file
 * The curve and cycle tables: curve.csv (one line per converged step,
 * written as the run goes), cycles.csv and envelope.csv (cyclic protocol),
 * the deleted cells (deletions.csv, with element deletion on) and the
 * cycles' entry of summary.json. The curve's own entries of summary.json
 * (peak stress, initial modulus, ...) are the run's (curve_summary.h).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/brickwork/protocol.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>

#include <deal.II/base/mpi.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      namespace
      {
        /** Results of one load-unload cycle. */
        struct Cycle
        {
          unsigned int cycle     = 0;
          double       amplitude = 0, peak_stress = 0, strain_at_peak = 0;
          double       residual_strain = 0, unloading_modulus = 0;
          double       dissipated_energy = 0;
          /** Curve indices: start of loading, turning point, end. */
          unsigned int first = 0, turn = 0, last = 0;
        };

        /** Cycle results from the curve. */
        std::vector<Cycle>
        cycle_results(const ModelView &view)
        {
          const auto        &curve = view.curve;
          std::vector<Cycle> cycles;
          for (unsigned int i = 1; i < curve.size(); ++i)
            {
              const CurvePoint &p = curve[i];
              if (cycles.empty() || cycles.back().cycle != p.cycle)
                {
                  Cycle c;
                  c.cycle = p.cycle;
                  c.first = c.turn = i - 1;
                  c.amplitude =
                    view.protocol.amplitude(p.cycle) / view.height();
                  cycles.push_back(c);
                }
              Cycle &c = cycles.back();
              c.last   = i;
              if (!p.unloading)
                c.turn = i;
              if (p.stress > c.peak_stress || c.first + 1 == i)
                {
                  c.peak_stress    = p.stress;
                  c.strain_at_peak = p.strain;
                }
            }
          for (auto &c : cycles)
            {
              const CurvePoint &turn = curve[c.turn], &end = curve[c.last];
              c.residual_strain = end.strain;
              c.unloading_modulus =
                c.last > c.turn && turn.strain != end.strain ?
                  (turn.stress - end.stress) / (turn.strain - end.strain) :
                  0.;
              // the loop's area: work per unit volume done on the wallette
              // from the start of the cycle to its end
              for (unsigned int i = c.first + 1; i <= c.last; ++i)
                c.dissipated_energy += 0.5 *
                                       (curve[i].stress + curve[i - 1].stress) *
                                       (curve[i].strain - curve[i - 1].strain);
            }
          return cycles;
        }

        /**
         * The common point of amplitude group @p k: where the reloading of
         * the second cycle at the amplitude meets the unloading of the
         * first, both as stress over strain: the highest stress where the
         * reloading line reaches the unloading line (NaN: none).
         */
        double
        common_point(const std::vector<CurvePoint> &curve,
                     const Cycle                   &first,
                     const Cycle                   &second)
        {
          auto on_unloading = [&](const double e) {
            for (unsigned int i = first.turn + 1; i <= first.last; ++i)
              {
                const auto &a = curve[i - 1], &b = curve[i];
                if ((e - a.strain) * (e - b.strain) <= 0 &&
                    a.strain != b.strain)
                  return a.stress + (b.stress - a.stress) * (e - a.strain) /
                                      (b.strain - a.strain);
              }
            return std::numeric_limits<double>::quiet_NaN();
          };
          // from the top of the reloading down to the first point on or
          // under the unloading line
          for (unsigned int i = second.turn; i > second.first; --i)
            {
              const double g = on_unloading(curve[i].strain);
              if (std::isfinite(g) &&
                  curve[i].stress <= g + 1e-9 * std::abs(first.peak_stress))
                return curve[i].stress;
            }
          return std::numeric_limits<double>::quiet_NaN();
        }

        /** curve.csv, cycles.csv, envelope.csv, deletions.csv and the
         * cycles' summary. */
        class CurveTables : public Postprocessor
        {
        public:
          static void
          declare_parameters(dealii::ParameterHandler &)
          {}

          void
          start(const ModelView &view) override
          {
            append(view, true);
          }

          void
          resume(const ModelView &view) override
          {
            // curve.csv anew, up to the checkpoint
            for (unsigned int i = 0; i < view.curve.size(); ++i)
              write_line(view, i, i == 0);
          }

          void
          step(const ModelView &view) override
          {
            append(view, false);
          }

          void
          finish(const ModelView &view, Json &summary) override
          {
            // curve.csv was written step by step
            view.context.output.file("curve.csv");
            // the curve's own entries (initial_modulus, peak_stress, ...)
            // are the run's (curve_summary.h)
            const double modulus = summary.value("initial_modulus", 0.);
            if (view.protocol.is_cyclic())
              write_cycles(view, modulus, summary);
            if (view.deletes_cells())
              write_deletions(view);
          }

        private:
          void
          append(const ModelView &view, const bool header) const
          {
            write_line(view, view.curve.size() - 1, header);
          }

          void
          write_line(const ModelView   &view,
                     const unsigned int i,
                     const bool         header) const
          {
            if (!view.is_root())
              return;
            // curve.csv grows line by line, so that a user can follow a long
            // run; a line that cannot be written ends the run
            const std::string path = view.context.output.path() + "curve.csv";
            std::ofstream out(path, header ? std::ios::trunc : std::ios::app);
            out << std::setprecision(12);
            if (header)
              {
                out << "step,displacement_m,strain,force_N,stress_Pa,"
                       "newton_iterations,max_damage,gauge_strain,cycle,"
                       "unloading,deleted_cells";
                for (const auto &name : view.laws.brick_damage_names())
                  out << ",brick_" << name;
                out << "\n";
              }
            const CurvePoint &p = view.curve[i];
            out << i << "," << p.displacement << "," << p.strain << ","
                << p.force << "," << p.stress << "," << p.newton << ","
                << p.max_damage << "," << p.gauge_strain << "," << p.cycle
                << "," << p.unloading << "," << p.deleted;
            const unsigned int n_damages =
              view.laws.brick_damage_names().size();
            for (unsigned int k = 0; k < n_damages; ++k)
              out << ","
                  << (k < p.brick_damages.size() ? p.brick_damages[k] : 0.);
            out << "\n";
            out.close();
            AssertThrow(
              out, dealii::ExcMessage(write_error(path, std::strerror(errno))));
          }

          void
          write_cycles(const ModelView &view,
                       const double     modulus,
                       Json            &summary) const
          {
            const auto              &curve  = view.curve;
            const std::vector<Cycle> cycles = cycle_results(view);
            const bool               root   = view.is_root();
            const std::string        dir    = view.context.output.path();
            view.context.output.file("cycles.csv");
            if (root)
              {
                OutputFile out(dir + "cycles.csv");
                out << std::setprecision(12);
                out << "cycle,amplitude_strain,peak_stress_Pa,strain_at_peak,"
                       "residual_strain,unloading_modulus_Pa,"
                       "stiffness_ratio,dissipated_energy_J_per_m3\n";
                for (const auto &c : cycles)
                  out << c.cycle << "," << c.amplitude << "," << c.peak_stress
                      << "," << c.strain_at_peak << "," << c.residual_strain
                      << "," << c.unloading_modulus << ","
                      << (modulus > 0 ? c.unloading_modulus / modulus : 0.)
                      << "," << c.dissipated_energy << "\n";
                out.close();
              }
            // envelope (first cycle at each amplitude), stability point
            // (last cycle) and common point
            const unsigned int n_rep = view.protocol.cycles_per_amplitude();
            if (root)
              {
                OutputFile out(dir + "envelope.csv");
                out << std::setprecision(12)
                    << "amplitude_strain,envelope_strain,envelope_stress_Pa,"
                       "common_point_stress_Pa,stability_point_stress_Pa\n";
                for (unsigned int k = 0; k * n_rep < cycles.size(); ++k)
                  {
                    const Cycle &first = cycles[k * n_rep];
                    const Cycle &lastc =
                      cycles[std::min<std::size_t>((k + 1) * n_rep,
                                                   cycles.size()) -
                             1];
                    // empty in the CSV where there is no second cycle
                    double common = std::numeric_limits<double>::quiet_NaN();
                    if (n_rep > 1 && k * n_rep + 1 < cycles.size())
                      common =
                        common_point(curve, first, cycles[k * n_rep + 1]);
                    out << first.amplitude << "," << first.strain_at_peak << ","
                        << first.peak_stress << ",";
                    if (std::isfinite(common))
                      out << common;
                    out << "," << lastc.peak_stress << "\n";
                  }
                out.close();
              }
            view.context.output.file("envelope.csv");
            Json list = Json::array();
            for (const auto &c : cycles)
              {
                Json j;
                j["cycle"]             = c.cycle;
                j["amplitude_strain"]  = c.amplitude;
                j["peak_stress"]       = c.peak_stress;
                j["residual_strain"]   = c.residual_strain;
                j["unloading_modulus"] = c.unloading_modulus;
                j["dissipated_energy"] = c.dissipated_energy;
                list.push_back(j);
              }
            summary["cycles"] = list;
          }

          /** deletions.csv: every deleted cell, in the order they went,
           * with what it carried when it went. */
          void
          write_deletions(const ModelView &view) const
          {
            view.context.output.file("deletions.csv");
            if (!view.is_root())
              return;
            OutputFile out(view.context.output.path() + "deletions.csv");
            out << std::setprecision(12)
                << "step,cycle,unloading,cell,region,x_m,y_m,z_m,"
                   "largest_principal_strain,stress_xx_Pa,stress_yy_Pa,"
                   "stress_zz_Pa,stress_xy_Pa,stress_yz_Pa,stress_xz_Pa\n";
            for (const auto &d : view.deletions())
              {
                out << d.step << "," << d.cycle << "," << d.unloading << ","
                    << d.cell << "," << int(d.region);
                for (const double x : d.centre)
                  out << "," << x;
                out << "," << d.strain;
                for (const double s : d.stress)
                  out << "," << s;
                out << "\n";
              }
            out.close();
          }
        };
      } // namespace

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  masonry::brickwork::postprocess::CurveTables,
  "curve tables",
  "curve.csv (one line per converged step: displacement in m, strain, force in N, stress in Pa, Newton iterations, largest joint damage, gauge strain, cycle, unloading, deleted cells, largest brick damages), cycles.csv and envelope.csv (cyclic protocol), deletions.csv (with `Deletion strain' > 0: one line per deleted cell in the order they went: the step after which it went, its cycle and leg, cell index, region 0 unit 1 mortar, centre in m, the largest principal value of its cell-averaged strain and the six components of its cell-averaged stress in Pa at that step, its fade included) and the cycles in summary.json (the run writes the curve's own entries: peak_stress in Pa, strain_at_peak, initial_modulus in Pa, final_stress, external_work in J).")
