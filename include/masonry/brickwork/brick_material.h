/**
 * @file
 * Constitutive laws of the enlarged bricks (`subsection Brick material`,
 * `set Model = ...`). Only `elastic` exists now; the damage–plasticity law
 * of the cyclic study is the next plugin of this interface.
 */
#ifndef masonry_brickwork_brick_material_h
#define masonry_brickwork_brick_material_h

#include <masonry/core/plugins.h>

namespace masonry
{
  namespace brickwork
  {
    /** Base class of brick materials. */
    class BrickMaterial
    {
    public:
      /** Parameters live in `subsection Brick material`. */
      static constexpr const char *registry_section = "Brick material";
      /** The selection entry: `set Model = ...`. */
      static constexpr const char *registry_entry = "Model";
      /** Default selection: "elastic". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();
      /** Entries shared by all brick materials: none. */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      virtual ~BrickMaterial() = default;

      /** Read the shared entries: none. */
      virtual void
      parse_common_parameters(dealii::ParameterHandler &prm);
      /** Read this material's own subsection: nothing by default. */
      virtual void
      parse_parameters(dealii::ParameterHandler &prm);

      /**
       * Whether stress is a fixed linear function of strain: then the
       * assembly computes each cell matrix once and reuses it.
       */
      virtual bool
      is_linear() const = 0;

      /**
       * The initial (elastic) stiffness as Young's modulus (Pa) and
       * Poisson's ratio: the stiffness of a linear material.
       */
      virtual double
      youngs_modulus() const = 0;
      /** Poisson's ratio of the initial stiffness. */
      virtual double
      poissons_ratio() const = 0;
    };
  } // namespace brickwork
} // namespace masonry

/** Register a brick material (one line in its .cc file). */
#define MASONRY_REGISTER_BRICK_MATERIAL(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::BrickMaterial,          \
                          classname,                                  \
                          name,                                       \
                          description)

#endif
