/**
 * @file
 * The cyclic protocol: load-unload cycles at growing amplitudes, each
 * unloading under displacement control to a small force.
 */
#include <masonry/brickwork/protocol.h>
#include <masonry/core/parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    namespace
    {
      /** Load-unload cycles, `Cycles per amplitude' at each amplitude. */
      class Cyclic : public Protocol
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          using dealii::Patterns::Double;
          declare_ranged_list(
            prm,
            "Cycle amplitudes",
            "",
            {0, 1, "(dimensionless)"},
            0,
            ",",
            "Strains (platen displacement / height, dimensionless, "
            "increasing) at which the cycles of the `cyclic' protocol turn "
            "back. Empty: k times `Amplitude increment' for k = 1, 2, ... up "
            "to `Target strain'.");
          declare_ranged_entry(prm,
                               "Amplitude increment",
                               "0.0005",
                               {0, 1, "(dimensionless)"},
                               "Strain added from one amplitude to the next "
                               "when `Cycle amplitudes' is empty "
                               "(dimensionless, > 0).");
          prm.declare_entry("Cycles per amplitude",
                            "1",
                            dealii::Patterns::Integer(1, 100),
                            "Load-unload cycles at each amplitude; 2 or more "
                            "give the common-point and stability-point "
                            "curves.");
          declare_ranged_entry(
            prm,
            "Unloading stress",
            "0.1e6",
            {0, 1e9, "Pa"},
            "An unloading ends when the stress (platen force "
            "/ gross area) has dropped to this, Pa (>= 0): "
            "the small target force of a test. Its last step "
            "is aimed at it; the leg ends at the first step "
            "at or below 1.01 times it.");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          strains =
            split_doubles(prm.get("Cycle amplitudes"), "Cycle amplitudes");
          increment        = positive_entry(prm, "Amplitude increment");
          repeats          = prm.get_integer("Cycles per amplitude");
          unloading_stress = prm.get_double("Unloading stress");
          for (unsigned int i = 1; i < strains.size(); ++i)
            AssertThrow(strains[i] > strains[i - 1],
                        ExcParameter("Cycle amplitudes",
                                     "must increase from one cycle to the "
                                     "next"));
          AssertThrow(strains.empty() || strains[0] > 0,
                      ExcParameter("Cycle amplitudes", "must be positive"));
          // (the default list needs the target strain: initialize())
          AssertThrow(!strains.empty() ||
                        increment <= target_strain * (1 + 1e-9),
                      ExcParameter("Amplitude increment",
                                   "is larger than the target strain: no "
                                   "cycle"));
        }

        void
        initialize(const double height) override
        {
          amplitudes.clear();
          if (strains.empty())
            for (unsigned int k = 1;
                 k * increment <= target_strain * (1 + 1e-9);
                 ++k)
              amplitudes.push_back(k * increment * height);
          else
            for (const double a : strains)
              amplitudes.push_back(a * height);
        }

        std::vector<Leg>
        legs() const override
        {
          std::vector<Leg> legs;
          unsigned int     cycle = 0;
          for (const double a : amplitudes)
            for (unsigned int r = 0; r < repeats; ++r)
              {
                ++cycle;
                legs.push_back({a, false, cycle});
                legs.push_back({0., true, cycle});
              }
          return legs;
        }

        double
        amplitude(const unsigned int cycle) const override
        {
          return amplitudes[(cycle - 1) / repeats];
        }

        unsigned int
        cycles_per_amplitude() const override
        {
          return repeats;
        }

        double
        target_displacement() const override
        {
          return amplitudes.back();
        }

        std::string
        description() const override
        {
          std::ostringstream s;
          s << "Protocol: " << legs().size() / 2
            << " load-unload cycles, unloading to " << unloading_stress * 1e-6
            << " MPa";
          return s.str();
        }

        /**
         * An unloading ends at the unloading stress. The aimed last step
         * lands a little above: the aim takes the slope of the last step,
         * and the IMPL-EX states lag one step (0.1 % of the unloading
         * stress in the cyclic examples); without the 1 % the leg went on
         * with a tiny step (2e-8 m) and then a whole one past the unloading
         * stress.
         */
        bool
        leg_done(const Leg                     &leg,
                 const std::vector<CurvePoint> &curve,
                 const double                   applied,
                 const double                   nominal) const override
        {
          if (!leg.unloading)
            return Protocol::leg_done(leg, curve, applied, nominal);
          return curve.size() > 1 &&
                 (curve.back().stress <= 1.01 * unloading_stress +
                                           1e-6 * std::abs(curve[1].stress) ||
                  applied <= leg.target + 1e-9 * nominal);
        }

        /** An unloading step aims at the unloading stress with the slope of
         * the last unloading step (elastic unloading is linear). */
        bool
        next_position(const Leg                     &leg,
                      const std::vector<CurvePoint> &curve,
                      const double                   applied,
                      const double                   increment,
                      const double                   nominal,
                      double                        &next) const override
        {
          if (!leg.unloading || leg_done(leg, curve, applied, nominal))
            return Protocol::next_position(
              leg, curve, applied, increment, nominal, next);
          next                     = applied - increment;
          const CurvePoint &last   = curve.back();
          const CurvePoint &before = curve[curve.size() - 2];
          if (last.unloading && last.displacement < before.displacement)
            {
              const double slope = (before.stress - last.stress) /
                                   (before.displacement - last.displacement);
              if (slope > 0)
                {
                  const double aim =
                    applied - (last.stress - unloading_stress) / slope;
                  if (aim > next - 1e-12 * nominal)
                    next = aim;
                }
            }
          next = std::max(next, leg.target);
          return applied - next >= 1e-9 * nominal;
        }

      private:
        /** The entries: amplitudes as strains, the increment of the
         * default list, cycles at each, the unloading stress (Pa). */
        std::vector<double> strains;
        double              increment        = 0.0005;
        unsigned int        repeats          = 1;
        double              unloading_stress = 0.1e6;
        /** The amplitudes as platen displacements, m. */
        std::vector<double> amplitudes;
      };
    } // namespace
  }   // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_PROTOCOL(
  masonry::brickwork::Cyclic,
  "cyclic",
  "Load-unload cycles at increasing amplitudes (`Cycle amplitudes'), each "
  "unloaded under displacement control until the stress has dropped to "
  "`Unloading stress'; cycles.csv and envelope.csv give per cycle the peak "
  "stress, residual strain, unloading modulus and dissipated energy, and "
  "the envelope, common-point and stability-point stresses.")
