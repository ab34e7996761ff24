/**
 * @file
 * A sample external plugin: the analysis `block on plane`.
 *
 * A rigid block of width b, height h and depth d stands on a horizontal plane
 * (friction coefficient mu) and is loaded by its weight W = rho g b h d and a
 * horizontal force lambda W (a horizontal acceleration lambda g). It
 * overturns about its toe when lambda W h/2 > W b/2, i.e. at lambda = b/h,
 * and slides when lambda W > mu W, i.e. at lambda = mu; the collapse
 * multiplier is the smaller of the two.
 */
#include <masonry/analysis/interface.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <string>

namespace block_on_plane
{
  /** Collapse multiplier of a rigid block on a plane under a lateral load. */
  class BlockOnPlane : public masonry::analysis::Interface
  {
  public:
    /** The entries of `subsection Block on plane`. */
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Width",
                        "0.5",
                        dealii::Patterns::Double(),
                        "Width b of the block in the direction of the "
                        "horizontal load (m); positive.");
      prm.declare_entry("Height",
                        "1",
                        dealii::Patterns::Double(),
                        "Height h of the block (m); positive.");
      prm.declare_entry("Depth",
                        "1",
                        dealii::Patterns::Double(),
                        "Depth of the block, normal to the load (m); "
                        "positive.");
      prm.declare_entry("Density",
                        "1800",
                        dealii::Patterns::Double(),
                        "Density of the block (kg/m^3); positive.");
      prm.declare_entry("Friction coefficient",
                        "0.6",
                        dealii::Patterns::Double(0),
                        "Coefficient of friction mu between block and plane "
                        "(dimensionless); non-negative.");
    }

    void
    parse_parameters(dealii::ParameterHandler &prm) override
    {
      width    = positive(prm, "Width");
      height   = positive(prm, "Height");
      depth    = positive(prm, "Depth");
      density  = positive(prm, "Density");
      friction = prm.get_double("Friction coefficient");
    }

    void
    run(masonry::RunContext &context) override
    {
      const double      g           = 9.81;
      const double      weight      = density * g * width * height * depth;
      const double      overturning = width / height;
      const double      sliding     = friction;
      const double      multiplier  = std::min(overturning, sliding);
      const std::string mode =
        overturning <= sliding ? "overturning" : "sliding";

      context.pcout << "Block on plane: collapse multiplier " << multiplier
                    << " (" << mode << "; overturning " << overturning
                    << ", sliding " << sliding << "), weight " << weight
                    << " N\n";
      context.summary["load_multiplier"]        = multiplier;
      context.summary["mode"]                   = mode;
      context.summary["overturning_multiplier"] = overturning;
      context.summary["sliding_multiplier"]     = sliding;
      context.summary["weight"]                 = weight;
    }

  private:
    /** The value of @p entry, which must be positive. */
    static double
    positive(dealii::ParameterHandler &prm, const std::string &entry)
    {
      const double value = prm.get_double(entry);
      AssertThrow(value > 0,
                  masonry::ExcParameter(entry,
                                        "must be positive, got " +
                                          prm.get(entry)));
      return value;
    }

    double width    = 0.5;
    double height   = 1;
    double depth    = 1;
    double density  = 1800;
    double friction = 0.6;
  };
} // namespace block_on_plane

MASONRY_REGISTER_ANALYSIS(
  block_on_plane::BlockOnPlane,
  "block on plane",
  "A rigid block of width b and height h on a horizontal plane with friction "
  "coefficient mu, under a horizontal acceleration lambda g: collapse "
  "multiplier min(b/h, mu) (overturning or sliding). A sample external "
  "plugin (contrib/examples/plugin).")
