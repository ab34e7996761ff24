/**
 * @file
 * The curve's entries of summary.json.
 */
#include "curve_summary.h"

namespace masonry
{
  namespace brickwork
  {
    void
    write_curve_summary(const std::vector<CurvePoint>  &curve,
                        const double                    gauge_span,
                        const std::vector<std::string> &damage_names,
                        Json                           &summary)
    {
      double peak = -1e300, strain_at_peak = 0;
      for (const auto &p : curve)
        if (p.stress > peak)
          {
            peak           = p.stress;
            strain_at_peak = p.strain;
          }
      double work = 0;
      for (unsigned int i = 1; i < curve.size(); ++i)
        work += 0.5 * (curve[i].force + curve[i - 1].force) *
                (curve[i].displacement - curve[i - 1].displacement);
      const double modulus       = curve.size() > 1 && curve[1].strain != 0 ?
                                     curve[1].stress / curve[1].strain :
                                     0.;
      summary["peak_stress"]     = curve.size() > 1 ? peak : 0.;
      summary["strain_at_peak"]  = strain_at_peak;
      summary["initial_modulus"] = modulus;
      if (gauge_span > 0)
        {
          summary["gauge_length"] = gauge_span;
          for (const auto &p : curve)
            if (p.stress == peak)
              summary["gauge_strain_at_peak"] = p.gauge_strain;
          summary["initial_modulus_gauge"] =
            curve.size() > 1 && curve[1].gauge_strain != 0 ?
              curve[1].stress / curve[1].gauge_strain :
              0.;
        }
      summary["final_stress"]  = curve.back().stress;
      summary["final_strain"]  = curve.back().strain;
      summary["external_work"] = work;
      summary["max_damage"]    = curve.back().max_damage;
      for (unsigned int k = 0; k < damage_names.size(); ++k)
        summary["max_brick_" + damage_names[k]] =
          k < curve.back().brick_damages.size() ?
            curve.back().brick_damages[k] :
            0.;
    }
  } // namespace brickwork
} // namespace masonry
