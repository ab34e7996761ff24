/**
 * @file
 * What every protocol shares: `Target strain', `Platen speed', loading legs
 * and the rigid platen.
 */
#include <masonry/brickwork/protocol.h>
#include <masonry/core/parameters.h>

#include <cmath>

namespace masonry
{
  namespace brickwork
  {
    const char *
    Protocol::default_plugin()
    {
      return "monotonic";
    }

    std::string
    Protocol::selection_documentation()
    {
      return "The path of the top platen (`monotonic': one ramp to the "
             "target strain; `cyclic': load-unload cycles).";
    }

    void
    Protocol::declare_common_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      declare_ranged_entry(prm,
                           "Target strain",
                           "0.003",
                           {0, 1, "(dimensionless)"},
                           "Final platen displacement divided by the height "
                           "of the wallette (dimensionless, > 0; the "
                           "displacement in m is this times the height).");
      declare_ranged_entry(
        prm,
        "Platen speed",
        "1e-5",
        {0, 1000, "m/s"},
        "Speed of the top platen, m/s (> 0): the pseudo-time of a step "
        "is its platen displacement / this speed. It matters only for "
        "the viscous regularisation of the brick and joint damage "
        "(`Viscosity' of the material and the interface law).");
    }

    void
    Protocol::parse_common_parameters(dealii::ParameterHandler &prm)
    {
      target_strain = positive_entry(prm, "Target strain");
      platen_speed  = positive_entry(prm, "Platen speed");
    }


    unsigned int
    Protocol::cycles_per_amplitude() const
    {
      return 1;
    }

    bool
    Protocol::is_cyclic() const
    {
      return legs().size() > 1;
    }

    std::string
    Protocol::description() const
    {
      return "";
    }

    double
    Protocol::pseudo_time(const double increment) const
    {
      return increment / platen_speed;
    }

    bool
    Protocol::leg_done(const Leg                     &leg,
                       const std::vector<CurvePoint> &curve,
                       const double                   applied,
                       const double                   nominal) const
    {
      if (!leg.unloading)
        return applied >= leg.target * (1 - 1e-12);
      return curve.size() > 1 && applied <= leg.target + 1e-9 * nominal;
    }

    bool
    Protocol::next_position(const Leg                     &leg,
                            const std::vector<CurvePoint> &curve,
                            const double                   applied,
                            const double                   increment,
                            const double                   nominal,
                            double                        &next) const
    {
      if (leg_done(leg, curve, applied, nominal))
        return false;
      if (!leg.unloading)
        {
          next = applied + increment;
          if (next > leg.target * (1 - 1e-9))
            next = leg.target;
          return true;
        }
      next = std::max(applied - increment, leg.target);
      return applied - next >= 1e-9 * nominal;
    }

    void
    Protocol::hold_platen(const Platen                      &platen,
                          dealii::AffineConstraints<double> &constraints) const
    {
      for (const auto &dofs : platen.dofs)
        for (unsigned int d = 0; d < 3; ++d)
          if ((platen.lateral_fixed || d == 2) &&
              !constraints.is_constrained(dofs[d]))
            constraints.add_line(dofs[d]);
    }

    void
    Protocol::move_platen(const Platen                            &platen,
                          const double                             displacement,
                          const dealii::AffineConstraints<double> &constraints,
                          dealii::TrilinosWrappers::MPI::Vector   &u) const
    {
      for (const auto &dofs : platen.dofs)
        for (unsigned int d = 0; d < 3; ++d)
          if (constraints.is_constrained(dofs[d]) &&
              u.locally_owned_elements().is_element(dofs[d]))
            u[dofs[d]] = displacement * platen.direction[d];
      u.compress(dealii::VectorOperation::insert);
    }
  } // namespace brickwork
} // namespace masonry
