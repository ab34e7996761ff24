#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>

#include <cmath>
#include <sstream>

namespace masonry
{
  namespace geometry
  {
    const char *
    Interface::default_plugin()
    {
      return "barrel vault";
    }

    std::string
    Interface::selection_documentation()
    {
      return "The shape of the vault: its middle surface as exact NURBS "
             "patches (z up, span along x, length along y, lengths in m).";
    }

    void
    Interface::declare_common_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Thickness",
        "0.36",
        dealii::Patterns::Anything(),
        "Thickness of the vault (m), measured along the normal of the middle "
        "surface: an expression in x, y, z (m; the point of the middle "
        "surface; the constant pi is defined), e.g. `0.36' or "
        "`0.5 - 0.04*z'. It must be positive and finite on the whole "
        "surface.");
      prm.declare_entry("Density",
                        "520",
                        dealii::Patterns::Double(0),
                        "Density of the masonry (kg/m^3), > 0.");
    }

    void
    Interface::parse_common_parameters(dealii::ParameterHandler &prm)
    {
      thickness_expression = prm.get("Thickness");
      thickness_function   = std::make_unique<dealii::FunctionParser<3>>(1);
      try
        {
          thickness_function->initialize("x,y,z",
                                         thickness_expression,
                                         {{"pi", M_PI}});
          // evaluate once: catches unknown variables at parse time
          (void)thickness_function->value(dealii::Point<3>());
        }
      catch (const std::exception &exc)
        {
          thickness_function.reset();
          AssertThrow(false,
                      ExcParameter("Thickness",
                                   "cannot parse the expression '" +
                                     thickness_expression +
                                     "' as a function of x, y, z."));
        }
      rho = prm.get_double("Density");
      AssertThrow(rho > 0 && std::isfinite(rho),
                  ExcParameter("Density", "must be positive (kg/m^3)."));
    }


    const std::vector<Patch> &
    Interface::patches() const
    {
      return patch_list;
    }

    double
    Interface::thickness(const dealii::Point<3> &x) const
    {
      return factor * unscaled_thickness(x);
    }

    double
    Interface::unscaled_thickness(const dealii::Point<3> &x) const
    {
      AssertThrow(thickness_function,
                  dealii::ExcMessage("geometry::Interface::thickness() called "
                                     "before parse_common_parameters()."));
      const double t = thickness_function->value(x);
      if (!(t > 0) || !std::isfinite(t))
        {
          plugins::ParsePathScope scope(registry_section);
          std::ostringstream      where;
          where << "the thickness '" << thickness_expression << "' is " << t
                << " m at the point (" << x << "); it must be positive.";
          AssertThrow(false, ExcParameter("Thickness", where.str()));
        }
      return t;
    }

    double
    Interface::constant_thickness(const std::string &entry) const
    {
      AssertThrow(thickness_function,
                  dealii::ExcMessage(
                    "geometry::Interface::constant_thickness() "
                    "called before parse_common_parameters()."));
      const double t = thickness_function->value(dealii::Point<3>());
      for (const dealii::Point<3> x : {dealii::Point<3>(1, 2, 3),
                                       dealii::Point<3>(-100, 37, 5),
                                       dealii::Point<3>(61, -100, 100),
                                       dealii::Point<3>(-13, 100, -100),
                                       dealii::Point<3>(100, 0.5, -0.25)})
        {
          const double other = thickness_function->value(x);
          AssertThrow(other == t ||
                        (std::isfinite(other) && std::isfinite(t) &&
                         std::abs(other - t) <= 1e-12 * std::abs(t)),
                      ExcParameter(entry,
                                   "needs a constant Thickness (a number of "
                                   "m), not '" +
                                     thickness_expression +
                                     "': give the span and rise of the "
                                     "middle surface for a varying "
                                     "thickness."));
        }
      return unscaled_thickness(dealii::Point<3>());
    }

    void
    Interface::set_thickness_factor(const double f)
    {
      AssertThrow(f > 0 && std::isfinite(f),
                  dealii::ExcMessage("the thickness factor must be positive"));
      factor = f;
    }

    double
    Interface::thickness_factor() const
    {
      return factor;
    }

    double
    Interface::density() const
    {
      return rho;
    }

    void
    Interface::set_patches(std::vector<Patch> new_patches)
    {
      patch_list = std::move(new_patches);
      if (thickness_function)
        for (const auto &patch : patch_list)
          for (unsigned int i = 0; i < 5; ++i)
            for (unsigned int j = 0; j < 5; ++j)
              (void)thickness(patch.point(dealii::Point<2>(i / 4., j / 4.)));
    }
  } // namespace geometry
} // namespace masonry
