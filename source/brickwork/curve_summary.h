/**
 * @file
 * The curve's entries of summary.json (peak stress, strain at peak, initial
 * modulus, gauge, final state, work, largest damages), computed by the run
 * itself from the curve, before any postprocessor: the run's result line
 * and every postprocessor read them whatever the list of postprocessors
 * holds.
 */
#ifndef masonry_brickwork_curve_summary_h
#define masonry_brickwork_curve_summary_h

#include <masonry/brickwork/curve.h>
#include <masonry/core/json.h>

#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    /**
     * Into @p summary: `peak_stress' (Pa, the largest stress of @p curve; 0
     * for a curve of the initial state only), `strain_at_peak',
     * `initial_modulus' (Pa, the secant of the first step), with a gauge
     * (@p gauge_span > 0, m) `gauge_length', `gauge_strain_at_peak' and
     * `initial_modulus_gauge', `final_stress', `final_strain',
     * `external_work' (J, the platen's work by the trapezoidal rule),
     * `max_damage' (joints) and `max_brick_NAME' for each of the brick
     * law's @p damage_names, at the last point.
     */
    void
    write_curve_summary(const std::vector<CurvePoint>  &curve,
                        const double                    gauge_span,
                        const std::vector<std::string> &damage_names,
                        Json                           &summary);
  } // namespace brickwork
} // namespace masonry

#endif
