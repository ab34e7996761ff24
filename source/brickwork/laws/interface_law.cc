/**
 * @file
 * The interface law family: its shared entries (the penalties and the
 * viscosity) and the defaults of InterfaceLaw.
 */
#include <masonry/brickwork/interface_law.h>
#include <masonry/core/parameters.h>

#include <vector>

namespace masonry
{
  namespace brickwork
  {
    double
    lourenco_rots_stiffness(const double E_u,
                            const double E_m,
                            const double h_m)
    {
      AssertThrow(E_u > E_m && E_m > 0 && h_m > 0,
                  dealii::ExcMessage(
                    "the Lourenco-Rots stiffness needs unit modulus > mortar "
                    "modulus > 0 and a positive joint thickness"));
      return E_u * E_m / (h_m * (E_u - E_m));
    }

    // ---------------------------------------------------------------------
    const char *
    InterfaceLaw::default_plugin()
    {
      return "bilinear";
    }

    std::string
    InterfaceLaw::selection_documentation()
    {
      return "The traction-separation law of the zero-thickness joints "
             "(bed, head and collar) between enlarged bricks. Tractions in "
             "Pa, openings in m; the normal opening is positive when the "
             "bricks separate.";
    }

    void
    InterfaceLaw::declare_common_parameters(dealii::ParameterHandler &prm)
    {
      declare_ranged_entry(
        prm,
        "Normal stiffness",
        "2.5e11",
        {0, 1e16, "Pa/m"},
        "Penalty stiffness k_n of the joint normal to it, Pa/m (> 0). For "
        "enlarged bricks Lourenco and Rots give k_n = E_u E_m / (h_m (E_u - "
        "E_m)) with the unit and mortar moduli E_u, E_m (Pa) and the joint "
        "thickness h_m (m): E_u = 10 GPa, E_m = 2 GPa, h_m = 10 mm give "
        "2.5e11 Pa/m.");
      declare_ranged_entry(prm,
                           "Shear stiffness",
                           "1.0e11",
                           {0, 1e16, "Pa/m"},
                           "Penalty stiffness k_s of the joint in both "
                           "directions of slip, Pa/m (> 0); the same formula "
                           "as k_n with the shear moduli G_u, G_m.");
      declare_ranged_entry(
        prm,
        "Viscosity",
        "0",
        {0, 1e6, "s"},
        "Viscous regularisation of the joint damage, s (>= 0; 0: none): "
        "the damage used is d_v = (d + (mu / dt) d_v,old) / (1 + mu / dt), "
        "with dt the pseudo-time of the step (platen displacement increment "
        "/ `Platen speed'). Keep mu well below the duration of the test to "
        "stay close to the rate-independent law.");
    }

    void
    InterfaceLaw::parse_common_parameters(dealii::ParameterHandler &prm)
    {
      normal_stiffness = prm.get_double("Normal stiffness");
      shear_stiffness  = prm.get_double("Shear stiffness");
      viscosity        = prm.get_double("Viscosity");
      AssertThrow(normal_stiffness > 0,
                  ExcParameter("Normal stiffness", "must be positive"));
      AssertThrow(shear_stiffness > 0,
                  ExcParameter("Shear stiffness", "must be positive"));
    }


    void
    InterfaceLaw::evaluate_extrapolated(const Local3  &jump,
                                        ConstStateView old,
                                        ConstStateView,
                                        const double,
                                        const InterfacePoint &point,
                                        Local3               &t,
                                        Local33              &tangent) const
    {
      std::vector<double> scratch(old.size());
      evaluate(jump, old, point, scratch, t, tangent);
    }

    bool
    InterfaceLaw::is_elastic(const Local3 &,
                             ConstStateView,
                             const InterfacePoint &) const
    {
      return is_linear();
    }

    Local33
    InterfaceLaw::elastic_tangent() const
    {
      Local33 D{};
      D[0][0] = normal_stiffness;
      D[1][1] = D[2][2] = shear_stiffness;
      return D;
    }

  } // namespace brickwork
} // namespace masonry
