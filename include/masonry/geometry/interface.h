/**
 * @file
 * Geometry models: the middle surface of the vault as exact NURBS patches,
 * its thickness and its density (`subsection Geometry model`).
 *
 * Conventions shared by all models: SI units (m, kg/m^3; angles in
 * degrees where an entry says so), z up, springings at z = 0 where
 * sensible, the span along x and the length along y. Every patch's
 * normal points towards the extrados (see Patch).
 */
#ifndef masonry_geometry_interface_h
#define masonry_geometry_interface_h

#include <masonry/core/plugins.h>
#include <masonry/geometry/patch.h>

#include <deal.II/base/function_parser.h>

#include <memory>
#include <vector>

namespace masonry
{
  namespace geometry
  {
    /**
     * Base class of geometry models. A model builds its patches in
     * parse_parameters() (calling set_patches(), which also checks the
     * thickness on them); patches() returns them.
     */
    class Interface : public plugins::InterfaceBase
    {
    public:
      /** The section: `subsection Geometry model`. */
      static constexpr const char *registry_section = "Geometry model";
      /** The selection entry: `set Model name = ...`. */
      static constexpr const char *registry_entry = "Model name";
      /** Default selection: "barrel vault". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();

      /**
       * Entries shared by all geometry models: `Thickness` (m, a function
       * of x, y, z) and `Density` (kg/m^3).
       */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      /**
       * Read and check `Thickness` (must parse) and `Density` (> 0).
       */
      void
      parse_common_parameters(dealii::ParameterHandler &prm) override;


      /** The patches of the middle surface, built by parse_parameters(). */
      virtual const std::vector<Patch> &
      patches() const;

      /**
       * The thickness (m) at the point @p x of the middle surface. Throws
       * ExcParameter("Thickness", ...) if it is not positive and finite.
       */
      double
      thickness(const dealii::Point<3> &x) const;

      /**
       * The thickness (m) at @p x without the factor of
       * set_thickness_factor(): thickness(x) is exactly
       * thickness_factor() * unscaled_thickness(x), so a model that keeps
       * these values can follow a change of the factor without evaluating
       * the thickness field again (rigid_blocks::BlockModel does). Throws
       * as thickness().
       */
      double
      unscaled_thickness(const dealii::Point<3> &x) const;

      /**
       * Multiply the thickness everywhere by @p f > 0 (used by the minimum
       * thickness analysis; 1 after parsing).
       */
      void
      set_thickness_factor(const double f);

      /** The factor of set_thickness_factor(). */
      double
      thickness_factor() const;

      /** The density (kg/m^3). */
      double
      density() const;

    protected:
      /**
       * The `Thickness' as one number (m), for a model that needs it before
       * it has a surface (the offset between the surface whose span and
       * rise are given and the middle surface): the expression evaluated at
       * points spread over ±100 m, which must all agree. Throws an
       * ExcParameter naming @p entry (the model's entry that needs it) if
       * they do not, and naming `Thickness' if the value is not positive.
       */
      double
      constant_thickness(const std::string &entry) const;

      /**
       * Store the patches and evaluate the thickness on a 5x5 grid of
       * parameter points of every patch (so that a non-positive thickness
       * is reported while parsing, not later).
       */
      void
      set_patches(std::vector<Patch> new_patches);

    private:
      /** The patches. */
      std::vector<Patch> patch_list;
      /** The thickness function t(x,y,z). */
      std::unique_ptr<dealii::FunctionParser<3>> thickness_function;
      /** The expression, for messages. */
      std::string thickness_expression;
      /** Density (kg/m^3). */
      double rho = 0;
      /** Factor on the thickness. */
      double factor = 1;
    };
  } // namespace geometry
} // namespace masonry

/** Register a geometry model (one line in the model's .cc file). */
#define MASONRY_REGISTER_GEOMETRY_MODEL(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::geometry::Interface,               \
                          classname,                                  \
                          name,                                       \
                          description)

#endif
